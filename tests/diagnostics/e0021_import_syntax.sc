// The path must be a quoted string.
import sensors;
import "imports/sensors.sc" { };
chart Main { initial S; state S; }
