// Conversions: `Enum(n)` picks the literal with index n (a run-time error outside the enum),
// `int(x)` gives an enum's index or a bool as 0/1.
enum Mode { A, B, C }
chart Conv {
  input raw: int[0..7] = 0;
  output m: Mode = A;
  output idx: int[0..2] = 0;
  output b: int[0..1] = 0;
  initial S;
  state S { during { m = Mode(raw); idx = int(m); b = int(m == C); } }
}
