// cycle_a.sc and cycle_b.sc import each other: the cycle is reported in cycle_b.sc, where it
// closes.
import "imports/cycle_a.sc";
chart Main { initial S; state S; }
