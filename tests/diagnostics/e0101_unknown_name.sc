// A misspelled variable in a guard: the hint suggests the closest name.
chart Pump {
  input level: int[0..100] = 0;
  output on_: bool = false;
  initial Off;
  state Off {
    on [levle > 80] -> On;
  }
  state On {
    entry { on_ = true; }
    on [level < 20 && threshold > 0] -> Off;
  }
}
