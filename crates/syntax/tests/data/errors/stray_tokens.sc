}
state S;
const A = 1;
observer O { }
instance c: C;
x = 3;
chart C { initial S; state S; } }
const B = 2;
