// One 12-bit input per Drive. Wide has two drives: 4096 * 4096 = 16777216 input vectors per
// tick, refused without --force (verdict unknown, exit 3). Restricted has one drive whose
// target an assume limits to three positions: 3 vectors per tick, states = pre-start +
// pos in {0, 2048, 4095} = 4.
chart Drive {
  input target: int[0..4095];
  output pos: int[0..4095] = 0;
  initial Move;
  state Move { during { pos = target; } }
}

system Wide {
  instance a: Drive;
  instance b: Drive;
}

system Restricted {
  instance d: Drive;
  assume d.target == 0 || d.target == 2048 || d.target == 4095;
}
