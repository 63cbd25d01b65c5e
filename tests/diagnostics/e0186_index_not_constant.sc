// E0186: an index that is not a compile-time constant (a variable selects no element before
// checking; the hint shows the loop that writes the selection out).
chart C {
  input i: int[0..2] = 0;
  input a[3]: int[0..9] = 0;
  output y: int[0..9] = 0;
  initial S;
  state S {
    during {
      y = a[i];
    }
  }
}
