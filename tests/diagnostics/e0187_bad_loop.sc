// E0187: a loop with bounds that are not constant, one whose variable hides another name, and
// loops that unroll to too many statements.
chart C {
  input n: int[0..3] = 0;
  output a[4]: int[0..9] = 0;
  local k: int[0..9] = 0;
  initial S;
  state S {
    during {
      for i in 0..n { a[0] = 1; }
      for k in 0..4 { a[k] = 2; }
      for i in 0..4 {
        for i in 0..4 { a[i] = 3; }
      }
      for i in 0..100000 {
        for j in 0..100000 { a[0] = 4; }
      }
    }
  }
}
