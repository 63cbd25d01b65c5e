chart C {
  initial S;
  state S {
    on Run S;
    on Run -> ;
    on Run -> choice [x] -> S;
    on Run priority high;
    on Run -> S priority 1 2;
    on after 3 -> S;
    on Run -> S;
  }
}
