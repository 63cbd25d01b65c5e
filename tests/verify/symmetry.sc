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
