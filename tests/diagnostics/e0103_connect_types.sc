chart P {
  output flag: bool = false;
  initial A;
  state A;
}
chart Q {
  input level: int[0..9] = 0;
  initial A;
  state A;
}
system S {
  instance p: P;
  instance q: Q;
  connect p.flag -> q.level;
}
