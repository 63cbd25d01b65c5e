fn clamp(x: int[-100..100]) -> int[0..10] = max(0, min(x, 10));
chart C {
  local x: int[0..10] = 0;
  initial A;
  state A {
    during { x = clmp(x + 1); x = saturate(x); }
  }
}
