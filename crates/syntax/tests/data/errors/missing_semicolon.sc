chart C {
  local n: int[0..3] = 0
  initial S;
  state S { entry { n = 1 } on [n > 0] -> S }
  state T
  state U { history deep }
}
const A = 1
const B = 2;
