// Symmetry reduction in every configuration of a matrix (`verify --all-configs --symmetry`):
// three identical counters modulo m, each moved by its own free input event, m chosen per
// configuration for the whole array. Each configuration's symmetry is detected in its own
// program.
// By hand: the state before tick 0, then every vector of counter values.
// - `thirds` (m = 3): 1 + 3^3 = 28 states without symmetry, 1 + C(3+3-1, 3) = 11 orbits with
//   it; `below` (c != 2) violated at depth 3 (tick 0 starts at 0, two `inc`s reach 2).
// - `halves` (m = 2): 1 + 2^3 = 9 states, 1 + C(2+3-1, 3) = 5 orbits; `below` proved (c < 2).
chart Stepper(m: int[2..3] = 3) {
  input event inc;
  output c: int[0..2] = 0;
  initial S;
  state S { on inc / { c = (c + 1) % m; }; }
  invariant below: c != 2;
}

system Steppers {
  instance a[3]: Stepper;
  configuration thirds { }
  configuration halves { a = Stepper(m = 2); }
}
