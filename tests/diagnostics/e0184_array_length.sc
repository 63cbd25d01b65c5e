// E0184: an array's length must be a constant within 1..4096.
const K: int = 0;
chart Bad(N: int[1..4]) {
  input x: int[0..3] = 0;
  output a[K]: bool = false;      // length 0
  output b[x]: bool = false;      // not a constant
  output c[N + 1]: bool = false;  // a parameter is fine
  initial S;
  state S;
}
system Sys {
  instance b: Bad(2);
}
interface I {
  input v[2]: int[0..3];          // a port is one variable
}
component Comp {
  output w[2]: bool;              // a port is one variable
  instance b: Bad(1);
  connect b.c[0] -> w;
}
