// 5 % at 0.8 %/s takes 6.25 s: not a whole number of 1 s ticks. The nearest tick lengths
// in whole milliseconds that divide 6.25 s are 625 ms and 1250 ms.
tick 1 s;

plant chart Feeder {
  input push: bool = false;
  continuous pos: [0 .. 100] = 0;
  grid pos 20;
  initial Home;
  state Home { on [push] -> PushHeavy; }
  state PushHeavy {
    der(pos) = 0.8;
    on [pos >= 100] -> Home;
  }
}
