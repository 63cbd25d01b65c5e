// HOME_SENSOR between the Feeder's home range predicate (`Feeder.home`, pos in [0, 5] %) and
// the Storage controller: ideal, or with a fault.
import "common.sc";

// A sensor passes on its raw reading (the range predicate of the plant) to the controller.
interface PositionSensor {
  input raw: bool;
  output detected: bool;
}

// The ideal sensor: detected exactly when the position lies in its range.
chart Sensor implements PositionSensor {
  input raw: bool = false;
  output detected: bool = false;
  initial Working;
  state Working {
    entry { detected = raw; }
    during { detected = raw; }
  }
}

// A sensor that may fail at any tick (the free input `fail`): from then on it is stuck at
// `false`, whatever the position (a broken wire).
chart Sensor_with_Fault implements PositionSensor {
  input raw: bool = false;
  input event fail;
  output detected: bool = false;
  initial Working;
  state Working {
    entry { detected = raw; }
    during { detected = raw; }
    on fail / { detected = false; } -> Stuck;
  }
  state Stuck;
}
