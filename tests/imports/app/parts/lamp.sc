// A lamp that shows its input.
chart Lamp {
  input on_: bool = false;
  output lit: bool = false;
  initial S;
  state S { during { lit = on_; } }
}
