// fam_system.sc — master + 1 FAM on one LIN bus (App. A, C, D; ch. 6): the closed loop the
// thesis could not verify (ch. 5, 7). The system FamSystem is in lib/fam_system1.sc; this file
// chooses the corrected modulus and the processing budget.
import "lib/modulus.sc";
import "lib/fam_system1.sc";

const BUDGET: int = 10;    // ch. 5.4: controller steps between a response and the next request
