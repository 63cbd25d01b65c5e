// R5: what `in()` returns in the actions of a firing transition A -> B. The active child of
// the chart changes when B is entered: in A's exit action and in the transition action A
// still counts as active (and B not); in B's entry action B is active and A is not.
chart I {
  input event go;
  output a_exit: bool = false;
  output a_tr: bool = false;
  output b_tr: bool = false;
  output a_en: bool = false;
  output b_en: bool = false;
  initial A;
  state A { exit { a_exit = in(A); } on go / { a_tr = in(A); b_tr = in(B); } -> B; }
  state B { entry { a_en = in(A); b_en = in(B); } }
}
