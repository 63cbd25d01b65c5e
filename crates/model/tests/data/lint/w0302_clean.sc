// The only way into Q is from inside P's subtree, and P is entered from A.
chart C {
  input event go;
  initial A;
  state A {
    on go -> P.P2;
  }
  state P {
    initial P1;
    state P1 { on go -> P2; }
    state P2 { on go -> Q; }
  }
  state Q {
    on go -> A;
  }
}
