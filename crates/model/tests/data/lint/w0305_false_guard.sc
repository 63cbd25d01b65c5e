// W0305: guards that are the constant false.
const DEBUG: bool = false;
chart C {
  input event go;
  initial A;
  state A {
    on go [DEBUG] -> B;
    on go -> B;
  }
  state B {
    on go -> choice {
      [1 > 2] -> A;
      else -> A;
    };
  }
}
