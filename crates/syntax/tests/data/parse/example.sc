tick 100 ms;
const N_MAX: int = 10;
enum Dir { Left, Right }
fn wrap(p: int[-4096..8191]) -> int[0..4095] = (p + 4096) % 4096;
fn parity(id: int[0..63]) -> int[0..3] { let p0 = (id ^ (id >> 1)) & 1; return p0 | (p0 << 1); }
chart Controller {
  input event Run; input event Halt;
  input x: int[-50..50] = 0;
  output U: int[-10..10] = 0;
  local count: int[0..20] = 0;
  local dir: Dir = Dir.Left;
  initial Stop;
  state Stop { entry { U = 0; count = 0; } on Run -> choice { [dir == Left] -> Go.GoLeft; else -> Go.GoRight; }; }
  state Go {
    history shallow;
    initial GoLeft;
    on Halt -> Stop priority 1;
    state GoLeft { entry { U = -10; count += 1; dir = Left; } on [x < -40] -> GoRight; }
    state GoRight { entry { U = 10; count += 1; dir = Right; } on [count > N_MAX] -> Pause; on [x > 40] -> GoLeft; }
    state Pause { entry { U = 0; count = 0; } on after(3 s) -> GoRight; }
  }
}
chart P { input a: bool; parallel { region r1 { initial A; state A { on [a] / { raise go; } ; } } region r2 { initial B; state B; } } local event go; }
system S {
  instance c: Controller; instance p[2]: P;
  connect c.U -> p[*].a;   // type errors are not the parser's business
  order c, p;
  assume c.x >= -10;
  invariant u_ok: c.U >= -10 assuming in(c.Go);
  reachable paused: in(c.Go.Pause);
  respond halts: c.Halt => in(c.Stop) within 1;
  observer Obs { input u: int[-10..10]; initial ok; state ok { on [u > 0] -> error; } state error; }
}
