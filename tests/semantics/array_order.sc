// R2: an instance array runs its elements in index order, at the array's place in the order.
// A ring a[0] -> a[1] -> a[2] -> a[0]: each element writes o = i + 1.
chart C {
  input i: int[0..9] = 0;
  output o: int[0..9] = 0;
  initial S;
  state S { during { o = min(i + 1, 9); } }
}
system Arr {
  instance a[3]: C;
  connect a[0].o -> a[1].i;
  connect a[1].o -> a[2].i;
  connect a[2].o -> a[0].i;
}
