// A region is an exclusive node: it may have an `initial` action and `history`, like an
// exclusive state (not entry/exit/during actions nor transitions).
chart H {
  input event go;
  input event step;
  output x: int[0..9] = 0;
  initial P;
  state P {
    region r { history shallow; initial A / { x += 1; }; state A { on step -> B; } state B; }
    region s { initial C; state C; }
    on go -> Q;
  }
  state Q { on go -> P; }
}
