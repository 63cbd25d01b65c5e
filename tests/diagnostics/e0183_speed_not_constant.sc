// First-order dynamics such as der(x) = k * (target - x) have no exact clock readings: only
// constant speeds (and profiles of them) are accepted, in each of its spellings.
tick 1 s;

chart Tank {
  input fill: bool = false;
  local level: int[0..100] = 0;
  continuous x: [0 .. 100] = 0;
  grid x 4;
  initial Idle;
  state Idle { on [fill] -> Filling; }
  state Filling { der(x) = 0.5 * (100 - x); }
  state Draining { der(x) = (0 - x) / 2; }
  state Coupled { der(x) = level / 10; }
}
