// E0190: an instance's rename block names something that is not one of the chart's
// synthesis events (`z`), or renames one event twice (`a`).
plant chart P {
  controllable event a;
  uncontrollable event b;
  initial S;
  state S { on a -> S; on b -> S; }
}

system Renamed {
  instance p: P { a -> a1; a -> a2; z -> z1; }
}
