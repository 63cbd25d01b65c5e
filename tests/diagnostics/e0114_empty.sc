chart C {
  local x: int[10..0] = 5;
  initial A;
  state A;
}
