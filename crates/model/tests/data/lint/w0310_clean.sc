// The work of the internal transition done inside `during`; an internal transition of a
// state without `during` suppresses nothing.
chart C {
  input event reset;
  input event bump;
  output n: int[0..9] = 0;
  initial A;
  state A {
    during { if bump && n < 9 { n = n + 1; } }
    on reset -> A2;
  }
  state A2 {
    on bump -> A;
    on reset / { n = 0; };
  }
}
