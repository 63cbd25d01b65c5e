chart C {
  local x: int[0..9] = 0;
  initial A;
  junction j {
    [x > 5] -> A;
    else -> k;
  }
  junction k {
    [x > 2] -> A;
    else -> j;
  }
  state A {
    on [x == 0] -> j;
  }
}
