import "cycle_a.sc";
chart B { initial S; state S; }
