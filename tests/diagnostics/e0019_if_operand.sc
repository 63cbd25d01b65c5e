chart C {
  local x: int[0..9] = 0;
  initial A;
  state A {
    entry { x = 1 + if x > 2 then 1 else 0; }
  }
}
