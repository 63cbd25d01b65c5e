// W0309: locals that are written but never read.
chart C {
  input event go;
  local count: int[0..100] = 0;
  local event beat;
  initial A;
  state A {
    entry { count = min(count + 1, 100); }
    on go / { raise beat; } -> B;
  }
  state B {
    on go -> A;
  }
}
