// Wonham's Small Factory (Wonham, "Supervisory Control of Discrete-Event Systems", §3).
// Two machines in series with a one-slot buffer between them. A machine starts (controllable),
// finishes or breaks down (uncontrollable), and is repaired (controllable). Requirement: the
// buffer neither overflows (M1 finishing into a full buffer) nor underflows (M2 starting on
// an empty one).
//
// Known answer: the product MACH1 x MACH2 x BUF has 3*3*2 = 18 states; the supremal
// controllable sublanguage is recognised by a 12-state, 24-transition supervisor:
// M1 may only start while the buffer is empty, so (M1 working, buffer full) and
// (M1 down, buffer full) are never reached: 18 - 3 - 3 = 12 states.

plant chart Machine1 {
    controllable event start1;
    uncontrollable event finish1;
    uncontrollable event break1;
    controllable event repair1;
    initial Idle;
    marked state Idle { on start1 -> Working; }
    state Working { on finish1 -> Idle; on break1 -> Down; }
    state Down { on repair1 -> Idle; }
}

plant chart Machine2 {
    controllable event start2;
    uncontrollable event finish2;
    uncontrollable event break2;
    controllable event repair2;
    initial Idle;
    marked state Idle { on start2 -> Working; }
    state Working { on finish2 -> Idle; on break2 -> Down; }
    state Down { on repair2 -> Idle; }
}

// M1's finish puts a part into the buffer, M2's start takes it.
requirement chart Buffer {
    uncontrollable event finish1;
    controllable event start2;
    initial Empty;
    marked state Empty { on finish1 -> Full; }
    state Full { on start2 -> Empty; }
}

system SmallFactory {
    instance m1: Machine1;
    instance m2: Machine2;
    instance buf: Buffer;
}

// The same factory with Wonham's second requirement: when both machines are down, M2 is
// repaired first (repair1 needs M2 not down).
system SmallFactoryRepair {
    instance m1: Machine1;
    instance m2: Machine2;
    instance buf: Buffer;
    requirement repair1 needs (!in(m2.Down));
}
