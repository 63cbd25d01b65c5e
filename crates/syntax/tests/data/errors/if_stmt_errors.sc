chart C {
  local n: int[0..3] = 0;
  initial S;
  state S {
    entry {
      if n > 0 then { n = 1; }
      n == 2;
      f(n);
      c.n = 1;
      let k = 2;
      else { n = 0; }
      3;
      n = 2;
    }
  }
}
