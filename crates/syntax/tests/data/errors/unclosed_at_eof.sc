chart C {
  initial S;
  state S {
    entry {
      n = 1;
