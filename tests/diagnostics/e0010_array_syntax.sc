// E0010 in the syntax of arrays and loops: a missing `]` after a length or an index, a loop
// without `..` between its bounds.
chart C {
  output a[3: int[0..9] = 0;
  initial S;
  state S {
    during {
      for k in 0 { a[0] = 1; }
      a[1 = 2;
    }
  }
}
