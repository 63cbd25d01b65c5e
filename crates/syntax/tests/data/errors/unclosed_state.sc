chart C {
  initial S;
  state S {
    entry { n = 1; }
    state Inner;
chart D { initial T; state T; }
