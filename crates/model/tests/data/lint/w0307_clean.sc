enum Mode { Off, Low, High }
chart C {
  input event go;
  input m: Mode = Off;
  input x: int[0..1000] = 0;
  initial A;
  state A {
    on go -> choice {
      [m == Low] -> B;
      [m == High || m == Off] -> B;    // covers every literal
    };
  }
  state B {
    on go [x >= 100] -> choice {
      [x > 500] -> A;
      [x <= 500] -> A;
    };
    on go -> choice {
      [m == Off] -> A;
      else -> A;
    };
  }
}
