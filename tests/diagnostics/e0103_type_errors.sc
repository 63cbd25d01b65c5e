enum Mode { IDLE, RUN }
chart C {
  input m: Mode = IDLE;
  local x: int[0..9] = 0;
  local b: bool = false;
  local u: int = 0;
  initial A;
  state A {
    on [x] -> A;
    on [m == 1] -> A;
    on [b < 2] -> A;
    entry {
      b = x + 1;
      x = if b then 1 else false;
      x = -b;
    }
  }
}
