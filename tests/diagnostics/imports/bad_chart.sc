// The error is in this imported file, and the diagnostic names it.
chart Bad {
  output x: int[0..3] = 0;
  initial S;
  state S { during { x = y; } }
}
