tick 10 ms;
tick 20 ms;
chart C {
  initial A;
  initial B;
  history shallow;
  history deep;
  state A {
    entry { }
    entry { }
  }
  state B;
}
system S {
  instance c: C;
  order c;
  order c;
}
