// A motion cut between two grid points by a timer, then resumed: the discretized position
// snaps back to the last grid point, so the model reaches a zone later than the continuous
// motion (docs/hybrid.md, "what the abstraction preserves").
//
// Hand derivation (tick 1 s, cells of 25, 5 units/s: 5 ticks per cell): `go` in tick 1
// enters Forward in tick 1; the timer leaves it 7 s later, in tick 8, after 7 s of motion:
// the continuous x is 35, the model's is 25 (reached in tick 6). The next choice is in tick 9:
// with `go` the motion resumes at 9 s. Continuous: 50 (zone `far` entered) after 15/5 = 3 s,
// at 12 s (tick 12); the model needs a whole cell from 25: tick 9 + 5 = 14. 100 is reached
// at 9 + 65/5 = 22 s continuously, in tick 9 + 15 = 24 by the model.
tick 1 s;

plant chart Linear {
  input go: bool = false;
  output far: bool;
  continuous x: [0 .. 100] = 0;
  grid x 4;
  sensor far = x in [50 .. 100];

  initial Home;
  state Home { on [go] -> Forward; }
  state Forward {
    der(x) = 5;
    on after(7 s) -> Rest;
    on [x >= 100] -> End;
  }
  state Rest { on [go] -> Forward; }
  state End;
}

system Line {
  instance lin: Linear;
}
