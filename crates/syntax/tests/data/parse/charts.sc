plant chart Plant {
  input u: int[-10..10] = 0;
  output y: int[0..100] = 50;
  output event overflow;
  local event tickle;
  initial Run;
  state Run { during { y += u; } }
  invariant y_ok: y >= 0;
  reachable top: y == 100;
  respond resp: u > 0 => y > 50 within 10;
}
requirement chart Req {
  input y: int[0..100];
  parallel {
    region a { initial A; state A; }
    region b { initial B; state B; }
  }
  invariant in_range: y <= 100 assuming in(a.A);
}
chart Empty {}
chart Mixed { parallel { } parallel { region only { initial X; state X; } } }
