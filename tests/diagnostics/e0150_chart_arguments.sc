// Arguments a chart does not take: one too many, an unknown name, a parameter given twice,
// and arguments to a chart without parameters.
chart Counter(max: int[1..100], start: int = 0) {
    input event step;
    output n: int[0..max] = start;
    initial Run;
    state Run { on step [n < max] / { n = n + 1; } -> Run; }
}
chart Plain { initial A; state A; }
system S {
    instance b: Counter(3, 0, 5);
    instance c: Counter(3, strt = 1);
    instance h: Counter(3, max = 4);
    instance g: Plain(1);
}
