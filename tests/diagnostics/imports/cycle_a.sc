import "cycle_b.sc";
chart A { initial S; state S; }
