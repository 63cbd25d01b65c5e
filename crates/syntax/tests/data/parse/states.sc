chart States {
  input event go;
  initial Top / { n = 0; };
  entry { n = 1; }
  during { n += 1; }
  exit { n = 0; }
  state Top {
    history deep;
    initial A;
    entry { n = 2; }
    during { n -= 1; }
    exit { n = 3; }
    state A;
    state B {}
    state C {
      initial C1;
      state C1 { state C1a; initial C1a; }
    }
    junction J {
      [n > 0] -> A;
      [n < 0] / { n = 0; } -> B;
      else -> C.C1;
    }
    on go -> J;
  }
  state Par {
    history shallow;
    region left { initial L; state L; }
    region right { initial R; state R { entry { raise go; } } }
  }
}
