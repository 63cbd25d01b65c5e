chart C {
  output count: int[1..9];
  initial A;
  state A {
    during { count = if count < 9 then count + 1 else 1; }
  }
}
