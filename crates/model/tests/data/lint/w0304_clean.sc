// Guarded first, unguarded last; an exhaustive choice shadows only its own trigger.
chart C {
  input event go;
  input x: int[0..10] = 0;
  initial A;
  state A {
    on go [x > 3] -> C;
    on go -> B;
  }
  state B {
    on go [x > 5] -> A;
    on go -> C;                  // taken when x <= 5
    on after(5) -> A;
  }
  state C {
    on go -> choice {
      [x > 5] -> A;
      [x <= 5] -> B;             // exhaustive without `else`
    };
    on after(3) -> A;
  }
}
