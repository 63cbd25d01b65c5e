// W0310: a transition without a target skips its state's `during` in the ticks it fires.
chart C {
  input event reset;
  input event bump;
  output n: int[0..9] = 0;
  initial A;
  during { n = 0; }
  on reset / { n = 9; };
  state A {
    during { n = 1; }
    on bump [n < 9] / { n = 2; };
    on bump [n >= 9] -> A2;
  }
  state A2 { on bump -> A; }
}
