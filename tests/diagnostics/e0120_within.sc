// A response bound in time units must be a whole number of ticks: 150 ms with 100 ms ticks.
tick 100 ms;

chart C {
  input event go;
  initial A;
  state A { on go -> B; }
  state B;
}

system S {
  instance c: C;
  respond quick: c.go => in(c.B) within 150 ms;
}
