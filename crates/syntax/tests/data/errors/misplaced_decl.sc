chart C {
  initial S;
  state S {
    local n: int[0..3] = 0;
    invariant bad: n > 0;
    on Go -> S;
  }
  instance c: C;
}
