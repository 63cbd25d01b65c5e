const BIG = 99999999999999999999;
chart C {
  initial A;
  state A;
}
