// Times in the configuration matrix (issue 18): ticks of 1250 ms; a light workpiece is pushed
// in 38 ticks, a heavy one in 94. `start` in tick 1 (tick 0 initialises); the stroke ends in
// tick 1 + 38 = 39 (48.75 s) or 1 + 94 = 95 (118.75 s), where `never_at_end` is violated.
tick 1250 ms;

interface Pusher {
  input event start;
  output pushed: bool;
}

chart Feeder(stroke: int[1..200] = 38) implements Pusher {
  input event start;
  output pushed: bool = false;
  initial Home;
  state Home { on start -> Pushing; }
  state Pushing { on after(stroke) / { pushed = true; } -> End; }
  state End;
}

system Station {
  instance f: Pusher;
  configuration light {
    f = Feeder(stroke = 38);
  }
  configuration heavy {
    f = Feeder(stroke = 94);
  }
  invariant never_at_end: !f.pushed;
}
