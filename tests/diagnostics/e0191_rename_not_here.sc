// E0191: renames belong to single chart instances, not to an instance array (every element
// would get the same names) nor to a component instance (it has no events of its own).
plant chart P {
  controllable event a;
  initial S;
  state S { on a -> S; }
}

component Pair {
  instance x: P { a -> ax; }
  instance y: P { a -> ay; }
}

system Renamed {
  instance ps[2]: P { a -> a1; }
  instance pair: Pair { a -> a2; }
}
