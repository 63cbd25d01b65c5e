chart C {
  initial A;
  state A {
    on;
  }
}
