// A speed must be a number, a constant or a ratio.
tick 1 s;

plant chart P {
  continuous x: [0 .. 10] = 0;
  initial A;
  state A { der(x) = true; }
}
