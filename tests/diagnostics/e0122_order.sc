chart C {
  initial A;
  state A;
}
system S {
  instance a: C;
  instance b: C;
  instance c: C;
  order a, a, Watch, b;
  observer Watch {
    initial ok;
    state ok;
    state error;
  }
}
