// 100 is not divisible into 3 whole-number cells; the second range is empty.
tick 1 s;

plant chart P {
  continuous x: [0 .. 100] = 0;
  grid x 3;
  continuous y: [5 .. 5];
  initial A;
  state A { der(x) = 1; }
}
