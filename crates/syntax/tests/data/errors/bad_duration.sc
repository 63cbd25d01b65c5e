tick 100;
tick 100 sec;
chart C {
  initial S;
  state S {
    on after(3 sec) -> S;
    on after(2 * N s) -> S;
    on after(3 s) -> S;
  }
}
