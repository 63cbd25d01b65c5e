// Each kind of mismatch between a chart and an interface it implements: a missing port
// (E0152), another direction or kind (E0153), another type or range (E0154), an unknown
// interface (E0101).
enum Level { LOW, HIGH }
interface Sensor {
  input raw: int[0..9];
  input event sample;
  output present: bool;
  output level: Level;
  output count: int[0..5];
}
chart Bad implements Sensor, Missing {
  input raw: int[0..5] = 0;
  output sample: bool = false;
  output present: int[0..1] = 0;
  output count: int[0..9] = 0;
  initial S;
  state S;
}
