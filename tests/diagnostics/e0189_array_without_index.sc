// E0189: an array named without an index (or with `[*]` outside a connection).
chart C {
  input a[2]: int[0..9] = 0;
  output y: int[0..9] = 0;
  output b[2]: int[0..9] = 0;
  initial S;
  state S {
    during {
      y = a;
      b = 1;
      y = a[*];
    }
  }
}
chart D {
  input x: int[0..9] = 0;
  initial S;
  state S;
}
system Sys {
  instance c: C;
  instance d: D;
  connect c.b -> d.x;
  invariant i: c.b[*] == 0;
}
