// lib/modulus.sc — position arithmetic modulo 4096, corrected (thesis ch. 5.3, 5.4), for the
// FAM (wrap12, lib/fam.sc) and the master (mod12, Eq. D.1, lib/master.sc). Import it before
// those files; lib/thesis_modulus.sc is the thesis's faulty version (bug_modulus.sc).

const POS_TOP: int = 4095;   // the largest value of a 12-bit position register (actualPos, targetPos)
const MOD_TOP: int = 4095;   // the largest value the modulus functions return

// Position arithmetic modulo 4096. The thesis's own modulus function returned 4096 (ch. 5.3,
// the actualPos range test): this is the corrected one.
fn wrap12(p: int[-4096..8191]) -> int[0..MOD_TOP] = (p + 4096) % 4096;

// Eq. D.1 with the 12-bit modulus (the thesis prints "mod 4095"; positions are 0..4095).
fn mod12(p: int[-8192..8191]) -> int[0..MOD_TOP] = (p + 8192) % 4096;
