// A small library: two sensors with the same interface.
chart Sensor {
  input raw: int[0..9] = 0;
  output present: bool = false;
  initial S;
  state S { during { present = raw > 3; } }
}
chart SensorWithFault {
  input raw: int[0..9] = 0;
  input stuck: bool = false;
  output present: bool = false;
  initial S;
  state S { during { present = if stuck then false else raw > 3; } }
}
