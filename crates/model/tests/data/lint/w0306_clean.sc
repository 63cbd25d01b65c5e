// Self-transitions on a leaf are fine; a composite state uses an internal transition.
chart C {
  input event reset;
  input event go;
  output n: int[0..100] = 0;
  initial Run;
  state Run {
    initial Slow;
    on reset / { n = 0; };
    state Slow { on go -> Fast; on reset -> Slow; }
    state Fast {
      on go -> Slow;
      on after(1) / { n = min(n + 1, 100); };
    }
  }
}
