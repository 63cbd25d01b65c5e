// A state reachable only through a rare input combination, for `sim --random --guided`.
//
// `a` and `b` are each true with probability 0.01 per tick, so both in one tick with
// probability 1/10,000. Tick 0 only initialises (enters Idle); Armed needs `a && b` in a tick
// spent in Idle, Open needs it again in Armed. Guided, every tick tries all four vectors
// (a, b): tick 1 enters Armed, tick 2 enters Open — all three states by tick 2.
chart Lock {
  input a: bool = false;
  input b: bool = false;
  initial Idle;
  state Idle { on [a && b] -> Armed; }
  state Armed { on [a && b] -> Open; }
  state Open;
}

system Rare {
  instance l: Lock;
  rate l.a = 0.01;
  rate l.b = 0.01;
}
