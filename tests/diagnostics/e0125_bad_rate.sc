// `rate` names a free boolean input or input event, once, with a probability from 0 to 1.
chart Plant {
  input fault: bool = false;
  input event kick;
  input level: int[0..3] = 0;
  output ok: bool = true;
  initial run;
  state run { during { ok = !fault && level < 3; } on kick -> run; }
}
chart Source { output x: bool = false; initial s; state s; }
system S {
  instance p: Plant;
  instance src: Source;
  connect src.x -> p.fault;
  rate p.fault = 0.5;   // driven by a connection
  rate p.level = 0.1;   // an integer
  rate p.ok = 0.1;      // an output
  rate p.kick = 1.5;    // not a probability
  rate p.kick = 0.2;
  rate p.kick = 0.3;    // a second rate
}
