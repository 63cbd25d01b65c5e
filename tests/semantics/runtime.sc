// R9: a value out of range stops the run at that tick.
chart Runtime {
  input step: int[0..3] = 0;
  local c: int[0..5] = 0;
  initial A;
  state A { during { c = c + step; } }
}
