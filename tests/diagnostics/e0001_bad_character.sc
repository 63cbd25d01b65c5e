chart C {
  local x: int[0..9] = 0;
  initial A;
  state A {
    on [x > 3 $ x < 5] -> A;
  }
}
