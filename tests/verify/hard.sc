// One property decided in moments and one that no engine decides within seconds, for the
// tests of streaming, interruption and budgets (crates/cli/tests/verify_live.rs).
//
// By hand: tick 0 enters Run; from tick 1 each tick adds one to c (c = 1 after tick 1), so
// `fast` (c < 3) is violated at tick 3 and its counterexample has 4 ticks (0..3).
// `commutes` holds (p = a*b and q = (a+1)*b - b are equal for all a, b), but deciding it means
// proving two 30-bit multipliers equal: hopeless for a SAT solver within seconds, and the
// explicit engine refuses 2^60 input vectors per tick. It stays `unknown` under a time limit.
chart Mul {
  input a: int[0..1073741823];
  input b: int[0..1073741823];
  output p: int[0..1152921504606846976] = 0;
  output q: int[0..1152921504606846976] = 0;
  output c: int[0..9] = 0;
  initial Run;
  state Run {
    during {
      p = a * b;
      q = (a + 1) * b - b;
      c = min(c + 1, 9);
    }
  }
}

// `commutes` first, so that a single engine meets the hard property before the easy one.
system Hard {
  instance m: Mul;
  invariant commutes: m.p == m.q;
  invariant fast: m.c < 3;
}
