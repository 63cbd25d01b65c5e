// bug_short_timeout.sc — master + 1 FAM with a processing budget of 5 steps (ch. 5.4): the
// system FamSystem of fam_system.sc with a shorter scheduler timeout.
import "lib/modulus.sc";
import "lib/fam_system1.sc";

const BUDGET: int = 5;     // BUG (bug_short_timeout): was 10
