// Timers: the timer of a state counts the ticks in which the step reaches it, from 0 at
// entry. An ancestor's transition that fires (here S's internal transition on `poke`) ends
// the reaction above A, so A's timer does not advance in that tick.
chart T {
  input event poke;
  output n: int[0..20] = 0;
  initial S;
  state S {
    on poke / { n += 1; };
    initial A;
    state A { on after(3) -> B; }
    state B;
  }
}
