// W0302: P and Q enter each other, but nothing reachable from A enters either.
chart C {
  input event go;
  initial A;
  state A {
    on go -> B;
  }
  state B {
    on go -> A;
  }
  state P {
    on go -> Q;
  }
  state Q {
    initial Q1;
    state Q1 { on go -> P; }   // a transition from inside Q counts as leaving Q
  }
}
