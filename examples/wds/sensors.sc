// Position sensors over a range of a linear axis (the Feeder's end-position sensors).
import "common.sc";

// A sensor reads the axis position and reports whether it lies in its range.
interface PositionSensor {
  input pos: int[0..100];
  output detected: bool;
}

// The ideal sensor: detected exactly when lo <= pos <= hi.
chart Sensor(lo: int[0..100], hi: int[0..100]) implements PositionSensor {
  input pos: int[0..100] = 0;
  output detected: bool = false;
  initial Working;
  state Working {
    entry { detected = lo <= pos && pos <= hi; }
    during { detected = lo <= pos && pos <= hi; }
  }
}

// A sensor that may fail at any tick (the free input `fail`): from then on it is stuck at
// `false`, whatever the position (a broken wire).
chart Sensor_with_Fault(lo: int[0..100], hi: int[0..100]) implements PositionSensor {
  input pos: int[0..100] = 0;
  input event fail;
  output detected: bool = false;
  initial Working;
  state Working {
    entry { detected = lo <= pos && pos <= hi; }
    during { detected = lo <= pos && pos <= hi; }
    on fail / { detected = false; } -> Stuck;
  }
  state Stuck;
}
