// lib/tie.sc — constant signals of the closed loops.
// Constant signals: the FAM's saveFails input in the closed loop (see the system) and the
// slave node addresses k[0..N-1] = 0..N-1 (as outputs, so that they are not free inputs; set
// by the entry action, which runs in tick 0 before any slave reads them: `tie` runs first).
chart Tie(N: int[1..5] = 5) {
  output low: bool = false;
  output k[N]: int[0..4] = 0;
  initial s;
  state s {
    entry {
      low = false;
      for i in 0..N { k[i] = i; }
    }
  }
}
