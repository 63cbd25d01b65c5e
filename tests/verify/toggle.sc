// A two-state machine toggled by one input event.
// By hand (system Free): states = pre-start, Off, On = 3; every state has 2 input vectors
// (t absent/present), so 6 transitions; tick 0 always enters Off (layer 1), On first after
// tick 1 (layer 2): depth 2. `stays_off` is violated at tick 1: 2 ticks (t at tick 1).
// System Frozen assumes t is never present: states = pre-start, Off = 2, transitions 2
// (one allowed vector per state), stays_off proved, On and both transitions are dead.
chart Toggle {
  input event t;
  initial Off;
  state Off { on t -> On; }
  state On { on t -> Off; }
}

system Free {
  instance sw: Toggle;
  invariant stays_off: in(sw.Off);
}

system Frozen {
  instance sw: Toggle;
  assume !sw.t;
  invariant stays_off: in(sw.Off);
}
