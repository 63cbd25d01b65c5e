// A realistic, clean model: a washing machine with hierarchy, history, parallel regions,
// choices, a junction, timers, local events, an observer and a system. No lint may fire.
tick 100 ms;

enum Program { Cotton, Synthetic, Wool }
const MAX_TEMP: int = 90;

chart Washer {
  input event start;
  input event pause;
  input event doorOpened;
  input program: Program = Cotton;
  input waterLevel: int[0..100] = 0;
  output heater: bool = false;
  output motor: int[-1..1] = 0;
  output event finished;
  local temp: int[0..90] = 0;
  local cycles: int[0..5] = 0;
  local event rinseDone;

  initial Idle;

  state Idle {
    entry { heater = false; motor = 0; }
    on start -> choice {
      [program == Wool] / { temp = 30; } -> Running;
      [program == Synthetic] / { temp = 40; } -> Running;
      [program == Cotton] / { temp = MAX_TEMP; } -> Running;   // exhaustive: no `else` needed
    };
  }

  state Running {
    history deep;
    initial Fill;
    on doorOpened -> Idle priority 1;
    on pause -> Paused priority 2;

    state Fill {
      on [waterLevel >= 80] -> Wash;
      on after(60 s) -> Idle;               // no water: give up
    }
    state Wash {
      region heating {
        initial Heat;
        state Heat {
          entry { heater = true; }
          exit { heater = false; }
          on after(10) -> Hold;
        }
        state Hold {
          on after(20) -> Heat;
        }
      }
      region drum {
        initial Left;
        state Left {
          entry { motor = -1; }
          on after(5) -> Right;
        }
        state Right {
          entry { motor = 1; }
          on after(5) / { cycles = min(cycles + 1, 5); } -> next;
        }
        junction next {
          [cycles < 5] -> Left;
          else -> Done;
        }
        state Done {
          entry { motor = 0; raise rinseDone; }
        }
      }
      on rinseDone [temp <= 40 || in(Running.Wash.heating.Hold)] -> Spin;
      on rinseDone -> Spin;
    }
    state Spin {
      entry { motor = 1; }
      exit { motor = 0; }
      on after(30) / { raise finished; cycles = 0; } -> Idle;
    }
  }

  state Paused {
    entry { motor = 0; heater = false; }
    on start -> Running;                   // deep history resumes where we paused
    on after(10 min) -> Idle;
  }
}

plant chart Tap {
  input open: bool = false;
  output level: int[0..100] = 0;
  initial Flowing;
  state Flowing {
    during { level = if open then min(level + 5, 100) else level; }
  }
}

system Laundry {
  instance w: Washer;
  instance tap: Tap;
  connect tap.level -> w.waterLevel;
  connect w.heater -> tap.open;
  invariant motor_stops_when_idle: !in(w.Idle) || w.motor == 0;

  observer HeaterOnlyWhenWashing {
    initial watching;
    state watching {
      on [w.heater && !in(w.Running.Wash)] -> error;
    }
    state error;
  }
}
