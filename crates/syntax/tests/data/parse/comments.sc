/* leading block comment
   spanning lines */
// line comment
const /* inline */ A /**/ = // trailing
  1 /* between */ + 2; // end
/***/ chart C { /* empty */ initial S; state S; // done
}
// final comment without newline
