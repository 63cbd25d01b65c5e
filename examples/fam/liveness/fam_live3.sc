// The liveness properties of the FAM closed loop, master + 3 FAMs, stated for FAM 0
// (the FAMs are alike): the closed loop FamBus(3) of ../fam_system3.sc (lib/bus.sc) and the
// temporal properties of issue 16. Results: docs/case-studies/temporal.md.
import "../fam_system3.sc";

system FamLive3 {
  instance net: FamBus(3);

  // "Faults stop occurring": from some tick on, no fault input is raised (F G calm). Each
  // property assumes it in its formula (a persistence assumption, not a `fair` justice one).

  // After a stall the stall procedure completes: the FAM's stall flag is cleared (the master
  // acknowledges it with STOP_STALL, D.3.2.2).
  ltl stall_procedure_completes:
    F G net.env.fault == NONE
    => G(net.fam[0].stall => F !net.fam[0].stall);

  // After a failure is cleared (the master, waiting in the general solution, sees no failure
  // flag) the master recalibrates and returns to normal running with a calibrated FAM.
  ltl recalibrates_after_failure:
    F G net.env.fault == NONE
    => G((net.ctrl[0].phase == FAIL_WAIT && (net.ctrl[0].rFail & MAJOR) == 0)
         => F(net.ctrl[0].phase == NORMAL && !net.fam[0].notCalib));

  // The FAM reaches a commanded target: once faults stop and the CCM stays at one value, the
  // FAM's position eventually equals the master's target for good.
  ltl reaches_target:
    F G (net.env.fault == NONE && net.env.ccmSel == 1)
    => F G net.fam[0].actualPos == net.ctrl[0].targetPos;
}
