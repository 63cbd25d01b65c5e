chart Echo {
  input prev: int[0..9] = 0;
  output next: int[0..9] = 0;
  initial A;
  state A {
    during { next = (prev + 1) % 10; }
  }
}
system S {
  instance e: Echo;
  connect e.next -> e.prev;
}
