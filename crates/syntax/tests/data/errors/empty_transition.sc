chart C {
  initial S;
  state S {
    on;
    on / { n = 1; };
    on priority 2;
  }
}
