const A = 3;
const B = A + C;
const C = 2;
chart X {
  initial S;
  state S;
}
