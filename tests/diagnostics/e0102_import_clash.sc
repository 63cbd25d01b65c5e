// `Sensor` is declared here and in the imported file: both places are shown.
import "imports/sensors.sc";
chart Sensor { initial S; state S; }
