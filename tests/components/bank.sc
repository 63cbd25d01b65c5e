// A parameterised component and an array of components (docs/components.md).
// `bank_flat.sc` is the same system flattened by hand (paths' `.`, `[`, `]` written `_`);
// both give the same verdicts, state counts and traces (crates/cli/tests/composites.rs).
//
// By hand: in a `Pair(m)` both counters step together on the one `step` event, `lo` stops
// at 1 and `hi` at m, so a pair reaches the m + 1 states (0,0), (1,1), (1,2) … (1,m).
// `p` is Pair(2) (3 states), `cells[0]` and `cells[1]` are Pair(3) (4 states each), each with
// its own free `step`: 3 * 4 * 4 = 48 reachable states.

chart Counter(max: int[1..3]) {
  input event step;
  output n: int[0..3] = 0;
  initial Run;
  state Run { on step [n < max] / { n = n + 1; }; }
}

component Pair(m: int[1..3]) {
  input event step;
  output last: int[0..3];
  instance lo: Counter(1);
  instance hi: Counter(m);
  connect step -> lo.step;
  connect step -> hi.step;
  connect hi.n -> last;
  invariant capped: hi.n <= m;
}

system Bank {
  instance p: Pair(2);
  instance cells[2]: Pair(3);
  reachable p_full: p.hi.n == 2;
  reachable c1_full: cells[1].last == 3;
  reachable p_three: p.hi.n == 3;
  invariant lo_follows: cells[0].lo.n == 0 || cells[0].hi.n >= 1;
}
