// Two instances of one parameterised chart (docs/components.md). `counters_flat.sc` is the
// same system with the arguments substituted by hand; both must give the same results.
chart Counter(max: int[1..100], start: int = 0) {
  input event step;
  output n: int[0..max] = start;
  initial Run;
  state Run { on step [n < max] / { n = n + 1; }; }
  invariant in_range: n <= max;
}

system Counters {
  instance a: Counter(2);
  instance b: Counter(max = 3, start = 1);
  reachable a_full: a.n == 2;
  invariant b_low: b.n >= 1;
  invariant sum: a.n + b.n < 5;
}
