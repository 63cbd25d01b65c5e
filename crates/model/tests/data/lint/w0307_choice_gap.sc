// W0307: choices whose guards can all be false.
enum Mode { Off, Low, High }
chart C {
  input event go;
  input m: Mode = Off;
  input x: int[0..1000] = 0;
  initial A;
  state A {
    on go -> choice {
      [m == Low] -> B;
      [m == High] -> B;
    };
  }
  state B {
    on go -> choice {
      [x > 500] -> A;
      [x < 100] -> choice {
        [m == Off] -> A;
        [m == Low] -> A;
      };
      else -> A;
    };
  }
}
