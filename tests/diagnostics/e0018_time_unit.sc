tick 10 ms;
chart C {
  initial A;
  state A {
    on after(2 sec) -> A;
  }
}
