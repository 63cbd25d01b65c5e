const MASK = 0b1021;
chart C {
  initial A;
  state A;
}
