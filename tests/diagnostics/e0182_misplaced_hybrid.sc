// A sensor on an integer output, `der` at chart level and of an undeclared variable.
tick 1 s;

plant chart P {
  output o: int[0 .. 1] = 0;
  continuous x: [0 .. 10] = 0;
  sensor o = x in [0 .. 5];
  der(x) = 1;
  initial A;
  state A { der(z) = 1; }
}
