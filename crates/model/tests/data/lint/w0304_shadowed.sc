// W0304: transitions that an earlier, always-enabled one preempts.
chart C {
  input event go;
  input x: int[0..10] = 0;
  initial A;
  state A {
    on go -> B;
    on go [x > 3] -> C;          // same trigger, the first one always wins
  }
  state B {
    on after(5) -> A;
    on after(5) -> C;            // same delay
    on go -> choice {
      [true] -> A;
      [x > 2] -> C;              // after a branch that is always taken
    };
  }
  state C {
    on [x > 1] -> A priority 2;
    on -> B priority 1;          // fires in every step, so the guarded one never does
  }
}
