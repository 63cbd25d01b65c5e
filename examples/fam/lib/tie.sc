// lib/tie.sc — constant signals of the closed loops.
// Constant signals: the FAM's saveFails input in the closed loop (see the system) and the
// slave node addresses 0..4 (as outputs, so that they are not free inputs).
chart Tie {
  output low: bool = false;
  output k0: int[0..4] = 0;
  output k1: int[0..4] = 1;
  output k2: int[0..4] = 2;
  output k3: int[0..4] = 3;
  output k4: int[0..4] = 4;
  initial s;
  state s;
}
