// `within` in time units (issue 18): ticks of 100 ms. `go` moves Idle -> Wait (from tick 1 on:
// no transition fires in tick 0); Wait leaves through `after(2 s)` = 20 ticks, so Wait
// entered in tick i (the trigger, holding in ticks i ..= i + 19) is answered by Done in tick
// i + 20, never earlier. So a bound of 20 ticks (2 s, 2000 ms) holds and a bound of 19 ticks
// (1900 ms) is violated: Wait entered in tick 1, unanswered at tick 1 + 19 = 20, i.e. 2.0 s.
tick 100 ms;

chart Answer {
  input event go;
  initial Idle;
  state Idle { on go -> Wait; }
  state Wait { on after(2 s) -> Done; }
  state Done;
}

system InSeconds {
  instance a: Answer;
  respond in_2s: in(a.Wait) => in(a.Done) within 2 s;
  respond in_2000ms: in(a.Wait) => in(a.Done) within 2000 ms;
  respond in_1900ms: in(a.Wait) => in(a.Done) within 1900 ms;
}

system InTicks {
  instance a: Answer;
  respond in_2s: in(a.Wait) => in(a.Done) within 20;
  respond in_2000ms: in(a.Wait) => in(a.Done) within 20;
  respond in_1900ms: in(a.Wait) => in(a.Done) within 19;
}
