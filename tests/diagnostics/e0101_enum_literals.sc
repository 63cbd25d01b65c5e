enum Color { RED, GREEN }
enum Light { RED, OFF }
chart C {
  local c: Color = Color.GREEN;
  local l: Light = Light.OFF;
  initial A;
  state A {
    entry { c = RED; l = Light.BLUE; }
  }
}
