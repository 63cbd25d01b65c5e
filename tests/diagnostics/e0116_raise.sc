chart C {
  input event go;
  local n: int[0..9] = 0;
  initial A;
  state A {
    entry { raise go; raise n; }
  }
}
