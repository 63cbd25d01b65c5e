// A request handler: Idle -req-> Work (n = 0), n counts up in Work, Work -> Done when n == 2,
// Done -> Idle. Work is entered at tick t, n = 1 at t+1, n = 2 at t+2, Done at t+3.
//
// Prompt: in(Work) => in(Done) within 3. The oldest trigger is the tick Work is entered, t;
// Done comes at t+3: proved.
// Slow: the same within 2: Work entered at tick 1 at the earliest (tick 0 only enters Idle),
// unanswered at tick 3 = 1 + 2: violated at tick 3, 4 ticks.
// Eager: req => in(Done) within 3. A request at tick 0 cannot be served (tick 0 only enters
// Idle); with no request at tick 1, it is still unanswered at tick 3: violated at tick 3,
// 4 ticks, and no shorter counterexample exists since the monitor needs 3 ticks to exceed 3.
chart Req {
  input event req;
  local n: int[0..3] = 0;
  initial Idle;
  state Idle { on req / { n = 0; } -> Work; }
  state Work {
    during { n += 1; }
    on [n == 2] -> Done;
  }
  state Done { on -> Idle; }
}

system Prompt {
  instance r: Req;
  respond work_done: in(r.Work) => in(r.Done) within 3;
}

system Slow {
  instance r: Req;
  respond work_done: in(r.Work) => in(r.Done) within 2;
}

system Eager {
  instance r: Req;
  respond req_done: r.req => in(r.Done) within 3;
}
