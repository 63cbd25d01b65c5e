// The probability of a `rate` is a decimal literal such as `0.01`.
chart Plant {
  input fault: bool = false;
  output ok: bool = true;
  initial run;
  state run { during { ok = !fault; } }
}
system S {
  instance p: Plant;
  rate p.fault = .01;
}
