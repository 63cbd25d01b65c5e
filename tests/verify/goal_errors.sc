// Properties and assumes whose evaluation can fail at run time: every consumer reads them with
// "an evaluation error is false" (the IR's `Goal`), the Promela export included.
// v.d is a free input in 0..3; 12 / v.d fails exactly when d = 0.
chart Div {
  input d: int[0..3];
  output q: int[0..12] = 0;
  initial S;
  state S { during { q = 12 / max(d, 1); } }
}

system Goals {
  instance v: Div;
  // d = 0 in some tick: the division fails, the invariant reads false: violated (1 tick).
  invariant div_fails: 12 / v.d >= 4;
  // The `||` never divides by 0; 12 / d is 12, 6, 4 for d = 1, 2, 3: proved.
  invariant div_guarded: v.d == 0 || 12 / v.d >= 4;
  // 12 / 2 == 6: reachable; a failing target (d = 0) is simply false.
  reachable six: 12 / v.d == 6;
  // 12 / d == 5 for no d in 1..3, and d = 0 fails: unreachable.
  reachable five: 12 / v.d == 5;
}

system Assumed {
  instance v: Div;
  // The assume fails at d = 0, so that input vector is rejected: d in 1..3 only, and
  // div_fails is proved.
  assume 12 / v.d >= 1;
  invariant div_fails: 12 / v.d >= 4;
}
