chart C {
  input event start;
  local event done;
  initial A;
  state A {
    on strat -> B;
    on stop -> B;
  }
  state B {
    entry { raise finished; }
    on done -> A;
  }
}
