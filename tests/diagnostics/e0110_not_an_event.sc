chart C {
  input speed: int[0..9] = 0;
  input fast: bool = false;
  output event alarm;
  initial A;
  state A {
    on fast -> A;
    entry { alarm = true; speed = 3; }
  }
}
