system S {
  state A { on go -> A; }
  instance c: C;
  instance d C;
  connect c.U d.a;
  connect c.U -> ;
  order c, d;
  local x: int;
  assume c.x > 0;
}
