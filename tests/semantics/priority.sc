// Priorities: explicit `priority N` before textual order; a composite's (group) transitions
// are tried before its children's.
chart Pri {
  input event e;
  local log: int[0..99] = 0;
  initial A;
  state A {
    initial A1;
    on e [log == 12] / { log = 2; } -> B;
    state A1 {
      on e / { log = 11; } -> A2;
      on e / { log = 12; } -> A2 priority 1;
    }
    state A2;
  }
  state B;
}
