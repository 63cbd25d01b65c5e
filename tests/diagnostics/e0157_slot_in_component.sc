// Configurations binding slots inside component instances by path: a chart that does not
// implement the slot's interface (E0156, so the slot stays open: E0157), a path that names no
// instance (E0101), a chart instance that is not a slot (E0156), a component for a slot inside
// a component (E0173).
interface Presence {
  input pos: int[0..3];
  output hit: bool;
}

chart Sensor implements Presence {
  input pos: int[0..3] = 0;
  output hit: bool = false;
  initial S;
  state S { during { hit = pos == 3; } }
}

chart Other {
  input pos: int[0..3] = 0;
  output hit: bool = false;
  initial S;
  state S;
}

chart Src {
  output pos: int[0..3] = 0;
  initial S;
  state S;
}

component Box {
  output hit: bool;
  instance src: Src;
  instance s: Presence;
  connect src.pos -> s.pos;
  connect s.hit -> hit;
}

component Big {
  output hit: bool;
  instance b: Box;
  connect b.hit -> hit;
}

system Top {
  instance big: Big;
  configuration a {
    big.b.s = Other;
  }
  configuration b {
    big.b.x = Sensor;
  }
  configuration c {
    big.b.src = Sensor;
  }
  configuration d {
    big.b.s = Big;
  }
}
