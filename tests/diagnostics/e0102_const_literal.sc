// A constant named like an enum literal (declared after it, and before it): a bare `RED` or
// `OFF` could mean either, so each constant is rejected at its declaration.
enum Color { RED, GREEN }
const RED = 7;
const OFF: int = 0;
enum Light { OFF, ON }
chart C {
  local c: Color = Color.GREEN;
  local n: int[0..9] = 0;
  initial A;
  state A {
    entry { c = Color.RED; n = 1; }
  }
}
