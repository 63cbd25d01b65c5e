chart Empty {
  local x: int[0..9] = 0;
}
chart P {
  region r1 { initial A; state A; }
  region r2 { }
}
