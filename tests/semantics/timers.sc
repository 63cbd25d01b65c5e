// after(n): a state entered at tick t can leave by `after(n)` at tick t+n at the earliest.
chart Timers {
  local n: int[0..100] = 0;
  initial A;
  state A { on after(3) / { n += 1; } -> B; }
  state B { on after(2) -> A; }
}
