const T1: bool = false;
const T2: int = -1;
const T3: int[-4096..8191] = 0;
const T4: int[0..N_MAX * 2] = 0;
const T5: Mode = Mode.Idle;
fn f(a: bool, b: int, c: int[0..3], d: Mode) -> int[-1..1] = 0;
