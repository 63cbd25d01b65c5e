chart C {
  initial A;
  state A {
    on after(3 s) -> A;
  }
}
