// W0202: an instance connected to itself reads its own output slot: a value written earlier
// in the same step (here by region r1, which runs before r2) is seen in the same tick.
chart W {
  input i: int[0..9] = 0;
  output o: int[0..9] = 0;
  output seen: int[0..9] = 0;
  region r1 { initial A; state A { during { o = min(o + 1, 9); } } }
  region r2 { initial B; state B { during { seen = i; } } }
}
system Self { instance w: W; connect w.o -> w.i; }
