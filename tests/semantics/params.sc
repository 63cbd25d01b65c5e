// A parameterised chart (docs/components.md): the period of `after` and the initial value of
// an output are parameters; each instance gives its own.
chart Blink(period: int[1..10], start_on: bool = false) {
  output lamp: bool = start_on;
  initial Wait;
  state Wait { on after(period) / { lamp = !lamp; } -> Wait; }
}

system Params {
  instance fast: Blink(1);
  instance slow: Blink(period = 2, start_on = true);
}
