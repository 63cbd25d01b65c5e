chart C {
  initial A;
  state A {
    parallel {
      region r { initial X; state X; }
    }
  }
}
