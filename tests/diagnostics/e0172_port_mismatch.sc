// Wrong uses of a component's ports (E0172): a port the component lacks, an input port
// written inside, an output port read inside, a port wired to an inner variable of another
// kind (an event to a variable) or an incompatible range, an output port driven twice.
chart Counter {
  input event step;
  input limit: int[0..5] = 5;
  output n: int[0..9] = 0;
  initial S;
  state S { on step [n < limit] / { n = n + 1; }; }
}
component Box {
  input event step;
  input limit: int[0..9];
  input event reset;
  output n: int[0..3];
  output m: int[0..9];
  instance c: Counter;
  instance d: Counter;
  instance k: Counter;
  connect step -> c.step;
  connect limit -> c.limit;
  connect c.n -> n;
  connect c.n -> m;
  connect d.n -> m;
  connect m -> d.limit;
  connect c.n -> step;
  connect reset -> k.limit;
}
system Shelf {
  instance b: Box;
  instance e: Counter;
  connect e.n -> b.size;
  invariant small: b.n <= 3;
}
