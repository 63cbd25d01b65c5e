enum Mode { IDLE, RUN }
chart C {
  input m: Mod = IDLE;
  local n: integer = 0;
  initial A;
  state A;
}
