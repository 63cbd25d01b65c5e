// Slots and configurations: a connection to a port the slot's interface lacks or in the wrong
// direction (E0155), a chart that does not implement the interface or an instance given
// another chart (E0156), a slot left open (E0157), an unknown instance (E0101).
interface Source { output v: int[0..3]; }
chart Gen implements Source { output v: int[0..3] = 0; output w: bool = false; initial S; state S; }
chart Other { output v: int[0..3] = 0; initial S; state S; }
chart Sink { input v: int[0..3] = 0; input w: bool = false; initial S; state S; }
system Open {
  instance src: Source;
  instance dst: Sink;
  connect src.v -> dst.v;
}
system Wired {
  instance src: Source;
  instance dst: Sink;
  connect src.w -> dst.w;
  connect dst.v -> src.v;
  configuration good { src = Gen; }
  configuration wrong { src = Other; dst = Gen; }
  configuration empty { sink = Sink; }
}
