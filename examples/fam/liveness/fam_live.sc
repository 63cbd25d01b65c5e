// The liveness properties of the FAM closed loop, master + 1 FAM: the system of
// fam_system.sc and the temporal properties of issue 16. Verdicts and their
// justification: docs/case-studies/temporal.md.
import "../fam_system.sc";

// No fault input is raised in this tick.
fn calm(stall: bool, hsl: bool, epm: bool, fbf: bool, req: bool, rsp: bool) -> bool =
  !(stall || hsl || epm || fbf || req || rsp);

system FamLive {
  instance tie: Tie;
  instance bus: MasterBus(1);
  instance port: FamPort;
  instance fam: Fam(FAM_START);   // closed loop: starts at its saved position
  instance ctrl: Controller;
  connect bus.hIdent -> port.hIdent;
  connect bus.hB1 -> port.hB1;
  connect bus.hB2 -> port.hB2;
  connect bus.hCk -> port.hCk;
  connect port.runMode -> fam.runMode;
  connect port.swap -> fam.swap;
  connect port.targetPos -> fam.targetPos;
  connect port.cofNow -> fam.cofNow;
  connect fam.notCalib -> port.notCalib;
  connect fam.stall -> port.stall;
  connect fam.dir -> port.dir;
  connect fam.run -> port.run;
  connect fam.actualPos -> port.actualPos;
  connect fam.failureReg -> port.failureReg;
  connect port.rB1 -> ctrl.sB1;
  connect port.rB2 -> ctrl.sB2;
  connect port.rB5 -> ctrl.sB5;
  connect port.rCk -> ctrl.sCk;
  connect bus.rspSel -> ctrl.rspSel;
  connect bus.proc -> ctrl.proc;
  connect ctrl.runMode -> bus.rm[0];
  connect ctrl.swap -> bus.sw[0];
  connect ctrl.targetPos -> bus.tp[0];
  connect tie.low -> fam.saveFails;
  connect tie.low -> fam.otFault;
  connect tie.low -> fam.ccfFault;
  connect tie.low -> fam.powerLoss;
  order tie, bus, port, fam, ctrl;

  connect tie.k[0] -> port.sna;
  connect tie.k[0] -> ctrl.myId;
  assume ctrl.ccm == 0 || ctrl.ccm == 500 || ctrl.ccm == 1000;
  // (written out as a sum; a call of a declared fn would be solved up front just the same)
  assume b(fam.stallNow) + b(fam.hslFault) + b(fam.epmFault) + b(fam.fbfFault)
         + b(bus.corrupt) + b(ctrl.corrupt) <= 1;
  // How often random simulation injects each fault (docs/tools.md): about once in 100 ticks,
  // so a random run also follows the nominal path. Verification ignores rates: the checkers
  // still consider every fault in every tick.
  rate fam.stallNow = 0.01;
  rate fam.hslFault = 0.01;
  rate fam.epmFault = 0.01;
  rate fam.fbfFault = 0.01;
  rate bus.corrupt = 0.01;
  rate ctrl.corrupt = 0.01;


  // "Faults stop occurring": from some tick on, no fault input is raised (F G calm). Each
  // property assumes it in its formula (a persistence assumption, not a `fair` justice one).

  // After a stall the stall procedure completes: the FAM's stall flag is cleared (the master
  // acknowledges it with STOP_STALL, D.3.2.2).
  ltl stall_procedure_completes:
    F G calm(fam.stallNow, fam.hslFault, fam.epmFault, fam.fbfFault, bus.corrupt, ctrl.corrupt)
    => G(fam.stall => F !fam.stall);

  // After a failure is cleared (the master, waiting in the general solution, sees no failure
  // flag) the master recalibrates and returns to normal running with a calibrated FAM.
  ltl recalibrates_after_failure:
    F G calm(fam.stallNow, fam.hslFault, fam.epmFault, fam.fbfFault, bus.corrupt, ctrl.corrupt)
    => G((ctrl.phase == FAIL_WAIT && (ctrl.rFail & MAJOR) == 0)
         => F(ctrl.phase == NORMAL && !fam.notCalib));

  // The FAM reaches a commanded target: once faults stop and the CCM stays at one value, the
  // FAM's position eventually equals the master's target for good.
  ltl reaches_target:
    F G (calm(fam.stallNow, fam.hslFault, fam.epmFault, fam.fbfFault, bus.corrupt, ctrl.corrupt) && ctrl.ccm == 500)
    => F G fam.actualPos == ctrl.targetPos;
}
