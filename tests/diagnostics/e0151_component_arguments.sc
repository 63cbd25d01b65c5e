// Arguments of parameterised components are bound like a chart's: missing (E0151), extra
// or unknown (E0150), out of range (E0104); arguments to a component without parameters
// (E0150). Arrays of components are indexed by an integer literal within range (E0176).

chart Counter(max: int[1..3]) {
  input event step;
  output n: int[0..3] = 0;
  initial Run;
  state Run { on step [n < max] / { n = n + 1; }; }
}

component Pair(m: int[1..3]) {
  input event step;
  instance hi: Counter(m);
  connect step -> hi.step;
}

component Plain {
  input event step;
  instance c: Counter(1);
  connect step -> c.step;
}

system Bad {
  instance a: Pair;
  instance b: Pair(1, 2);
  instance c: Pair(k = 1);
  instance d: Pair(4);
  instance e: Plain(1);
  instance cells[2]: Pair(2);
  reachable no_index: cells.hi.n == 1;
  reachable out_of_range: cells[2].hi.n == 1;
  reachable all: cells[*].hi.n == 1;
}
