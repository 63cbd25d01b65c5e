// A lamp for the drawing tests (crates/cli/tests/dot.rs): a timer written in seconds, a long
// guard, an action, and an observer whose `error` state is meant never to be entered.
tick 100 ms;

chart Lamp {
  input event press;
  input enabled: bool = false;
  output count: int[0..3] = 0;
  initial Off;
  state Off {
    on press [enabled && count < 3 && count >= 0 && enabled] / { count += 1; } -> On;
  }
  state On {
    on after(3 s) -> Off;
  }
}

system Lit {
  instance lamp: Lamp;
  observer bounded {
    initial watch;
    state watch { on [in(lamp.On) && lamp.count == 0] -> error; }   // On is entered with count >= 1
    state error;
  }
}
