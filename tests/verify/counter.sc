// A counter that counts 0..9 by one per tick from tick 1 (tick 0 only enters Run), then stays.
// By hand: states = the pre-start state + c = 0..9 after tick 0 = 11; one input vector per
// state (no inputs), so 11 transitions; the deepest layer is c = 9 after 10 ticks (depth 10).
// `below5` is violated when c = 5, at tick 5: the counterexample has 6 ticks (0..5).
chart Counter {
  output c: int[0..9] = 0;
  initial Run;
  state Run {
    on [c < 9] / { c += 1; };
  }
}

system Counting {
  instance k: Counter;
  invariant below5: k.c < 5;
  invariant never_above9: k.c <= 9;
}

// reach9 holds first at tick 9 (witness of 10 ticks); c > 9 never holds in range.
system Reaching {
  instance k: Counter;
  reachable reach9: k.c == 9;
  reachable reach_neg: k.c < 0;
}

// The observer enters `error` in the tick where c first exceeds 6: tick 7 (8 ticks).
system Observed {
  instance k: Counter;
  observer over6 {
    initial Watch;
    state Watch { on [k.c > 6] -> error; }
    state error;
  }
}
