chart C {
  input x;
  output y: ;
  local z: int[0, 3] = 0;
  local w: int[0..3 = 0;
  input event;
  output ok: bool;
}
