// The same file imported twice by one file (here once through `..`).
import "imports/sensors.sc" { Sensor };
import "imports/../imports/sensors.sc" { SensorWithFault };
system Main { instance s: Sensor; }
