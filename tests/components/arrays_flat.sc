// arrays.sc written with scalars by hand: the arrays' elements `go[k]`, `b[k]` are `go_k`,
// `b_k`, the loop unrolled for N = 3, and each element-wise connection written out.

chart Slave {
  input go: bool = false;
  output busy: bool = false;
  initial Idle;
  state Idle { on [go] / { busy = true; } -> Work; }
  state Work { on [true] / { busy = false; } -> Idle; }
}

chart Master3 {
  input req: bool = false;
  input sel: int[0..2] = 0;
  input b_0: bool = false;
  input b_1: bool = false;
  input b_2: bool = false;
  output go_0: bool = false;
  output go_1: bool = false;
  output go_2: bool = false;
  output n: int[0..3] = 0;
  initial Run;
  state Run {
    during {
      n = 0;
      go_0 = req && sel == 0;
      if b_0 { n += 1; }
      go_1 = req && sel == 1;
      if b_1 { n += 1; }
      go_2 = req && sel == 2;
      if b_2 { n += 1; }
    }
  }
}

chart Probe {
  input seen: bool = false;
  output last: bool = false;
  initial S;
  state S { during { last = seen; } }
}

system Bus {
  instance m: Master3;
  instance s[3]: Slave;
  instance p[3]: Probe;
  instance q: Probe;
  connect m.go_0 -> s[0].go;
  connect m.go_1 -> s[1].go;
  connect m.go_2 -> s[2].go;
  connect s[0].busy -> m.b_0;
  connect s[1].busy -> m.b_1;
  connect s[2].busy -> m.b_2;
  connect s[0].busy -> p[0].seen;
  connect s[1].busy -> p[1].seen;
  connect s[2].busy -> p[2].seen;
  connect m.go_1 -> q.seen;
  order m, s, p, q;
  invariant at_most_one: m.n <= 1;
  reachable two_busy: s[0].busy && s[1].busy;
  reachable back_to_back: m.n == 1 && s[2].busy;
  invariant probes_copy: p[1].last == s[1].busy && q.last == m.go_1;
}
