// E0177: an interleaved system's implicit scheduler is the instance `sched` (its input
// `sched.unit` chooses the unit that steps); an instance of the system cannot take the name.

chart Blink {
  output lit: bool = false;
  initial S;
  state S { during { lit = !lit; } }
}

system Lights interleaved {
  instance sched: Blink;
  instance other: Blink;
}
