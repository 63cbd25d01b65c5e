// A component checked against the interface it implements, like a chart: a missing port
// (E0152), a port of another kind (E0153), of an incompatible range (E0154).
interface Axis {
  input event go;
  input event back;
  output pos: int[0..3];
  output extended: bool;
}

chart Cylinder {
  input event go;
  input back: bool = false;
  output pos: int[0..9] = 0;
  initial S;
  state S { on go [pos < 9] / { pos = pos + 1; }; }
}

component Feeder implements Axis {
  input event go;
  input back: bool;
  output pos: int[0..9];
  instance cyl: Cylinder;
  connect go -> cyl.go;
  connect back -> cyl.back;
  connect cyl.pos -> pos;
}
