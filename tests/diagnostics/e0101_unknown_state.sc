chart C {
  output busy: bool = false;
  initial Idle;
  state Idle;
  state Run {
    initial Fast;
    state Fast;
  }
  state Watch {
    during { busy = in(Run.Fats) || in(Stop); }
  }
}
