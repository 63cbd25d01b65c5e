// lib/fam_system1.sc — master + 1 FAM on one LIN bus (App. A, C, D; ch. 6): the system
// FamSystem, with the scheduler and LIN driver MasterBus(1) of lib/bus.sc. Shared by
// ../fam_system.sc and the bug variants, which import it after a modulus file (lib/modulus.sc
// or lib/thesis_modulus.sc) and declare BUDGET (the controller's processing ticks per bus
// round).

import "bus.sc";

// ---------------------------------------------------------------------------------------
// Master + 1 FAM on one LIN bus: the closed loop the thesis could not verify (ch. 5, 7).
//
// Environment (free inputs, every tick): the CCM value (one of 0, 500, 1000: three targets
// across position 0 of the flap range), and at most one of: a stall, an HSL cause (bit 7:
// the permanent-failure exception), an EPM (bit 5: the general solution), an FBF (bit 2: the
// retry routine), a corrupted request frame (COF, bit 3), a corrupted response frame.
// Abstractions, each to keep the explicit state space small:
//  - OTF, CCF (handled like HSL: cleared only once the cause is gone, by the general
//    solution) and power loss (CPF: like EPM) are tied low: with them the closed loop has
//    4.4 million states at depth 42 and is not exhausted in 600 s (docs/case-studies/fam.md);
//  - at most one fault per tick (an input-only assume: the explicit engine solves it once,
//    up front, whatever the other assumes read);
//  - no failed position save (DPR): it moves the FAM to 0x800, two thousand positions from
//    the (scaled) flap range (the FAM alone covers DPR);
//  - positions of the master's procedures scaled down by 10 (see lib/master.sc);
//  - the FAM starts at FAM_START (lib/lin.sc), its saved position, inside the flap range.
system FamSystem {
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

  // --- the FAM's properties (ch. 5.3), now with the master as the FAM's environment ------
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

  // --- the master's properties (ch. 5.4) --------------------------------------------------
  // "Can the master send NORMAL_RUN if there is a failure in the FAM?": never a request frame
  // with NORMAL_RUN while the master's latest response shows a failure flag. COF (bit 3) is
  // excluded: it "does not inhibit any functionality" and its clearing has the lowest
  // priority (D.3.2.3), so the master keeps running with it.
  invariant master_no_normal_run_on_failure:
    !(bus.reqSel == 1 && ctrl.runMode == NORMAL_RUN && (ctrl.rFail & MAJOR) != 0);
  // "handle Stall and failure at the same time": failure is prioritized — the stall
  // procedure (STOP_STALL) is never requested while a failure flag is known.
  invariant master_failure_before_stall:
    !(bus.reqSel == 1 && ctrl.runMode == STOP_STALL && (ctrl.rFail & MAJOR) != 0);
  // "Are the output variables from the controller within the boundaries?" (runMode and swap
  // are bounded by their types.)
  invariant master_outputs_in_range:
    ctrl.targetPos >= 0 && ctrl.targetPos <= 4095;
  // targetPos outside [endPos1, endPos2] only while calibrating ...
  invariant master_target_outside_ends_only_calibrating:
    inRange(ctrl.targetPos, ctrl.endPos1) || ctrl.phase == CALIB;
  // ... and the thesis's literal question, which is supposed to be "violated": it happens.
  reachable master_target_outside_ends:
    !inRange(ctrl.targetPos, ctrl.endPos1);

  // §5.4.1, the sequence property as an observer of the request frames on the bus: once the
  // master knows of a failure, it requests only STOP_FAILURE (or FAILURE_RUN, the bit 7 and
  // bit 2 exceptions) until the flags are cleared; then the calibration sequence: moves, a
  // STOP_STALL, and only after that CLEAR_NOT_CALIB.
  observer master_failure_sequence {
    initial ok;
    state ok {
      on [(ctrl.rFail & MAJOR) != 0] -> failed;
    }
    state failed {
      on [bus.reqSel == 1 && ctrl.runMode == FAILURE_RUN] -> degraded;
      on [bus.reqSel == 1 && ctrl.runMode != STOP_FAILURE] -> error;
      on [(ctrl.rFail & MAJOR) == 0] -> recal;
    }
    state recal {
      on [(ctrl.rFail & MAJOR) != 0] -> failed;
      on [bus.reqSel == 1 && ctrl.runMode == CLEAR_NOT_CALIB] -> error;
      on [bus.reqSel == 1 && ctrl.runMode == STOP_STALL] -> acked;
    }
    state acked {
      on [(ctrl.rFail & MAJOR) != 0] -> failed;
      on [bus.reqSel == 1 && ctrl.runMode == CLEAR_NOT_CALIB] -> ok;
      on [bus.reqSel == 1 && ctrl.runMode != STOP_STALL] -> recal;
    }
    state degraded;   // FAILURE_RUN until power off
    state error;
  }
}
