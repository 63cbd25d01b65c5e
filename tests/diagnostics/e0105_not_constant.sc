chart C {
  input n: int[0..9] = 0;
  local x: int[0..9] = n;
  initial A;
  state A {
    on after(n) -> A;
  }
}
system S {
  instance c[c.n]: C;
}
