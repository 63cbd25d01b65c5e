// bug_modulus.sc — master + 1 FAM with the thesis's modulus error in FAM and master (ch. 5.3,
// 5.4): the system FamSystem of fam_system.sc with lib/thesis_modulus.sc in place of
// lib/modulus.sc (position registers one value wider, 4096 not wrapped).
import "lib/thesis_modulus.sc";
import "lib/fam_system1.sc";

const BUDGET: int = 10;    // ch. 5.4: controller steps between a response and the next request
