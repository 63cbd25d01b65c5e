chart C {
  local x: int[0..9] = 0;
  initial A;
  state A {
    on [x > 1] -> Bee;
    on [x > 2] -> B[1];
    on [x > 3] -> choice {
      else -> A;
      [x > 5] -> B;
    };
    on [x > 4] -> choice { };
  }
  state B;
}
chart D {
  initial A;
  junction j { }
  state A { on -> j; }
}
