// Top-level items of every kind.
tick 100 ms;
tick 2 s;
tick 1 min;
tick (N) ms;
const A = 1;
const B: int = 0x7FF;
const C: int[0..4_095] = 0b1010;
const D: bool = true;
const E: Color = Color.RED;
enum Color { RED, GREEN, BLUE, }
enum One { Only }
fn zero() -> int = 0;
fn add(a: int, b: int[-3..3]) -> int[-10..10] = a + b;
fn pick(c: bool, d: Color) -> bool { return c; }
fn lets(x: int) -> int { let a = x * 2; let b = a - 1; return max(a, b); }
