const A = ;
const B = 1 + ;
const C = * 3;
chart C {
  local n: int[0..3] = ;
  initial S;
  state S { entry { n = ; n = 1; } on [] -> S; }
}
