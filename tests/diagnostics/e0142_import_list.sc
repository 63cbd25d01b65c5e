// `Sensr` is not declared by sensors.sc.
import "imports/sensors.sc" { Sensor, Sensr };
system Main { instance s: Sensor; }
