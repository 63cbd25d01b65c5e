chart C {
  output x: int[0..9] = 0;
  initial A;
  state A;
}
system S {
  instance c: C;
  observer Watch {
    initial ok;
    state ok { on [c.x > 5] -> bad; }
    state bad;
  }
}
