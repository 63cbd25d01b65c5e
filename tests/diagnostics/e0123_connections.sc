chart P {
  output v: int[0..9] = 0;
  local hidden: int[0..9] = 0;
  initial A;
  state A;
}
chart Q {
  input v: int[0..9] = 0;
  output w: int[0..9] = 0;
  initial A;
  state A;
}
system S {
  instance p: P;
  instance q: Q;
  instance qs[2]: Q;
  connect p.hidden -> q.v;
  connect p.v -> q.w;
  connect p.v -> q.v;
  connect p.v -> q.v;
  connect qs[*].w -> q.v;
  connect p -> q.v;
  connect p.v -> qs.v;
}
system T {
  instance p: P;
  instance q: Q;
  connect p[0].v -> q.v;
}
