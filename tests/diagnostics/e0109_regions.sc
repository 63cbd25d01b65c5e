chart C {
  initial A;
  state A {
    region r1 { initial X; state X; }
    state Y;
  }
  state B {
    region r2 {
      initial X;
      entry { }
      state X;
    }
  }
}
