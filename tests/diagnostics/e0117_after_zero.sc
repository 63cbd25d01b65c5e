chart C {
  initial A;
  state A {
    on after(0) -> A;
  }
}
