// R1: tick 0 only initialises. An input event given in tick 0 is seen by entry actions (and
// by the properties checked after tick 0) but triggers no transition.
chart E {
  input event go;
  output saw: bool = false;
  output fired: bool = false;
  initial A;
  state A { entry { saw = go; } on go / { fired = true; } -> B; }
  state B;
}
