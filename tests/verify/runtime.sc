// Run-time errors are violations of the built-in properties.
// Divide: q = 12 / d from tick 1 on (tick 0 only enters S): d = 0 at tick 1 divides by zero,
// 2 ticks. SafeDivide assumes d != 0: no_division_by_zero proved.
// Sum: r = r + d with r: int[0..5]; r <= 3 after tick 1, so the first overflow is at tick 2
// (3 + 3 = 6): 3 ticks.
chart Div {
  input d: int[0..3];
  output q: int[0..12] = 0;
  initial S;
  state S { during { q = 12 / d; } }
}

chart Sum {
  input d: int[0..3];
  output r: int[0..5] = 0;
  initial S;
  state S { during { r = r + d; } }
}

system Divide {
  instance v: Div;
}

system SafeDivide {
  instance v: Div;
  assume v.d != 0;
}

system Add {
  instance s: Sum;
}
