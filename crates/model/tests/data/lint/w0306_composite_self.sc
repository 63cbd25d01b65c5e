// W0306: a composite state that transitions to itself.
chart C {
  input event reset;
  input event go;
  initial Run;
  state Run {
    initial Slow;
    on reset -> Run;
    state Slow { on go -> Fast; }
    state Fast { on go -> Slow; }
  }
}
