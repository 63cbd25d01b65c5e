system Empty {}
system Full {
  instance c: Controller;
  instance fam[N * 2]: Family;
  connect c.U -> fam[*].u;
  connect fam[0].y -> c.x;
  order c, fam;
  assume c.x >= -10 && c.x <= 10;
  assume true;
  invariant i1: c.U >= -10 assuming in(c.Go);
  invariant i2: fam[1].y != 3;
  reachable r1: in(c.Go.Pause);
  respond p1: c.Halt => in(c.Stop) within 0;
  observer Obs {
    input u: int[-10..10];
    input event halt;
    initial ok;
    state ok { on [u > 0] -> error; on halt; }
    state error;
    invariant never_error: !in(error);
  }
  observer Par { parallel { region a { initial A; state A; } } }
}
