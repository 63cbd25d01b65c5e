// Targets resolve from the nearest enclosing scope; a state in another region needs its path.
chart C {
  input event go;
  initial Top;
  state Top {
    region left {
      initial A;
      state A { on go -> B; }
    }
    region right {
      initial B;
      state B { on go -> Idel; }
      state Idle;
    }
  }
}
