// Locals that are written and read (in a guard, or by an observer).
chart C {
  input event go;
  local count: int[0..100] = 0;
  local seen: bool = false;
  local event beat;
  initial A;
  state A {
    entry { count = min(count + 1, 100); seen = true; }
    on go / { raise beat; } -> B;
  }
  state B {
    on beat [count < 5] -> A;
  }
}
system Sys {
  instance c: C;
  observer Watch {
    initial ok;
    state ok { on [c.seen && !in(c.A) && !in(c.B)] -> error; }
    state error;
  }
}
