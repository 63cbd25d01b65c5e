const DEBUG: bool = true;
chart C {
  input event go;
  input x: int[0..3] = 0;
  initial A;
  state A {
    on go [DEBUG && x > 1] -> B;
    on go -> B;
  }
  state B {
    on go -> A;
  }
}
