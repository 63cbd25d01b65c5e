// plant.sc with its imports written out by hand: must give the same traces and state counts.
chart Sensor {
  input raw: int[0..9] = 0;
  output present: bool = false;
  initial S;
  state S { during { present = raw > 3; } }
}

chart Lamp {
  input on_: bool = false;
  output lit: bool = false;
  initial S;
  state S { during { lit = on_; } }
}

system Plant {
  instance home: Sensor;
  instance lamp: Lamp;
  connect home.present -> lamp.on_;
  order home, lamp;
  invariant follows: lamp.lit == home.present;
  reachable lit: lamp.lit;
}
