// W0308: unused declarations.
chart C {
  input event go;
  input unusedIn: int[0..3] = 0;
  input event unusedEv;
  output y: bool = false;
  output event done;
  local spare: int[0..3] = 0;
  local event ping;
  initial A;
  state A {
    on go -> B;
    on ping -> B;
  }
  state B {
    on go -> A;
  }
}
