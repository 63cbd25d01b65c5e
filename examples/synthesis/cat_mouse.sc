// Cat and Mouse (Ramadge & Wonham 1989; Wonham's notes): five rooms joined by one-way doors,
// some only for the cat (c1..c7), some only for the mouse (m1..m6). Every door can be closed
// except c7, which the cat may use in both directions between rooms 1 and 3 (uncontrollable).
// The cat starts in room 2, the mouse in room 4; that configuration is the only marked one.
// Requirement: cat and mouse are never in the same room.
//
//   cat:   c1: 0->1  c2: 1->2  c3: 2->0  c4: 0->3  c5: 3->4  c6: 4->0  c7: 1<->3
//   mouse: m1: 0->2  m2: 2->1  m3: 1->0  m4: 0->4  m5: 4->3  m6: 3->0
//
// Known answer: the supervisor has 6 states (and 9 transitions): the mouse never leaves the
// 4->3->0->4 loop while the cat is home (2), and the cat roams rooms 0, 1, 3 only while the
// mouse stays in 4. From (cat 1 or 3, mouse 4) c7 is always possible, so the cat must
// not enter 4 (c5 disabled) and the mouse must not leave 4 (m5 disabled) while the cat is out.

plant chart Cat {
    controllable event c1;
    controllable event c2;
    controllable event c3;
    controllable event c4;
    controllable event c5;
    controllable event c6;
    uncontrollable event c7;
    initial R2;
    state R0 { on c1 -> R1; on c4 -> R3; }
    state R1 { on c2 -> R2; on c7 -> R3; }
    marked state R2 { on c3 -> R0; }
    state R3 { on c5 -> R4; on c7 -> R1; }
    state R4 { on c6 -> R0; }
}

plant chart Mouse {
    controllable event m1;
    controllable event m2;
    controllable event m3;
    controllable event m4;
    controllable event m5;
    controllable event m6;
    initial R4;
    state R0 { on m1 -> R2; on m4 -> R4; }
    state R1 { on m3 -> R0; }
    state R2 { on m2 -> R1; }
    state R3 { on m6 -> R0; }
    marked state R4 { on m5 -> R3; }
}

system CatMouse {
    instance cat: Cat;
    instance mouse: Mouse;
    requirement never (in(cat.R0) && in(mouse.R0));
    requirement never (in(cat.R1) && in(mouse.R1));
    requirement never (in(cat.R2) && in(mouse.R2));
    requirement never (in(cat.R3) && in(mouse.R3));
    requirement never (in(cat.R4) && in(mouse.R4));
}
