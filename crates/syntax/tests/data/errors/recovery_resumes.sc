// After a malformed element, parsing resumes at the next one.
chart C {
  initial A;
  state A B { on go -> A; }
  state Good1;
  state 3 { }
  state Good2;
  on after 3 / { n = 1; } -> A;
  state Good3;
}
