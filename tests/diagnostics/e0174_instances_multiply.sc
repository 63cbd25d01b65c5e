// E0174: 2 instances per component over 30 levels: C0 holds 2 charts, Ck holds 2^(k+1), so
// Top flattens to 2^30 = 1073741824 chart instances: refused at once, with the count, before
// any flattening. (C12..C29 are too big to run alone and are not; in a file with a system
// only the system is reported.)

chart Leaf {
  input a: bool = false;
  output b: bool = false;
  initial S;
  state S { during { b = a; } }
}

component C0 {
  input a: bool;
  output b: bool;
  instance x: Leaf;
  instance y: Leaf;
  connect a -> x.a;
  connect x.b -> y.a;
  connect y.b -> b;
}

component C1 { input a: bool; output b: bool; instance x: C0; instance y: C0; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C2 { input a: bool; output b: bool; instance x: C1; instance y: C1; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C3 { input a: bool; output b: bool; instance x: C2; instance y: C2; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C4 { input a: bool; output b: bool; instance x: C3; instance y: C3; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C5 { input a: bool; output b: bool; instance x: C4; instance y: C4; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C6 { input a: bool; output b: bool; instance x: C5; instance y: C5; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C7 { input a: bool; output b: bool; instance x: C6; instance y: C6; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C8 { input a: bool; output b: bool; instance x: C7; instance y: C7; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C9 { input a: bool; output b: bool; instance x: C8; instance y: C8; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C10 { input a: bool; output b: bool; instance x: C9; instance y: C9; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C11 { input a: bool; output b: bool; instance x: C10; instance y: C10; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C12 { input a: bool; output b: bool; instance x: C11; instance y: C11; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C13 { input a: bool; output b: bool; instance x: C12; instance y: C12; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C14 { input a: bool; output b: bool; instance x: C13; instance y: C13; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C15 { input a: bool; output b: bool; instance x: C14; instance y: C14; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C16 { input a: bool; output b: bool; instance x: C15; instance y: C15; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C17 { input a: bool; output b: bool; instance x: C16; instance y: C16; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C18 { input a: bool; output b: bool; instance x: C17; instance y: C17; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C19 { input a: bool; output b: bool; instance x: C18; instance y: C18; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C20 { input a: bool; output b: bool; instance x: C19; instance y: C19; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C21 { input a: bool; output b: bool; instance x: C20; instance y: C20; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C22 { input a: bool; output b: bool; instance x: C21; instance y: C21; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C23 { input a: bool; output b: bool; instance x: C22; instance y: C22; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C24 { input a: bool; output b: bool; instance x: C23; instance y: C23; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C25 { input a: bool; output b: bool; instance x: C24; instance y: C24; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C26 { input a: bool; output b: bool; instance x: C25; instance y: C25; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C27 { input a: bool; output b: bool; instance x: C26; instance y: C26; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C28 { input a: bool; output b: bool; instance x: C27; instance y: C27; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }
component C29 { input a: bool; output b: bool; instance x: C28; instance y: C28; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }

system Top {
  instance t: C29;
  invariant ok: true;
}
