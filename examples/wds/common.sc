// The Workpiece Distribution Station (WDS): what every part shares.
// The parameter set is ours (README.md): the paper's figures are not in its text.

// One tick is 1.25 s: every cell of the 5 % grids (feeder.sc, transfer.sc) is crossed in a whole
// number of ticks at every speed.
tick 1250 ms;

// The workpiece token: what a buffer of size 1 holds (NONE: empty).
enum Wp { NONE, LIGHT, HEAVY }

// The Transfer's motion command.
enum Move { STOP, TO_STORAGE, TO_UNLOAD }
