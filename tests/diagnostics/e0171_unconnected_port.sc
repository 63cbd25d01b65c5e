// Ports that lead nowhere inside their component (E0171): an input port that feeds no inner
// instance and an output port that no inner instance drives.
chart Lamp {
  input power: bool = false;
  output lit: bool = false;
  initial S;
  state S { during { lit = power; } }
}
component Panel {
  input power: bool;
  input dim: bool;
  output lit: bool;
  output broken: bool;
  instance lamp: Lamp;
  connect power -> lamp.power;
  connect lamp.lit -> lit;
}
system Desk {
  instance p: Panel;
  invariant lit_follows: p.lit == p.power;
}
