chart C {
  initial A;
  state A {
    entry { }
