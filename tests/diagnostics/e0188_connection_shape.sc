// E0188: element-wise connections need arrays of the same length, and one `[*]` per endpoint.
chart Src {
  output o[3]: bool = false;
  output one: bool = false;
  initial S;
  state S;
}
chart Dst {
  input i[2]: bool = false;
  input x: bool = false;
  initial S;
  state S;
}
system Sys {
  instance s: Src;
  instance d[2]: Dst;
  instance e: Dst;
  connect s.o[*] -> e.i[*];         // 3 elements to 2
  connect s.one -> d[*].i[*];       // two `[*]` in one endpoint
}
