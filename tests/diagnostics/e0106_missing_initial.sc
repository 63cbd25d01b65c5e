chart C {
  state A {
    state A1;
    state A2;
  }
  state B;
}
