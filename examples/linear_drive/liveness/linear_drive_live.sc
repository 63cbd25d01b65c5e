// liveness/linear_drive_live.sc — liveness of the linear drive (issue 16). Everything above the
// marker line below is linear_drive.sc's text, verbatim (crates/cli/tests/temporal.rs
// checks that it stays so); the system at the end states the temporal properties.
// === begin copy of linear_drive.sc ===
// linear_drive.sc — the linear drive controller of Donath, Haufe, Blochwitz, Neidhold, "A new
// Approach for Modeling and Verification of Discrete Control Components within a Modelica
// Environment" (../../../shared/seeds/uml-statecharts-in-modelica.txt), §2.1–2.4 and Fig. 5.
//
// The specification (§2.1): start after Run is given and drive to the left; run 10 times
// between the left and right end positions; pause 3 seconds, afterwards continue; stop
// immediately after Halt; restart with the action suspended by Halt when Run is given again.
// The normative detail is the generated Modelica code of §2.4: its entry-activities and
// transition conditions are reproduced here one for one (each is quoted beside its line).
//
// Units and scaling. The paper's position x is in metres with LimitLeft = -0.4 and
// LimitRight = 0.4. Here x is an integer in millimetres: x: int[-500..500], limits -400 / +400.
// U is in volts (-10, 0, +10). The drive model (not given numerically in the paper) moves
// 1 mm per tick per volt: at U = 10 V and a 100 ms tick that is 10 mm per tick = 0.1 m/s, so an
// end-to-end run (-410 -> +410 mm) takes 82 ticks = 8.2 s.
//
// Tick semantics that matter here (docs: synchronous ticks, outer transitions first): the
// controller runs before the drive in each tick, so it reads the position of the previous tick
// and the drive applies this tick's U at once.

tick 100 ms;

const N_MAX: int = 10;             // §2.4 initialisation: N_Max := 10
const LIMIT_LEFT: int = -400;      // LimitLeft := -0.4 (m), in mm
const LIMIT_RIGHT: int = 400;      // LimitRight := 0.4 (m), in mm
const X_MIN: int = -500;           // mechanical travel of the drive model (mm)
const X_MAX: int = 500;

enum DirT { Left, Right }          // §2.4: dir := DirT.Left initially

// ---------------------------------------------------------------------------------------
// The control program of Fig. 3: Main = { Stop, Go }, Go = { GoLeft, GoRight, Pause }.
chart Controller {
  input event Run;                 // operator command (§2.1, a toggled signal in Modelica)
  input event Halt;                // operator command, highest priority (§2.3.5)
  input x: int[-500..500];         // drive position (mm)
  output U: int[-10..10] = 0;      // motor voltage: -10 left, +10 right, 0 stop (§2.1)
  // count is at most 12: GoRight is entered with count <= 11 + 1 and then goes to Pause.
  local count: int[0..12] = 0;     // count := 0
  local dir: DirT = Left;          // dir := DirT.Left

  initial Stop;                    // mainState := MainStateT.Stop

  state Stop {
    // "when (mainState==MainStateT.Stop) then U:=0; count:=0;"
    entry { U = 0; count = 0; }
    // "if (change(Run)) then if (dir==DirT.Left) then ... entryGoState:=GoStateT.GoLeft;
    //  elseif (dir==DirT.Right) then ... entryGoState:=GoStateT.GoRight;"
    // This is how the paper resumes the action suspended by Halt: GoLeft and GoRight record
    // their direction in `dir` on entry, so Run re-enters the one that was active (or, after
    // a Halt in Pause, GoRight — the direction Pause was entered from). The §2.3.4 guards
    // [dir == DirT.Left] / [dir == DirT.Right] pick the target.
    on Run -> choice {
      [dir == Left] -> Go.GoLeft;
      else -> Go.GoRight;          // dir == Right: DirT has no third value
    };
  }

  state Go {
    // §2.2.3 lists shallow history among the supported pseudo states and §2.1 asks to
    // "restart with the action which was suspended". Go keeps its shallow-history marker, but
    // the generated code never consults it: both transitions into Go target a leaf chosen by
    // `dir` (above), and an explicit leaf target does not go through history. The two agree
    // except after a Halt in Pause, where history would resume Pause and the paper's code
    // resumes GoRight; we follow the code.
    history shallow;
    initial GoLeft;

    // Halt from every substate: "if (change(Halt)) then goState:=GoStateT.InActive;
    // ontoMainState:=MainStateT.Stop;" is the first test of each substate, i.e. a group
    // transition with the highest priority (§2.3.5). Outer transitions are tried before inner
    // ones, so it preempts x/count/timeout. Leaving Pause this way also cancels its timer
    // ("t_PauseFinished:=time").
    on Halt -> Stop priority 1;

    state GoLeft {
      // "when (goState==GoStateT.GoLeft) then U:=-10; count:=count+1; dir:=DirT.Left;"
      entry { U = -10; count = count + 1; dir = Left; }
      // "elseif (x<LimitLeft) then goState:=GoStateT.GoRight;"
      on [x < LIMIT_LEFT] -> GoRight;
    }

    state GoRight {
      // "when (goState==GoStateT.GoRight) then U:=10; count:=count+1; dir:=DirT.Right;"
      entry { U = 10; count = count + 1; dir = Right; }
      // "elseif (count>N_Max) then goState:=GoStateT.Pause;
      //  elseif (x>LimitRight) then goState:=GoStateT.GoLeft;" — in this order.
      on [count > N_MAX] -> Pause;
      on [x > LIMIT_RIGHT] -> GoLeft;
    }

    state Pause {
      // "when (goState==GoStateT.Pause) then U:=0; count:=0; t_PauseFinished:=time+t_Pause;"
      entry { U = 0; count = 0; }
      // "elseif (change(timeout)) then goState:=GoStateT.GoRight;" with t_Pause := 3 (s)
      on after(3 s) -> GoRight;
    }
  }
}

// ---------------------------------------------------------------------------------------
// The drive (Fig. 2, simplified): a position integrator with end stops, x' = U (mm/tick/V).
plant chart Drive {
  input U: int[-10..10];
  output x: int[-500..500] = 0;    // starts in the middle
  output v: int[-10..10] = 0;      // displacement applied in this tick (0 when stopped)
  initial moving;
  state moving {
    during {
      v = max(X_MIN, min(X_MAX, x + U)) - x;
      x = x + v;
    }
  }
}

// === end copy of linear_drive.sc ===
system LinearDriveLive {
  instance ctrl: Controller;
  instance drive: Drive;
  connect ctrl.U -> drive.U;
  connect drive.x -> ctrl.x;
  order ctrl, drive;
  assume !(ctrl.Run && ctrl.Halt);

  // §2.1: after Run (which enters Go; Run in tick 0 is not seen, R1) the drive eventually
  // reaches each end position — unless Halt is given
  // again (the operator may stop it at any time), so the property allows for a later Halt.
  ltl run_reaches_left: G((ctrl.Run && in(ctrl.Go)) => F(drive.x < LIMIT_LEFT || ctrl.Halt));
  ltl run_reaches_right: G((ctrl.Run && in(ctrl.Go)) => F(drive.x > LIMIT_RIGHT || ctrl.Halt));
  // Without the Halt escape the property fails: Halt right after Run stops the drive.
  ltl run_reaches_left_always: G((ctrl.Run && in(ctrl.Go)) => F drive.x < LIMIT_LEFT);
  // The controller can always be brought back to Stop, and from there restarted.
  ctl can_stop: AG EF in(ctrl.Stop);
  nonblocking can_run: in(ctrl.Go);
}
