// Random simulation under state-dependent assumes that end in a deadlock (no input allowed).
//
// Tick 0 only initialises (level stays 0); each later tick adds 1 when `fill` is true.
chart Tank {
  input fill: bool = false;
  output level: int[0..3] = 0;
  initial Run;
  state Run { during { if fill { level += 1; } } }
}

// One mixed assume (reads the state and the input): fill is forced while level < 2, and the
// second disjunct can never hold (level <= 3). Ticks 0, 1, 2 draw fill = true, so level is 0,
// 1, 2 after them; before tick 3 (level 2) no value of fill is allowed: deadlock at tick 3.
system Forced {
  instance t: Tank;
  assume (t.fill && t.level < 2) || (!t.fill && t.level > 5);
}

// An input-only assume (fill always) and a state-only one: level 0, 1, 2 after ticks 0-2;
// before tick 3 the state violates `assume` #2 whatever the input: deadlock at tick 3.
system StateOnly {
  instance t: Tank;
  assume t.fill;
  assume t.level != 2;
}

// Never blocked: level < 3 or not filling. Level reaches 3 and then fill must be false.
system Bounded {
  instance t: Tank;
  assume t.level < 3 || !t.fill;
}
