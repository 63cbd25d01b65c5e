// R3, R4, R6: regions run in declaration order; a raised local event is present in the next
// tick only; a transition that leaves the parallel state stops its later regions.
chart Par {
  input event go;
  input event leave;
  local event ping;
  local log: int[0..999999999] = 0;
  during { log = 0; }
  initial P;
  state P {
    region r1 {
      initial X;
      state X { on go / { log = log * 10 + 1; raise ping; } -> Y; }
      state Y { on leave / { log = log * 10 + 2; } -> Q; }
    }
    region r2 {
      initial U;
      state U {
        during { log = log * 10 + 3; }
        on ping / { log = log * 10 + 4; } -> V;
      }
      state V { during { log = log * 10 + 5; } }
    }
  }
  state Q { entry { log = log * 10 + 6; } }
}
