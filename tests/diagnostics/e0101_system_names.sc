chart Sensor {
  output value: int[0..10] = 0;
  initial A;
  state A;
}
chart Filter {
  input raw: int[0..10] = 0;
  initial A;
  state A;
}
system S {
  instance s: Sensor;
  instance f: Filtr;
  instance g: Filter;
  instance arr[3]: Filter;
  connect sen.value -> g.raw;
  connect s.valeu -> g.raw;
  connect s.value -> arr.raw;
  order s, g, arr, x;
  invariant i1: s.value < 5 || arr[1].raw == 0;
  invariant i2: s[0].value == 0;
  invariant i3: arr.raw == 0;
  invariant i4: arr[*].raw == 0;
  invariant i5: s.A;
  invariant i6: in(s.B);
}
