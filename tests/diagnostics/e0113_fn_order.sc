fn f(x: int[0..9]) -> int[0..9] = g(x);
fn g(x: int[0..9]) -> int[0..9] = x;
chart C {
  initial A;
  state A;
}
