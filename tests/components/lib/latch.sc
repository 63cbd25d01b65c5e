// A library chart with a dead state: `Never` cannot be entered (its guard is false).
chart Latch {
  input set: bool = false;
  output lit: bool = false;
  initial Off;
  state Off { on [set] / { lit = true; } -> On; }
  state On { on [false] -> Never; }
  state Never;
}
