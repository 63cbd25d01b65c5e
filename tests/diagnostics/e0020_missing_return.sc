fn twice(x: int[0..9]) -> int[0..18] {
  let y = x * 2;
}
chart C {
  initial A;
  state A;
}
