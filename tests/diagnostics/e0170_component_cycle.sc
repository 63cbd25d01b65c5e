// A component that contains itself through another (E0170): the flattening would not end.
chart Leaf {
  input event go;
  initial S;
  state S;
}
component Outer {
  input event go;
  instance inner: Inner;
  connect go -> inner.go;
}
component Inner {
  input event go;
  instance leaf: Leaf;
  instance again: Outer;
  connect go -> leaf.go;
}
system Top {
  instance o: Outer;
}
