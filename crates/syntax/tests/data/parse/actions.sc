chart Actions {
  output event done;
  local n: int[0..100] = 0;
  local m: int[-5..5] = 0;
  initial S;
  state S {
    entry {
      n = 0;
      n += 1;
      m -= 2 * n;
      raise done;
      if n > 3 { n = 3; }
      if n > 3 { n = 3; } else { n = 0; }
      if n == 0 { m = 1; } else if n == 1 { m = 2; } else if n == 2 { m = 3; } else { m = 4; }
      if in(S) { if m < 0 { m = 0; } }
      m = if n > 0 then 1 else -1;
    }
    entry { }
  }
}
