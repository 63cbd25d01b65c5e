// Time in the user's units (issue 18): ticks of 1250 ms, and a timer of 117500 ms = 94 ticks.
// The feeder starts pushing in tick 1 (the event `start`; tick 0 initialises), so it reaches
// its end position in tick 1 + 94 = 95 (entered in tick t, `after(n)` leaves in tick t + n),
// at 95 × 1.25 s = 118.75 s. The invariant `never_at_end` is violated exactly then.
tick 1250 ms;

chart Feeder {
  input event start;
  output pushed: bool = false;
  initial Home;
  state Home { on start -> Pushing; }
  state Pushing { on after(117500 ms) / { pushed = true; } -> End; }
  state End;
}

system Station {
  instance feeder: Feeder;
  invariant never_at_end: !in(feeder.End);
}
