// R8: shallow history resumes the remembered child with its own default entry; deep history
// resumes the whole remembered configuration.
chart Hist {
  input event toS;
  input event toD;
  input event back;
  input event next;
  input event inner;
  initial Off;
  state Off { on toS -> S; on toD -> D; }
  state S {
    history shallow;
    initial S1;
    on back -> Off;
    state S1 { on next -> S2; }
    state S2 { initial a; state a { on inner -> b; } state b; }
  }
  state D {
    history deep;
    initial D1;
    on back -> Off;
    state D1 { on next -> D2; }
    state D2 { initial a; state a { on inner -> b; } state b; }
  }
}
