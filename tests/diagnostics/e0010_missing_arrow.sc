chart C {
  input event go;
  initial A;
  state A {
    on go B;
  }
  state B;
}
