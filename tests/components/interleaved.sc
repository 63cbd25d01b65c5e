// Synchronous and interleaved composition of the same two units (docs/components.md).
//
// `a` toggles `x` in every step it takes; `b` copies `a.x` into `y` in every step it takes.
//
// Synchronous (`Sync`): tick 0 enters (x = y = false); in every later tick a runs, then b
// reads the new x, so y == x after every tick: `same` holds. States by hand: (x, y) in
// {(F,F), (T,T)} plus the state before tick 0: 3; no input, 1 successor each: 3 transitions.
//
// Interleaved (`Async`): one unit steps per tick, chosen by the input `sched.unit` (0 = a,
// 1 = b, in execution order). Tick 1 with `sched.unit = 0`: a makes x = true, b does not step,
// y stays false: `same` is violated at tick 1. States by hand: all four (x, y) (from (F,F): a
// gives (T,F); from (T,F): b gives (T,T); from (T,T): a gives (F,T)) plus the state before
// tick 0: 5; 2 scheduler choices from each: 10 transitions.

chart Toggle {
  output x: bool = false;
  initial S;
  state S { during { x = !x; } }
}

chart Copy {
  input i: bool = false;
  output y: bool = false;
  initial S;
  state S { during { y = i; } }
}

system Sync {
  instance a: Toggle;
  instance b: Copy;
  connect a.x -> b.i;
  order a, b;
  invariant same: b.y == a.x;
}

system Async interleaved {
  instance a: Toggle;
  instance b: Copy;
  connect a.x -> b.i;
  order a, b;
  invariant same: b.y == a.x;
}
