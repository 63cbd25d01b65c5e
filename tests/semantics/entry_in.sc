// R5: `in()` of a composite's children inside the composite's own entry action reads the
// composite's active-child slot before the child is chosen. Without history the slot is reset
// to the `initial` child when the composite is left, so there it is always the initial child;
// with history it is the remembered child. It names the child about to be entered only when
// the entry is a default one (initial or history), not when a transition targets another
// child directly (`-> P.P2`, `-> H.H1` below).
chart E {
  input event go2;
  input event toH;
  input event toH1;
  input event next;
  input event back;
  output p1_en: bool = false;
  output p2_en: bool = false;
  output h1_en: bool = false;
  output h2_en: bool = false;
  initial Off;
  state Off { on go2 -> P.P2; on toH -> H; on toH1 -> H.H1; }
  state P {
    initial P1;
    entry { p1_en = in(P.P1); p2_en = in(P.P2); }
    on back -> Off;
    state P2 { }
    state P1 { }
  }
  state H {
    history shallow;
    initial H1;
    entry { h1_en = in(H.H1); h2_en = in(H.H2); }
    on back -> Off;
    state H1 { on next -> H2; }
    state H2 { }
  }
}
