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

// ---------------------------------------------------------------------------------------
system LinearDrive {
  instance ctrl: Controller;
  instance drive: Drive;
  connect ctrl.U -> drive.U;
  connect drive.x -> ctrl.x;
  order ctrl, drive;

  // The operator never gives Run and Halt in the same tick. Without this, the checker finds
  // that Run wins in Stop (Stop has no Halt transition, and at most one transition fires per
  // tick): the drive starts although Halt was given — as in the paper's Modelica code, where
  // Stop tests only change(Run). The assumption keeps halt_stops_next_tick about Halt alone.
  assume !(ctrl.Run && ctrl.Halt);

  // §2.1 "Stop immediately after command Halt was given", §2.3.5 "Halt shall have the highest
  // priority": in the Halt tick or the next one, U is 0 and the drive no longer moves.
  // (With the controller ordered first it happens in the Halt tick itself.)
  respond halt_stops_next_tick: ctrl.Halt => ctrl.U == 0 && drive.v == 0 within 1;

  // §2.1 "Pause 3 seconds": Pause never lasts longer than 3 s = 30 ticks ...
  respond pause_at_most_3s: in(ctrl.Go.Pause) => !in(ctrl.Go.Pause) within 30;

  // ... and when it ends by its timer (not by Halt) it has lasted exactly 30 ticks: Pause is
  // active in 30 consecutive ticks t .. t+29 and GoRight is entered at t+30.
  observer pause_lasts_3s {
    local n: int[0..30] = 0;       // ticks seen in Pause so far
    initial idle;
    state idle {
      on [in(ctrl.Go.Pause)] / { n = 1; } -> inPause;
    }
    state inPause {
      on [!in(ctrl.Go.Pause) && !in(ctrl.Stop) && n != 30] -> error;   // left early (not Halt)
      on [!in(ctrl.Go.Pause)] -> idle;                                 // by timer or by Halt
      on [n >= 30] -> error;                                           // still paused: too long
      during { n = n + 1; }
    }
    state error;
  }

  // Fig. 5, the assertion chart: "If the DC motor supply voltage U alters to U > 0, then drive
  // position x will exceed its limit within T seconds, otherwise a fault will be reported."
  // T is not given in the paper; from anywhere in [-500, 500] the drive needs at most 91 ticks
  // at +10 mm/tick to pass +400, so T = 10 s. Two readings of "otherwise":
  //  - literally, any U > 0 episode must reach the limit. That fails in this model in two ways
  //    the checker can show: Halt during GoRight (U drops to 0), and GoRight entered with
  //    count = 12, which drives right for one tick before `count > N_Max` moves to Pause (in
  //    the paper's continuous-time Modelica both happen at one instant, so U > 0 for no time);
  //  - as written here: the episode is abandoned when U leaves > 0 before the limit (Halt or
  //    Pause switched the motor off); only a motor that keeps pushing right for T without
  //    reaching the limit is a fault. This is the version we expect to hold.
  observer fig5_limit_reached {
    initial idle;
    state idle {
      on [ctrl.U > 0] -> watching;                   // U alters to U > 0
    }
    state watching {
      on [drive.x > LIMIT_RIGHT] -> reached;         // x exceeds its limit: assertion met
      on [ctrl.U <= 0] -> idle;                      // motor switched off first: abandoned
      on after(10 s) -> error;                       // T elapsed: report the fault
    }
    state reached {
      on [ctrl.U <= 0] -> idle;                      // wait for the next U > 0 episode
    }
    state error;
  }
}
