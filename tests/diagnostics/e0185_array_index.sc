// E0185: a constant index out of range, or an index on a scalar (in a chart and in a system).
chart C {
  output a[3]: int[0..9] = 0;
  output s: int[0..9] = 0;
  initial S;
  state S {
    during {
      a[3] = 1;          // out of range
      s = a[-1];         // out of range
      s[0] = 2;          // a scalar
    }
  }
}
system Sys {
  instance c: C;
  invariant i: c.a[5] == 0 && c.s[0] == 0;
}
