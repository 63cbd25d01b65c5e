// Wonham's transfer line (Wonham, "Supervisory Control of Discrete-Event Systems", §4):
// machine M1 feeds buffer B1 (capacity 3), M2 takes from B1 and feeds B2 (capacity 1), the
// test unit TU takes from B2 and either accepts the part (it leaves) or rejects it back to B1.
// Starts are controllable; finishes, accept and reject are not.
//
// Known answer: the supremal controllable sublanguage for "B1 and B2 never overflow or
// underflow" has 28 states and 65 transitions (Wonham's TLSUP (28,65)). In words: M1 may
// start only while B1 + (M1 working) + (M2 working) + (TU working) + B2 < 3 +1 fits: every part
// in the loop M2 -> B2 -> TU -> B1 must find room in B1 on rejection.

plant chart M1 {
    controllable event s1;
    uncontrollable event f1;
    initial Idle;
    marked state Idle { on s1 -> Working; }
    state Working { on f1 -> Idle; }
}

plant chart M2 {
    controllable event s2;
    uncontrollable event f2;
    initial Idle;
    marked state Idle { on s2 -> Working; }
    state Working { on f2 -> Idle; }
}

plant chart TestUnit {
    controllable event s3;
    uncontrollable event accept;
    uncontrollable event reject;
    initial Idle;
    marked state Idle { on s3 -> Testing; }
    state Testing { on accept -> Idle; on reject -> Idle; }
}

// B1 holds 0..3 parts: M1's finish and TU's reject add one, M2's start takes one.
requirement chart B1 {
    uncontrollable event f1;
    uncontrollable event reject;
    controllable event s2;
    initial N0;
    marked state N0 { on f1 -> N1; on reject -> N1; }
    state N1 { on f1 -> N2; on reject -> N2; on s2 -> N0; }
    state N2 { on f1 -> N3; on reject -> N3; on s2 -> N1; }
    state N3 { on s2 -> N2; }
}

// B2 holds 0..1 parts: M2's finish adds one, TU's start takes it.
requirement chart B2 {
    uncontrollable event f2;
    controllable event s3;
    initial N0;
    marked state N0 { on f2 -> N1; }
    state N1 { on s3 -> N0; }
}

system TransferLine {
    instance m1: M1;
    instance m2: M2;
    instance tu: TestUnit;
    instance b1: B1;
    instance b2: B2;
}
