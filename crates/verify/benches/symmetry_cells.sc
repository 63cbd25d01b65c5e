// `verify --symmetry` on the SAT side (docs/verification.md, "Symmetry reduction"): N
// identical cells, each with a proved property that IC3 needs a few hundred milliseconds for.
// Timed with and without `--symmetry`, N = 6, 7, 8 (`sed 's/c\[8\]/c[6]/'` for the others):
//   statecheck verify crates/verify/benches/symmetry_cells.sc --engine ic3 [--symmetry]
chart Cell {
  input event inc;
  input event rst;
  output x: int[0..255] = 0;
  initial S;
  state S {
    on rst / { x = 0; };
    on inc [x < 252] / { x = x + 3; };
  }
  // x stays a multiple of 3 (0, 3, ..., 252), so x != 235 (235 = 3 * 78 + 1) is proved; it is
  // not inductive: IC3 must learn x mod 3 = 0 in bits.
  invariant never235: x != 235;
}

system Cells {
  instance c[8]: Cell;
}
