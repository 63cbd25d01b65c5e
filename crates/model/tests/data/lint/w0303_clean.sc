// Distinct priorities; equal numbers on different states are fine.
chart C {
  input x: int[0..10] = 0;
  initial A;
  state A {
    on [x > 5] -> B priority 1;
    on [x < 2] -> B priority 2;
  }
  state B {
    on [x == 0] -> A priority 1;
  }
}
