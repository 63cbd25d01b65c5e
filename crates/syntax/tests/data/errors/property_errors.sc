system S {
  invariant x > 3;
  reachable r in(c.Go);
  respond p: a => b;
  respond q: a b within 3;
  invariant fine: true;
}
