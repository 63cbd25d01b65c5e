fn add(a: int[0..9], b: int[0..9]) -> int[0..18] = a + b;
chart C {
  local x: int[0..18] = 0;
  initial A;
  state A {
    entry { x = min(x); x = abs(x, 1); x = add(1); }
  }
}
