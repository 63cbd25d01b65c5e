// W0303: two transitions of A both claim priority 1.
chart C {
  input x: int[0..10] = 0;
  initial A;
  state A {
    on [x > 5] -> B priority 1;
    on [x < 2] -> B priority 2;
    on [x == 3] -> B priority 1;
  }
  state B {
    on [x == 0] -> A;
  }
}
