chart C {
  initial A;
  state A;
  /* this comment never ends
}
