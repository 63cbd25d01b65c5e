// A parameterised plant chart in synthesis (docs/components.md): the parameter expansion
// happens before synthesis reads the checked model. By hand: the machine and the
// requirement both alternate start/finish, so the product has 2 reachable states and the
// supervisor allows `start` everywhere: 2 states, 2 transitions.
plant chart Machine(k: int[0..3] = 0) {
  controllable event start;
  uncontrollable event finish;
  initial Idle;
  marked state Idle { on start -> Working; }
  state Working { on finish -> Idle; }
}

requirement chart Once {
  controllable event start;
  uncontrollable event finish;
  initial A;
  marked state A { on start -> B; }
  state B { on finish -> A; }
}

system S {
  instance m: Machine(2);
  instance r: Once;
}
