// Rates declared in the model (`rate instance.input = P;`) and overridden by `--rate`.
//
// Tick 0 only initialises (level stays 0); each later tick adds 1 when `fill` is true and
// the assume allows it (level < 3).
chart Tank {
  input fill: bool = false;
  output level: int[0..3] = 0;
  initial Run;
  state Run { during { if fill { level += 1; } } }
}

// `fill` at rate 1: drawn whenever the assume allows it, so level is 0, 1, 2, 3 after ticks
// 0-3 and stays 3 (from level 3 only `fill = false` is allowed, drawn as the only vector).
system Always {
  instance t: Tank;
  assume t.level < 3 || !t.fill;
  rate t.fill = 1;
}

// `fill` at rate 0: never drawn, level stays 0.
system Never {
  instance t: Tank;
  rate t.fill = 0.0;
}
