const N = 3;
const N = 4;
enum E { A, B, A }
chart C {
  local x: int[0..9] = 0;
  local x: bool = false;
  initial S;
  state S;
  state S;
}
system Sys {
  instance c: C;
  instance c: C;
  invariant p: c.x == 0;
  invariant p: c.x != 0;
}
system Sys {
  instance d: C;
}
fn f(x: int[0..9]) -> int[0..9] = x;
fn f(x: int[0..9]) -> int[0..9] = x + 1;
