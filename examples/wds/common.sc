// The Workpiece Distribution Station (WDS): what every part shares.
// The parameter set is ours (README.md): the paper's figures are not in its text.

// One tick is 1.25 s: every cell crossing time of the grid below is a whole number of ticks.
tick 1250 ms;

// The workpiece token: what a buffer of size 1 holds (NONE: empty).
enum Wp { NONE, LIGHT, HEAVY }

// The Transfer's motion command.
enum Move { STOP, TO_STORAGE, TO_UNLOAD }

// The grid over every stroke 0..100 %: 20 cells of 5 %.
const CELL = 5;

// The time to cross one cell at `speed`, in 0.1 %/s, in milliseconds: 5 % / (speed / 10 %/s).
// Every speed used divides 50000 (README.md: 8, 20, 40, 5, 10), and `after` refuses a
// duration that is not a whole number of 1250 ms ticks.
fn cell_ms(speed: int[1..1000]) -> int[50..50000] = CELL * 10000 / speed;
