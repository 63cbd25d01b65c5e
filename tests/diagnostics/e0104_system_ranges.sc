chart P {
  output v: int[0..100] = 0;
  initial A;
  state A;
}
chart Q {
  input v: int[0..10] = 0;
  initial A;
  state A;
}
system S {
  instance p: P;
  instance qs[0]: Q;
  instance rs[2]: Q;
  connect p.v -> rs[0].v;
  connect p.v -> rs[5].v;
  invariant i: rs[2].v == 0;
  respond r: p.v > 0 => p.v == 0 within -1;
}
