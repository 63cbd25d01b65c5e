// R1, R4, R5: initialisation order, exit innermost-first, entry outermost-first, group
// transitions tried before inner ones, self-transition of a composite exits and re-enters.
// Each action appends a digit to `log`; the chart-level `during` clears it every tick, so the
// value of `log` after a tick spells the order of that tick's actions.
chart Order {
  input event e;
  input event f;
  local log: int[0..999999999] = 0;
  entry { log = 1; }
  during { log = 0; }
  initial A;
  state A {
    entry { log = log * 10 + 2; }
    exit { log = log * 10 + 3; }
    initial A1;
    on f / { log = log * 10 + 8; } -> A;
    state A1 {
      entry { log = log * 10 + 4; }
      exit { log = log * 10 + 5; }
      on e -> B;
    }
  }
  state B {
    entry { log = log * 10 + 6; }
    on e / { log = log * 10 + 7; } -> A.A1;
  }
}
