// R7: a transition whose choice has no valid branch does not fire (the next one is tried);
// branch guards see the values from before the transition's action.
chart Choice {
  input x: int[0..10] = 0;
  local v: int[0..10] = 0;
  initial A;
  state A {
    on [true] / { v = 5; } -> choice { [v == 5] -> B; [x > 5] -> C; };
    on [x == 0] -> D;
  }
  state B;
  state C;
  state D { on [x == 9] -> A; }
}
