// Minimised counterexamples (docs/verification.md, "Minimised counterexamples").
//
// Only `go` matters: tick 0 initialises (n stays 0), each later tick with `go` adds 1, so
// `n < 3` is first violated after tick 3 when `go` holds in ticks 1, 2 and 3 — a shortest
// counterexample has 4 ticks. `noise` and `ping` change nothing that the property reads.
// Minimised, the scenario is `go = true` at tick 1 (held through tick 3) and nothing else:
// `go` at tick 0 does not matter, `noise` and `ping` never do.
chart Counter {
  input go: bool = false;
  input noise: bool = true;
  input event ping;
  output n: int[0..3] = 0;
  output seen: int[0..1] = 0;
  initial S;
  state S {
    during {
      if go { n += 1; }
      seen = if noise then 1 else 0;
    }
    on ping -> S;
  }
}

system Minimise {
  instance c: Counter;
  invariant below_three: c.n < 3;
  reachable two: c.n == 2;
}
