chart C {
  initial Idel;
  state Idle {
    initial X;
  }
  state Run;
  state Par {
    initial r1;
    region r1 { initial A; state A; }
    region r2 { initial B; state B; }
  }
}
