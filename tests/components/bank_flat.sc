// `bank.sc` flattened by hand: each component instance replaced by its chart instances, the
// `step` port fanned out (the first inner input stays free, the other reads it), properties
// of the component copied per instance and named by its path.

chart Counter(max: int[1..3]) {
  input event step;
  output n: int[0..3] = 0;
  initial Run;
  state Run { on step [n < max] / { n = n + 1; }; }
}

system Bank {
  instance p_lo: Counter(1);
  instance p_hi: Counter(2);
  instance cells_0__lo: Counter(1);
  instance cells_0__hi: Counter(3);
  instance cells_1__lo: Counter(1);
  instance cells_1__hi: Counter(3);
  connect p_lo.step -> p_hi.step;
  connect cells_0__lo.step -> cells_0__hi.step;
  connect cells_1__lo.step -> cells_1__hi.step;
  order p_lo, p_hi, cells_0__lo, cells_0__hi, cells_1__lo, cells_1__hi;
  invariant p_capped: p_hi.n <= 2;
  invariant cells_0__capped: cells_0__hi.n <= 3;
  invariant cells_1__capped: cells_1__hi.n <= 3;
  reachable p_full: p_hi.n == 2;
  reachable c1_full: cells_1__hi.n == 3;
  reachable p_three: p_hi.n == 3;
  invariant lo_follows: cells_0__lo.n == 0 || cells_0__hi.n >= 1;
}
