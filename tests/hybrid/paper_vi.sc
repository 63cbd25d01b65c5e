// The IEC 61499 paper's §VI example: a cylinder moving forward at Speed = 5 % of its stroke
// per time unit over D = 100, discretized into N = 4 cells. T(x) = x / Speed, so the clock
// readings at the grid points 25, 50, 75, 100 are 5, 10, 15, 20 time units (here seconds,
// with a tick of 1 s: 5, 10, 15, 20 ticks).
tick 1 s;

plant chart Linear {
  input go: bool = false;
  output at_end: bool;
  continuous x: [0 .. 100] = 0;
  grid x 4;
  sensor at_end = x in [100 .. 100];

  initial Home;
  state Home { on [go] -> Forward; }
  state Forward {
    der(x) = 5;
    on [x >= 100] -> End;
  }
  state End;
}
