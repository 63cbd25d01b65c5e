chart C {
  output count: int[0..10] = 0;
  initial A;
  state A {
    entry { cnt = 1; total = 2; }
  }
}
