// Execution order: a connected input sees the value written earlier in the same tick, or the
// previous tick's value when its writer runs later.
chart Src {
  input event go;
  output n: int[0..10] = 0;
  initial S;
  state S { on go / { n += 1; }; }
}
chart Dst {
  input m: int[0..10] = 0;
  output seen: int[0..10] = 0;
  initial S;
  state S { during { seen = m; } }
}
system Early { instance a: Src; instance b: Dst; connect a.n -> b.m; order a, b; }
system Late { instance a: Src; instance b: Dst; connect a.n -> b.m; order b, a; }
