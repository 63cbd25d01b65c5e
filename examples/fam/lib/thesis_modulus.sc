// lib/thesis_modulus.sc — the thesis's faulty modulus functions (ch. 5.3: actualPos = 4096;
// ch. 5.4: targetPos in 0..4096), in place of lib/modulus.sc: imported by bug_modulus.sc.
// The registers get the width the thesis's doubles had (one value wider), so that the
// properties, not the range checks, see the 4096.

const POS_TOP: int = 4096;   // BUG (bug_modulus): one value wider than 12 bits
const MOD_TOP: int = 8191;

// BUG (bug_modulus): 4096 stays 4096.
fn wrap12(p: int[-4096..8191]) -> int[0..MOD_TOP] = if p > 4096 then p - 4096 else if p < 0 then p + 4096 else p;

// BUG (bug_modulus): 4096 stays 4096.
fn mod12(p: int[-8192..8191]) -> int[0..MOD_TOP] = if p > 4096 then p - 4096 else if p < 0 then p + 4096 else p;
