// Every state is entered: by `initial`, by a transition, or through a descendant.
chart C {
  input event go;
  input event jump;
  initial A;
  state A {
    on go -> B;
    on jump -> Outer.In2;  // enters Outer on the way to In2
  }
  state B {
    on go -> A;
  }
  state Outer {
    history shallow;
    initial In1;
    state In1 { on go -> In2; }
    state In2 { on go -> In1; on jump -> A; }
  }
}
