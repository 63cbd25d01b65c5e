tick 100 ms;
chart C {
  initial A;
  state A {
    on after(250 ms) -> A;
  }
}
