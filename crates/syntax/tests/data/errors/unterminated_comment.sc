const A = 1;
chart C { initial S; state S; }
/* this comment never ends
const B = 2;
