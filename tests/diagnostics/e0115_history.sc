chart C {
  initial A;
  state A {
    history deep;
  }
  state P {
    history shallow;
    region r1 { initial X; state X; }
    region r2 { initial Y; state Y; }
  }
}
