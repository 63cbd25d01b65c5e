// The liveness properties of the FAM closed loop, master + 5 FAMs, stated for FAM 0
// (the FAMs are alike): the closed loop FamBus(5) of ../fam_system5.sc (lib/bus.sc) and the
// temporal properties of issue 16. Results: docs/case-studies/temporal.md.
import "../fam_system5.sc";

// FAM 0 is within SPEED_HIGH positions past an end of the factory range and was moving
// outwards (fam_live.sc).
fn atEndStop(pos: int[0..4095], dir: bool) -> bool =
  (sdist(pos, E1F) < 0 && sdist(pos, E1F) >= -SPEED_HIGH && dir)
  || (sdist(pos, E1F) > RANGE && sdist(pos, E1F) <= RANGE + SPEED_HIGH && !dir);

system FamLive5 {
  instance net: FamBus(5);

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

  // The corrected statements (docs/case-studies/temporal.md, "Corrected formulas"; each one's
  // expected verdict and its reason: fam_live.sc). The three above are kept and stay
  // violated. With end stops: from some tick on the only fault is a stall of FAM 0 at an end
  // stop (atEndStop, below), and FAM 0 running outside the range infinitely often stalls
  // infinitely often.
  ltl stall_procedure_completes_unless_permanent:
    F G net.env.fault == NONE
    => G((net.fam[0].stall && net.ctrl[0].phase != HSL_PERM && net.ctrl[0].phase != FBF_PERM)
         => F(!net.fam[0].stall || net.ctrl[0].phase == HSL_PERM
              || net.ctrl[0].phase == FBF_PERM));

  ltl recalibrates_with_end_stops:
    (F G (net.env.fault == NONE
          || (net.env.fault == STALL && net.env.who == 0
              && atEndStop(net.fam[0].actualPos, net.fam[0].dir)))
     && (G F (net.fam[0].run && !inRange(net.fam[0].actualPos, E1F)) => G F net.fam[0].stall))
    => G((net.ctrl[0].phase == FAIL_WAIT && (net.ctrl[0].rFail & MAJOR) == 0)
         => F((net.ctrl[0].phase == NORMAL && !net.fam[0].notCalib)
              || net.ctrl[0].phase == HSL_PERM || net.ctrl[0].phase == FBF_PERM));

  ltl reaches_target_with_end_stops:
    (F G ((net.env.fault == NONE
           || (net.env.fault == STALL && net.env.who == 0
               && atEndStop(net.fam[0].actualPos, net.fam[0].dir)))
          && net.env.ccmSel == 1)
     && (G F (net.fam[0].run && !inRange(net.fam[0].actualPos, E1F)) => G F net.fam[0].stall))
    => F G net.fam[0].actualPos == net.ctrl[0].targetPos;
}
