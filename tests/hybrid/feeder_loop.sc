// A pneumatic feeder (docs/hybrid.md) in closed loop with a controller that pushes on
// `start`, retracts at the end sensor and stops at the home sensor.
//
// Hand derivation (tick 1.25 s, grid of 20 cells of 5 %):
// - pushing at 2 %/s covers 2.5 % per tick: 2 ticks per cell; retracting at 4 %/s: 5 % per
//   tick, 1 tick per cell.
// - The earliest push: `start` in tick 1 (tick 0 only initialises); `ctrl` runs first and
//   raises `push`, which `feeder` reads in the same tick: Push is entered in tick 1.
// - `at_end` (pos in [95 .. 100]) first holds when pos reaches 95 = 19 cells: tick
//   1 + 19 * 2 = 39 (48.75 s). So `never_end` is violated, first in tick 39.
// - pos == 100 first in tick 1 + 20 * 2 = 41: `full` is reachable in tick 41.
// - at_home ([0 .. 5]) and at_end ([95 .. 100]) are disjoint: `not_both` holds.
tick 1250 ms;

plant chart Feeder {
  input push: bool = false;
  input retract: bool = false;
  output at_home: bool;
  output at_end: bool;
  continuous pos: [0 .. 100] = 0;
  grid pos 20;
  sensor at_home = pos in [0 .. 5];
  sensor at_end = pos in [95 .. 100];

  initial Home;
  state Home { on [push] -> Push; }
  state Push {
    der(pos) = 2;
    on [pos >= 100] -> End;
  }
  state End { on [retract] -> Back; }
  state Back {
    der(pos) = -4;
    on [pos <= 0] -> Home;
  }
}

chart Ctrl {
  input start: bool = false;
  input at_end: bool = false;
  input at_home: bool = true;
  output push: bool = false;
  output retract: bool = false;

  initial Idle;
  state Idle { on [start] / { push = true; } -> Pushing; }
  state Pushing { on [at_end] / { push = false; retract = true; } -> Retracting; }
  state Retracting { on [at_home && !push] / { retract = false; } -> Idle; }
}

system Loop {
  instance ctrl: Ctrl;
  instance feeder: Feeder;
  connect ctrl.push -> feeder.push;
  connect ctrl.retract -> feeder.retract;
  connect feeder.at_end -> ctrl.at_end;
  connect feeder.at_home -> ctrl.at_home;
  order ctrl, feeder;

  invariant not_both: !(feeder.at_home && feeder.at_end);
  invariant never_end: !feeder.at_end;
  reachable full: feeder.pos == 100;
}
