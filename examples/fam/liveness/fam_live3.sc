// The liveness properties of the FAM closed loop, master + 3 FAMs, stated for FAM 0
// (the FAMs are alike): the system of fam_system3.sc and the temporal properties of
// issue 16. Results: docs/case-studies/temporal.md.
import "../fam_system3.sc";

system FamLive3 {
  instance bus: MasterBus3;
  instance port[3]: FamPort;
  instance fam[3]: Fam(FAM_START);
  instance sbus: SlaveBus3;
  instance ctrl[3]: Controller;
  instance tie: Tie;
  instance env: Env3;
  connect bus.hIdent -> port[*].hIdent;
  connect bus.hB1 -> port[*].hB1;
  connect bus.hB2 -> port[*].hB2;
  connect bus.hCk -> port[*].hCk;
  connect bus.rspSel -> ctrl[*].rspSel;
  connect bus.proc -> ctrl[*].proc;
  connect sbus.sB1 -> ctrl[*].sB1;
  connect sbus.sB2 -> ctrl[*].sB2;
  connect sbus.sB5 -> ctrl[*].sB5;
  connect sbus.sCk -> ctrl[*].sCk;
  connect tie.low -> fam[*].saveFails;
  connect port[0].runMode -> fam[0].runMode;
  connect port[0].swap -> fam[0].swap;
  connect port[0].targetPos -> fam[0].targetPos;
  connect port[0].cofNow -> fam[0].cofNow;
  connect fam[0].notCalib -> port[0].notCalib;
  connect fam[0].stall -> port[0].stall;
  connect fam[0].dir -> port[0].dir;
  connect fam[0].run -> port[0].run;
  connect fam[0].actualPos -> port[0].actualPos;
  connect fam[0].failureReg -> port[0].failureReg;
  connect port[0].rB1 -> sbus.rB10;
  connect port[0].rB2 -> sbus.rB20;
  connect port[0].rB5 -> sbus.rB50;
  connect port[0].rCk -> sbus.rCk0;
  connect ctrl[0].runMode -> bus.rm0;
  connect ctrl[0].swap -> bus.sw0;
  connect ctrl[0].targetPos -> bus.tp0;
  connect tie.k0 -> port[0].sna;
  connect tie.k0 -> ctrl[0].myId;
  connect port[1].runMode -> fam[1].runMode;
  connect port[1].swap -> fam[1].swap;
  connect port[1].targetPos -> fam[1].targetPos;
  connect port[1].cofNow -> fam[1].cofNow;
  connect fam[1].notCalib -> port[1].notCalib;
  connect fam[1].stall -> port[1].stall;
  connect fam[1].dir -> port[1].dir;
  connect fam[1].run -> port[1].run;
  connect fam[1].actualPos -> port[1].actualPos;
  connect fam[1].failureReg -> port[1].failureReg;
  connect port[1].rB1 -> sbus.rB11;
  connect port[1].rB2 -> sbus.rB21;
  connect port[1].rB5 -> sbus.rB51;
  connect port[1].rCk -> sbus.rCk1;
  connect ctrl[1].runMode -> bus.rm1;
  connect ctrl[1].swap -> bus.sw1;
  connect ctrl[1].targetPos -> bus.tp1;
  connect tie.k1 -> port[1].sna;
  connect tie.k1 -> ctrl[1].myId;
  connect port[2].runMode -> fam[2].runMode;
  connect port[2].swap -> fam[2].swap;
  connect port[2].targetPos -> fam[2].targetPos;
  connect port[2].cofNow -> fam[2].cofNow;
  connect fam[2].notCalib -> port[2].notCalib;
  connect fam[2].stall -> port[2].stall;
  connect fam[2].dir -> port[2].dir;
  connect fam[2].run -> port[2].run;
  connect fam[2].actualPos -> port[2].actualPos;
  connect fam[2].failureReg -> port[2].failureReg;
  connect port[2].rB1 -> sbus.rB12;
  connect port[2].rB2 -> sbus.rB22;
  connect port[2].rB5 -> sbus.rB52;
  connect port[2].rCk -> sbus.rCk2;
  connect ctrl[2].runMode -> bus.rm2;
  connect ctrl[2].swap -> bus.sw2;
  connect ctrl[2].targetPos -> bus.tp2;
  connect tie.k2 -> port[2].sna;
  connect tie.k2 -> ctrl[2].myId;
  connect env.stallNow0 -> fam[0].stallNow;
  connect env.hslFault0 -> fam[0].hslFault;
  connect env.epmFault0 -> fam[0].epmFault;
  connect env.otFault0 -> fam[0].otFault;
  connect env.fbfFault0 -> fam[0].fbfFault;
  connect env.ccfFault0 -> fam[0].ccfFault;
  connect env.powerLoss0 -> fam[0].powerLoss;
  connect env.ccm -> ctrl[0].ccm;
  connect env.rspCorrupt0 -> ctrl[0].corrupt;
  connect env.stallNow1 -> fam[1].stallNow;
  connect env.hslFault1 -> fam[1].hslFault;
  connect env.epmFault1 -> fam[1].epmFault;
  connect env.otFault1 -> fam[1].otFault;
  connect env.fbfFault1 -> fam[1].fbfFault;
  connect env.ccfFault1 -> fam[1].ccfFault;
  connect env.powerLoss1 -> fam[1].powerLoss;
  connect env.ccm -> ctrl[1].ccm;
  connect env.rspCorrupt1 -> ctrl[1].corrupt;
  connect env.stallNow2 -> fam[2].stallNow;
  connect env.hslFault2 -> fam[2].hslFault;
  connect env.epmFault2 -> fam[2].epmFault;
  connect env.otFault2 -> fam[2].otFault;
  connect env.fbfFault2 -> fam[2].fbfFault;
  connect env.ccfFault2 -> fam[2].ccfFault;
  connect env.powerLoss2 -> fam[2].powerLoss;
  connect env.ccm -> ctrl[2].ccm;
  connect env.rspCorrupt2 -> ctrl[2].corrupt;
  connect env.reqCorrupt -> bus.corrupt;
  order env, tie, bus, port, fam, sbus, ctrl;

  // "Faults stop occurring": from some tick on, no fault input is raised (F G calm). Each
  // property assumes it in its formula (a persistence assumption, not a `fair` justice one).

  // After a stall the stall procedure completes: the FAM's stall flag is cleared (the master
  // acknowledges it with STOP_STALL, D.3.2.2).
  ltl stall_procedure_completes:
    F G env.fault == NONE
    => G(fam[0].stall => F !fam[0].stall);

  // After a failure is cleared (the master, waiting in the general solution, sees no failure
  // flag) the master recalibrates and returns to normal running with a calibrated FAM.
  ltl recalibrates_after_failure:
    F G env.fault == NONE
    => G((ctrl[0].phase == FAIL_WAIT && (ctrl[0].rFail & MAJOR) == 0)
         => F(ctrl[0].phase == NORMAL && !fam[0].notCalib));

  // The FAM reaches a commanded target: once faults stop and the CCM stays at one value, the
  // FAM's position eventually equals the master's target for good.
  ltl reaches_target:
    F G (env.fault == NONE && env.ccmSel == 1)
    => F G fam[0].actualPos == ctrl[0].targetPos;
}
