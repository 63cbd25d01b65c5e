chart C {
  initial S;
  state S { history; initial A; state A; }
  state T { history full; initial B; state B; }
  state U { shallow; }
}
