// Dining philosophers with 5 forks, written with ONE philosopher chart and ONE fork chart:
// each instance renames the chart's events to its own (docs/synthesis.md, "Event renaming").
// The same automata as the generated philosophers_5.sc (ten copied charts), so the same
// answer: supervisor 81 states, 260 transitions (crates/synth/tests/renames.rs checks both
// files give it).
// Philosopher i takes fork i with `take{i}l` (left), then fork i+1 with `take{i}r` (right),
// eats, and puts both down with `put{i}`.

plant chart Phil {
  controllable event take_left;
  controllable event take_right;
  uncontrollable event put;
  initial Thinking;
  marked state Thinking { on take_left -> HasLeft; }
  state HasLeft { on take_right -> Eating; }
  state Eating { on put -> Thinking; }
}

// Fork i: taken by philosopher i as its left fork or by philosopher i-1 as its right one.
plant chart Fork {
  controllable event by_left;
  controllable event by_right;
  uncontrollable event put_left;
  uncontrollable event put_right;
  initial Free;
  marked state Free { on by_left -> Left; on by_right -> Right; }
  state Left { on put_left -> Free; }
  state Right { on put_right -> Free; }
}

system Philosophers5 {
  instance p0: Phil { take_left -> take0l; take_right -> take0r; put -> put0; }
  instance f0: Fork { by_left -> take0l; by_right -> take4r; put_left -> put0; put_right -> put4; }
  instance p1: Phil { take_left -> take1l; take_right -> take1r; put -> put1; }
  instance f1: Fork { by_left -> take1l; by_right -> take0r; put_left -> put1; put_right -> put0; }
  instance p2: Phil { take_left -> take2l; take_right -> take2r; put -> put2; }
  instance f2: Fork { by_left -> take2l; by_right -> take1r; put_left -> put2; put_right -> put1; }
  instance p3: Phil { take_left -> take3l; take_right -> take3r; put -> put3; }
  instance f3: Fork { by_left -> take3l; by_right -> take2r; put_left -> put3; put_right -> put2; }
  instance p4: Phil { take_left -> take4l; take_right -> take4r; put -> put4; }
  instance f4: Fork { by_left -> take4l; by_right -> take3r; put_left -> put4; put_right -> put3; }
}
