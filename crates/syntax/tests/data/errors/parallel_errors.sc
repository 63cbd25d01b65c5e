chart C {
  parallel {
    region a { initial A; state A; }
    state B;
  }
  state S {
    parallel { region r { initial R; state R; } }
  }
}
