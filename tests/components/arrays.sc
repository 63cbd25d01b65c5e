// Arrays of variables, constant indices, `for` loops and element-wise connections
// (docs/language.md §5, §8, §14). `arrays_flat.sc` is the same system written with scalars by
// hand (`go[1]` is `go_1` there); both give the same verdicts, state counts and traces
// (crates/cli/tests/arrays.rs).
//
// By hand: in every tick after tick 0 the master runs first: it raises go[k] for the one slave
// `sel` when `req` holds, and counts the slaves busy in the previous tick (n). Then each slave
// steps: an idle slave with go[k] becomes busy, a busy one becomes idle. So slave k is busy
// after a tick iff go[k] was raised in it and k was idle before: at most one slave is busy,
// and n is 0 or 1. The states after tick >= 1, as (go, busy, n):
//   go none: busy none, n 0 or 1 (2 states);
//   go[k] (k = 0, 1, 2): busy k with n 0 or 1 (another slave busy before), or busy none with
//   n 1 (k itself was busy before): 3 states each, 9 in all;
// tick 0's state is (none, none, 0), already counted, and the state before tick 0 is one more:
// 2 + 9 + 1 = 12 states. `back_to_back` (n == 1 and slave 2 busy) is reachable in tick 2
// (go[0] in tick 1, go[2] in tick 2). The probes copy what they read (p[k].last is s[k].busy,
// q.last is go[1]) and add no state.

chart Slave {
  input go: bool = false;
  output busy: bool = false;
  initial Idle;
  state Idle { on [go] / { busy = true; } -> Work; }
  state Work { on [true] / { busy = false; } -> Idle; }
}

chart Master(N: int[1..4]) {
  input req: bool = false;
  input sel: int[0..N - 1] = 0;
  input b[N]: bool = false;   // gathered: slave k's busy
  output go[N]: bool = false; // scattered: slave k's go
  output n: int[0..N] = 0;
  initial Run;
  state Run {
    during {
      n = 0;
      for k in 0..N {
        go[k] = req && sel == k;
        if b[k] {
          n += 1;
        }
      }
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
  instance m: Master(3);
  instance s[3]: Slave;
  instance p[3]: Probe;
  instance q: Probe;
  connect m.go[*] -> s[*].go;     // scatter
  connect s[*].busy -> m.b[*];    // gather
  connect s[*].busy -> p[*].seen; // element by element
  connect m.go[1] -> q.seen;      // one element
  order m, s, p, q;
  invariant at_most_one: m.n <= 1;
  reachable two_busy: s[0].busy && s[1].busy;
  reachable back_to_back: m.n == 1 && s[2].busy;
  invariant probes_copy: p[1].last == s[1].busy && q.last == m.go[1];
}
