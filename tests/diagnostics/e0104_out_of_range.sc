tick 0 ms;
const K: int[0..10] = 11;
chart C {
  local x: int[0..9] = 12;
  local y: int[0..9] = 0;
  initial A;
  state A {
    entry { y = 10; x = 1 / 0; y = 1 << 63; }
    on [x > 3] -> A priority 0;
  }
}
