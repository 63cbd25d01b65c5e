// Every declaration is used: inputs read (also by a property or a connection), outputs
// written, local events raised and consumed.
chart C {
  input event go;
  input limit: int[0..3] = 0;
  output y: bool = false;
  output event done;
  local event ping;
  initial A;
  state A {
    on go / { raise ping; };
    on ping -> B;
  }
  state B {
    entry { y = true; raise done; }
    on go -> A;
  }
  invariant small: limit <= 3;
}
chart D {
  input y: bool = false;
  output z: bool = false;
  initial S;
  state S { during { z = y; } }
}
system Sys {
  instance c: C;
  instance d: D;
  connect c.y -> d.y;
  invariant z_follows: d.z || !d.z;
}
