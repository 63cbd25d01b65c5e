// `sensors.sc` is found on the library path (`--lib tests/imports/lib` or STATECHECK_PATH);
// `parts/lamp.sc` relative to this file. plant_flat.sc is the same model written out by hand.
import "sensors.sc" { Sensor };
import "parts/lamp.sc";

system Plant {
  instance home: Sensor;
  instance lamp: Lamp;
  connect home.present -> lamp.on_;
  order home, lamp;
  // States (derived by hand): pre-start; after tick 0 (present = lit = false, no `during`);
  // afterwards present = raw > 3 and lit = present of the same tick (home runs first), so
  // (false, false) or (true, true): 3 states, each with 10 input vectors (raw in 0..9).
  invariant follows: lamp.lit == home.present;
  reachable lit: lamp.lit;
}
