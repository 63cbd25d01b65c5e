const in = 3;
chart state { }
chart C {
  local event: int;
  initial S;
  state choice;
  state S;
}
