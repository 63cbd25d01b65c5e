chart C { initial S;
  state S { state S { state S { state S { on go -> S; } } } }
  state T { entry { if a { if b { if c { x = 1; } else if d { x = 2; } } } } }
}
