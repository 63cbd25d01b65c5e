const A = ;
enum Dir { Left Right }
chart Controller {
  input x: int[0..9] = 0;
  initial Stop;
  state Stop { entry { U = 0 } on Run -> ; }
  state Go { on [x = 1] -> Stop; on; }
}
system S {
  instance c Controller;
  connect c.U p.a;
  order c,;
  invariant ok c.U > 0;
}
const Z = 1;
