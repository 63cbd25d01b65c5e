tick 10 ms;
chart T {
  input event go; input event stop;
  input x: int[0..10];
  local n: int[0..100] = 0;
  initial A;
  state A {
    on go -> B;
    on [x > 3] -> B;
    on go [x > 3] -> B;
    on go / { n = 1; } -> B;
    on go [x == 1] / { n = 2; } -> B priority 2;
    on go -> B priority 1;
    on stop;
    on [x == 0] / { n += 1; };
    on / { n = 0; } -> B;
    on after(5) -> B;
    on after(N + 1) -> B;
    on after(3 s) -> B;
    on after(250 ms) -> B;
    on after(N s) -> B;
    on after((N * 2) min) -> B;
    on after(2) [x > 1] -> B;
    on go -> choice { [x > 5] -> B; [x > 2] / { n = 3; } -> choice { [n > 1] -> B.B1; else -> A; }; else -> A; };
    on stop -> B.B1 priority 3;
  }
  state B { initial B1; state B1; }
}
