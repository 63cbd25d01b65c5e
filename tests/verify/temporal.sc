// Temporal properties with answers derived by hand (crates/cli/tests/temporal.rs).
//
// One counter: `reset` (checked first) sets n to 0; `inc` adds 1 below 3. Positions are the
// states after each tick; tick 0 only initialises (n = 0) and ignores its events.
chart C {
  input event inc;
  input event reset;
  output n: int[0..3] = 0;
  initial A;
  state A {
    on reset / { n = 0; } -> A;
    on inc [n < 3] / { n += 1; } -> A;
  }
}

system Free {
  instance c: C;
  ltl reaches3: F c.n == 3;            // violated: inc never comes (lasso: n = 0 forever)
  ltl bounded: G c.n <= 3;             // proved: the type's range
  ltl gf_zero: G F c.n == 0;           // violated: inc three times, then nothing
  respond resets: c.reset => c.n == 0; // proved: reset at tick >= 1 zeroes n in that tick; at
                                       // tick 0 n is 0 already
  ctl can_reach3: AG EF c.n == 3;      // proved: inc is always possible
  ctl ax_one: AX c.n == 1;             // violated: position 0 can be followed by n = 0
  ctl eg_low: EG c.n < 3;              // proved: the run without inc
  nonblocking zero: c.n == 0;          // proved: reset is always possible
}

// Justice on `inc && !reset` does not force n to 3: resets may come in between
// (n = 0, 1, 0, 1, ...), so the counterexample's loop contains an inc without reset.
system FairInc {
  instance c: C;
  fair inc_often: c.inc && !c.reset;
  ltl reaches3: F c.n == 3;            // violated, by a fair lasso
  ltl gf_inc: G F (c.inc && !c.reset); // proved: it is the fairness constraint itself
}

// Without resets, justice on inc makes n reach 3.
system NoReset {
  instance c: C;
  assume !c.reset;
  fair inc_often: c.inc;
  ltl reaches3: F c.n == 3;            // proved
  ltl stays3: F G c.n == 3;            // proved: n never decreases without reset
}

// Compassion: if n == 1 infinitely often then n == 2 infinitely often. Without resets n never
// decreases, so n == 1 infinitely often means n stays 1: such runs are unfair.
system Compassion {
  instance c: C;
  assume !c.reset;
  fair leave_one: c.n == 1 => c.n == 2;
  ltl past_one: G(c.n == 1 => F c.n == 2);  // proved under compassion
  ltl reaches2: F c.n >= 2;                  // violated: stuck at 0 is fair
}

// The same property without the compassion constraint.
system NoCompassion {
  instance c: C;
  assume !c.reset;
  ltl past_one: G(c.n == 1 => F c.n == 2);  // violated: inc once, then nothing
}

// `assume c.n < 2` (on the state before each tick) allows no input once n = 2: a deadlock,
// first reached by tick 0, inc, inc (3 ticks). Infinite runs never reach n = 2.
system Deadlock {
  instance c: C;
  assume c.n < 2;
  ltl never2: G c.n < 2;     // proved: only finite runs reach n = 2
  ltl reaches2: F c.n == 2;  // violated: n = 0 forever
}
