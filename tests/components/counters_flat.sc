// `counters.sc` with its arguments substituted by hand: Counter(2) and Counter(3, 1).
chart Counter2 {
  input event step;
  output n: int[0..2] = 0;
  initial Run;
  state Run { on step [n < 2] / { n = n + 1; }; }
  invariant in_range: n <= 2;
}

chart Counter3 {
  input event step;
  output n: int[0..3] = 1;
  initial Run;
  state Run { on step [n < 3] / { n = n + 1; }; }
  invariant in_range: n <= 3;
}

system Counters {
  instance a: Counter2;
  instance b: Counter3;
  reachable a_full: a.n == 2;
  invariant b_low: b.n >= 1;
  invariant sum: a.n + b.n < 5;
}
