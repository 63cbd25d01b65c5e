chart C {
  input event Run;
  Stop;
  init Stop;
  Run -> Go;
  Go { }
  count: int = 0;
  [x > 0] -> Go;
  state Stop;
  state Go;
}
