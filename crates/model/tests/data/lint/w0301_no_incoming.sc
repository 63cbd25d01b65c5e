// W0301: `Lost` is not the initial state and nothing enters it.
chart C {
  input event go;
  input event again;
  initial A;
  state A {
    on go -> B;
  }
  state B {
    on go -> A;
  }
  state Lost {
    on go -> A;
    on again -> Lost;     // a self-loop is no way in
  }
  state Outer {
    // history only resumes a state entered before: it does not make Outer reachable
    history shallow;
    initial In1;
    state In1 { on go -> In2; }
    state In2 { on go -> In1; }
  }
}
