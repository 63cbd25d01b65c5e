const A = 3 @ 4;
const B = "text";
chart C { # not a comment
  initial S; state S€;
}
