// Arithmetic: MIN % -1 (MIN = -2^63) overflows, like MIN / -1: a run-time error (R9), as C
// leaves both undefined. The mathematical remainder would be 0.
chart M {
  input d: int[-1..1] = 1;
  output r: int[-10..10] = 0;
  local m: int[-9223372036854775807 - 1 .. 0] = -9223372036854775807 - 1;
  initial A;
  state A { during { r = m % d; } }
}
