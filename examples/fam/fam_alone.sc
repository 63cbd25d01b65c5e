// fam_alone.sc — the FAM alone in a small environment: the FAM half of the thesis's table
// (ch. 5.3). See README: FamAloneSmall.
import "lib/modulus.sc";
import "lib/fam.sc";

const T_NEAR: int = 2049;
const T_FAR: int = 2052;
enum Fault { NONE, STALL, HSL_F, EPM_F, OTF_F, COF_F, FBF_F, CCF_F, POWER_LOSS, POWER_LOSS_NO_SAVE }
plant chart FamEnv {
  input fault: Fault = NONE;
  input far: bool = false;
  output targetPos: int[0..4095] = T_NEAR;
  output stallNow: bool = false;
  output hslFault: bool = false;
  output epmFault: bool = false;
  output otFault: bool = false;
  output cofNow: bool = false;
  output fbfFault: bool = false;
  output ccfFault: bool = false;
  output powerLoss: bool = false;
  output saveFails: bool = false;
  initial env;
  state env {
    during {
      targetPos = if far then T_FAR else T_NEAR;
      stallNow = fault == STALL;
      hslFault = fault == HSL_F;
      epmFault = fault == EPM_F;
      otFault = fault == OTF_F;
      cofNow = fault == COF_F;
      fbfFault = fault == FBF_F;
      ccfFault = fault == CCF_F;
      powerLoss = fault == POWER_LOSS || fault == POWER_LOSS_NO_SAVE;
      saveFails = fault == POWER_LOSS_NO_SAVE;
    }
  }
}
system FamAloneSmall {
  instance env: FamEnv;
  instance fam: Fam;
  connect env.targetPos -> fam.targetPos;
  connect env.stallNow -> fam.stallNow;
  connect env.hslFault -> fam.hslFault;
  connect env.epmFault -> fam.epmFault;
  connect env.otFault -> fam.otFault;
  connect env.cofNow -> fam.cofNow;
  connect env.fbfFault -> fam.fbfFault;
  connect env.ccfFault -> fam.ccfFault;
  connect env.powerLoss -> fam.powerLoss;
  connect env.saveFails -> fam.saveFails;
  order env, fam;
  assume env.fault == NONE || env.fault == STALL || env.fault == COF_F || (fam.failureReg & MAJOR) == 0;
  reachable fam_stall_running_possible:
    in(fam.stallHandler.stallMode) && in(fam.moveHandler.running);
  invariant fam_stall_blocks_run:
    !(in(fam.stallHandler.stallMode) && in(fam.moveHandler.running))
    assuming fam.runMode != FAILURE_RUN;
  reachable fam_failure_running_possible:
    in(fam.failureHandler.failure) && in(fam.moveHandler.running);
  invariant fam_failure_blocks_run:
    !(in(fam.failureHandler.failure) && in(fam.moveHandler.running))
    assuming fam.runMode != FAILURE_RUN;
  invariant fam_cof_with_notcalib:
    !(fam.notCalib && fam.failureReg == COF);
  invariant fam_actualpos_in_range:
    fam.actualPos >= 0 && fam.actualPos <= 4095;
}
