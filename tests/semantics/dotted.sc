// §10: a dotted target is resolved as a whole, from the source outwards: the innermost level
// at which the whole path names a state wins. `X.Y` from Q: Q has no child X; Q's sibling X
// has no child Y, so it does not match; the chart's X has Y: the target is the top-level X.Y.
chart D {
  input event go;
  input event back;
  initial P;
  state P {
    initial Q;
    state Q { on go -> X.Y; on back -> X.Z; }
    state X { initial Z; state Z; }
  }
  state X { initial Z; state Z; state Y; on back -> P; }
}
