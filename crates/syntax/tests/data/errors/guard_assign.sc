chart C {
  input x: int[0..9];
  initial S;
  state S { on [x = 3] -> S; }
  invariant p: x = 1;
}
