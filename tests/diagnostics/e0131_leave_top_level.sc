chart C {
  region left {
    initial A;
    state A { on [in(right.B)] -> right.B; }
  }
  region right {
    initial B;
    state B;
  }
}
