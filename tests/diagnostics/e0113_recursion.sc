fn fact(n: int[0..5]) -> int[1..120] = if n == 0 then 1 else n * fact(n - 1);
const X = later(2);
fn later(x: int[0..9]) -> int[0..9] = x;
chart C {
  initial A;
  state A;
}
