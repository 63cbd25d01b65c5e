// Symmetry reduction (docs/verification.md): three identical counters modulo 3, each moved by
// its own free input event; nothing outside the array tells them apart.
// By hand: the state before tick 0, then (from tick 0 on) every vector of counter values:
// 1 + 3^3 = 28 states without symmetry, 1 + C(3+3-1, 3) = 11 orbits with it.
chart Counter {
  input event inc;
  output c: int[0..2] = 0;
  initial S;
  state S { on inc / { c = (c + 1) % 3; }; }
  // Violated: tick 0 starts at 0, two `inc`s reach 2 (3 ticks), for every element.
  invariant below: c != 2;
}

system Counters {
  instance a[3]: Counter;
}

// The same counters with a property that names one element: no symmetry (W0317).
system Named {
  instance a[3]: Counter;
  invariant first: a[0].c != 1;
}

// Workers started together by a broadcast event, each stopped by its own free `kick` or after
// 3 ticks: timers, entry/exit actions and a bounded `respond` per element (its monitor moves
// with its element). Symmetric; checked against the search without symmetry.
chart Env {
  input event start;
  output event go;
  output n: int[0..3] = 0;
  initial S;
  state S { on start / { raise go; n = (n + 1) % 4; }; }
}

chart Worker {
  input event go;
  input event kick;
  output busy: bool = false;
  local t: int[0..5] = 0;
  initial Idle;
  state Idle { on go -> Busy; }
  state Busy {
    entry { busy = true; t = 0; }
    exit { busy = false; }
    during { t = min(t + 1, 5); }
    on kick -> Idle;
    on after(3) -> Idle;
  }
  respond done: busy => !busy within 2;
  invariant short: t < 3;
  reachable long: t == 3;
}

system Workers {
  instance env: Env;
  instance w[3]: Worker;
  connect env.go -> w[*].go;
  invariant env_ok: env.n < 3;
}

// A family that holds: `x` and `y` step together modulo 4, so `x == y` is inductive (proved
// by IC3 and by k-induction at k = 1; BMC says `bounded`). `full` (x == 3) needs three `inc`s
// after tick 0: reachable at depth 4, for every element.
chart Pair {
  input event inc;
  output x: int[0..3] = 0;
  output y: int[0..3] = 0;
  initial S;
  state S { on inc / { x = (x + 1) % 4; y = (y + 1) % 4; }; }
  invariant same: x == y;
  reachable full: x == 3;
}

system Pairs {
  instance p[4]: Pair;
}

// The counters interleaved: one element steps per tick, chosen by the scheduler input
// `sched.unit`, which names elements by index. The detection accepts the array, but
// exchanging two elements does not commute with the step (the scheduler's choice stays), so
// the engines' test of the step turns the reduction off (`symmetry_note`).
system Interleaved interleaved {
  instance a[3]: Counter;
}
