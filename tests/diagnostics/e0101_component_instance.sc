// A misspelt instance inside a component: reported once (the component is instantiated
// twice) with a suggestion among the component's own instances and ports.
chart Sensor {
  output a: bool = false;
  initial A;
  state A { }
}
chart Valve {
  input a: bool = false;
  initial B;
  state B { }
}
component Cell {
  instance sensor: Sensor;
  instance valve: Valve;
  connect sensro.a -> valve.a;
}
system Plant {
  instance left: Cell;
  instance right: Cell;
}
