// A parameter without a default must be given; a given one must have the parameter's type,
// lie in its range and be constant.
chart Counter(max: int[1..100], start: int = 0) {
    input event step;
    input limit: int[0..9];
    output n: int[0..max] = start;
    initial Run;
    state Run { on step [n < max] / { n = n + 1; } -> Run; }
}
chart User { output k: int[0..9] = 0; initial A; state A; }
system S {
    instance u: User;
    instance a: Counter;
    instance c: Counter(start = 1);
    instance d: Counter(300);
    instance e: Counter(true);
    instance f: Counter(u.k);
    instance g: Counter(3, start = 9);
}
