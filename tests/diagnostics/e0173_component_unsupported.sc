// What a component cannot be or contain (E0173): an array of it, arguments, an observer
// inside, a port with an initial value.
chart Leaf {
  input event go;
  output done: bool = false;
  initial S;
  state S { on go / { done = true; }; }
}
component Unit {
  input event go;
  output done: bool = true;
  instance leaf: Leaf;
  connect go -> leaf.go;
  connect leaf.done -> done;
  observer Watch {
    initial Ok;
    state Ok;
    state error;
  }
}
system Line {
  instance units[2]: Unit;
  instance one: Unit(3);
}
