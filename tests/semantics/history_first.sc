// R8: the first entry of a state with history takes the default path (with the initial
// action); later entries resume the remembered child without it.
chart HistoryFirst {
  input event go;
  input event step;
  output x: int[0..9] = 0;
  initial Off;
  state Off { on go -> On; }
  state On {
    history shallow;
    initial A / { x = x + 1; };
    on go -> Off;
    state A { on step -> B; }
    state B;
  }
}
