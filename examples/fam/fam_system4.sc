// fam_system4.sc — master + 4 FAMs on one LIN bus (App. A, C, D; ch. 6). The FAM, the LIN
// layer and the controller come from lib/; this file holds what depends on the number of
// slaves: the scheduler + master LIN driver, the slaves' wired-AND, the environment and the
// wiring (the language has no array-valued ports, so each slave's ports are written out).
import "lib/modulus.sc";
import "lib/fam.sc";
import "lib/lin.sc";
import "lib/master.sc";
import "lib/tie.sc";

const BUDGET: int = 10;    // ch. 5.4: controller steps between a response and the next request

// Scheduler + master LIN driver for 4 slave(s), Fig. D.1: request slots 0..3,
// response slots 4..7, then BUDGET processing ticks. A request slot sends the
// header and request field of that slave's controller (its outputs of the previous tick);
// a response slot sends only the header. `corrupt` flips a bit of the request field.
chart MasterBus4 {
  input corrupt: bool = false;
  input rm0: RunMode = STOP_STALL;
  input sw0: bool = false;
  input tp0: int[0..8191] = 0;
  input rm1: RunMode = STOP_STALL;
  input sw1: bool = false;
  input tp1: int[0..8191] = 0;
  input rm2: RunMode = STOP_STALL;
  input sw2: bool = false;
  input tp2: int[0..8191] = 0;
  input rm3: RunMode = STOP_STALL;
  input sw3: bool = false;
  input tp3: int[0..8191] = 0;
  output slot: int[0..17] = 17;
  output reqSel: int[0..5] = 0;      // k+1 in slave k's request slot
  output rspSel: int[0..5] = 0;      // k+1 in slave k's response slot
  output proc: bool = false;         // a processing tick
  output hIdent: int[0..255] = IDLE;
  output hB1: int[0..255] = IDLE;
  output hB2: int[0..255] = IDLE;
  output hCk: int[0..255] = IDLE;
  initial run;
  state run {
    during {
      slot = if slot + 1 >= 8 + BUDGET then 0 else slot + 1;
      reqSel = if slot < 4 then slot + 1 else 0;
      rspSel = if slot >= 4 && slot < 8 then slot - 3 else 0;
      proc = slot >= 8;
      hIdent = IDLE; hB1 = IDLE; hB2 = IDLE; hCk = IDLE;
      if slot == 0 {
        hIdent = identField(reqId(0));
        hB1 = reqDb1(rm0, sw0, tp0);
        hB2 = corruptByte(reqDb2(tp0), corrupt);
        hCk = checksum2(reqDb1(rm0, sw0, tp0), reqDb2(tp0));
      }
      if slot == 4 { hIdent = identField(rspId(0)); }
      if slot == 1 {
        hIdent = identField(reqId(1));
        hB1 = reqDb1(rm1, sw1, tp1);
        hB2 = corruptByte(reqDb2(tp1), corrupt);
        hCk = checksum2(reqDb1(rm1, sw1, tp1), reqDb2(tp1));
      }
      if slot == 5 { hIdent = identField(rspId(1)); }
      if slot == 2 {
        hIdent = identField(reqId(2));
        hB1 = reqDb1(rm2, sw2, tp2);
        hB2 = corruptByte(reqDb2(tp2), corrupt);
        hCk = checksum2(reqDb1(rm2, sw2, tp2), reqDb2(tp2));
      }
      if slot == 6 { hIdent = identField(rspId(2)); }
      if slot == 3 {
        hIdent = identField(reqId(3));
        hB1 = reqDb1(rm3, sw3, tp3);
        hB2 = corruptByte(reqDb2(tp3), corrupt);
        hCk = checksum2(reqDb1(rm3, sw3, tp3), reqDb2(tp3));
      }
      if slot == 7 { hIdent = identField(rspId(3)); }
    }
  }
}

// The slaves' side of the bus: wired-AND of the response fields (only the addressed
// slave drives it; the others send 0xFF).
chart SlaveBus4 {
  input rB10: int[0..255] = IDLE;
  input rB11: int[0..255] = IDLE;
  input rB12: int[0..255] = IDLE;
  input rB13: int[0..255] = IDLE;
  output sB1: int[0..255] = IDLE;
  input rB20: int[0..255] = IDLE;
  input rB21: int[0..255] = IDLE;
  input rB22: int[0..255] = IDLE;
  input rB23: int[0..255] = IDLE;
  output sB2: int[0..255] = IDLE;
  input rB50: int[0..255] = IDLE;
  input rB51: int[0..255] = IDLE;
  input rB52: int[0..255] = IDLE;
  input rB53: int[0..255] = IDLE;
  output sB5: int[0..255] = IDLE;
  input rCk0: int[0..255] = IDLE;
  input rCk1: int[0..255] = IDLE;
  input rCk2: int[0..255] = IDLE;
  input rCk3: int[0..255] = IDLE;
  output sCk: int[0..255] = IDLE;
  initial run;
  state run {
    during {
      sB1 = rB10 & rB11 & rB12 & rB13;
      sB2 = rB20 & rB21 & rB22 & rB23;
      sB5 = rB50 & rB51 & rB52 & rB53;
      sCk = rCk0 & rCk1 & rCk2 & rCk3;
    }
  }
}

enum EnvFault { NONE, STALL, HSL_F, EPM_F, OTF_F, FBF_F, CCF_F, POWER_LOSS, REQ_CORRUPT, RSP_CORRUPT }
chart Env4 {
  input ccmSel: int[0..2] = 0;
  input who: int[0..3] = 0;
  input fault: EnvFault = NONE;
  output ccm: int[0..1000] = 0;
  output reqCorrupt: bool = false;
  output stallNow0: bool = false;
  output hslFault0: bool = false;
  output epmFault0: bool = false;
  output otFault0: bool = false;
  output fbfFault0: bool = false;
  output ccfFault0: bool = false;
  output powerLoss0: bool = false;
  output rspCorrupt0: bool = false;
  output stallNow1: bool = false;
  output hslFault1: bool = false;
  output epmFault1: bool = false;
  output otFault1: bool = false;
  output fbfFault1: bool = false;
  output ccfFault1: bool = false;
  output powerLoss1: bool = false;
  output rspCorrupt1: bool = false;
  output stallNow2: bool = false;
  output hslFault2: bool = false;
  output epmFault2: bool = false;
  output otFault2: bool = false;
  output fbfFault2: bool = false;
  output ccfFault2: bool = false;
  output powerLoss2: bool = false;
  output rspCorrupt2: bool = false;
  output stallNow3: bool = false;
  output hslFault3: bool = false;
  output epmFault3: bool = false;
  output otFault3: bool = false;
  output fbfFault3: bool = false;
  output ccfFault3: bool = false;
  output powerLoss3: bool = false;
  output rspCorrupt3: bool = false;
  initial s;
  state s {
    during {
      ccm = ccmSel * 500;
      reqCorrupt = fault == REQ_CORRUPT;
      stallNow0 = who == 0 && fault == STALL;
      hslFault0 = who == 0 && fault == HSL_F;
      epmFault0 = who == 0 && fault == EPM_F;
      otFault0 = who == 0 && fault == OTF_F;
      fbfFault0 = who == 0 && fault == FBF_F;
      ccfFault0 = who == 0 && fault == CCF_F;
      powerLoss0 = who == 0 && fault == POWER_LOSS;
      rspCorrupt0 = who == 0 && fault == RSP_CORRUPT;
      stallNow1 = who == 1 && fault == STALL;
      hslFault1 = who == 1 && fault == HSL_F;
      epmFault1 = who == 1 && fault == EPM_F;
      otFault1 = who == 1 && fault == OTF_F;
      fbfFault1 = who == 1 && fault == FBF_F;
      ccfFault1 = who == 1 && fault == CCF_F;
      powerLoss1 = who == 1 && fault == POWER_LOSS;
      rspCorrupt1 = who == 1 && fault == RSP_CORRUPT;
      stallNow2 = who == 2 && fault == STALL;
      hslFault2 = who == 2 && fault == HSL_F;
      epmFault2 = who == 2 && fault == EPM_F;
      otFault2 = who == 2 && fault == OTF_F;
      fbfFault2 = who == 2 && fault == FBF_F;
      ccfFault2 = who == 2 && fault == CCF_F;
      powerLoss2 = who == 2 && fault == POWER_LOSS;
      rspCorrupt2 = who == 2 && fault == RSP_CORRUPT;
      stallNow3 = who == 3 && fault == STALL;
      hslFault3 = who == 3 && fault == HSL_F;
      epmFault3 = who == 3 && fault == EPM_F;
      otFault3 = who == 3 && fault == OTF_F;
      fbfFault3 = who == 3 && fault == FBF_F;
      ccfFault3 = who == 3 && fault == CCF_F;
      powerLoss3 = who == 3 && fault == POWER_LOSS;
      rspCorrupt3 = who == 3 && fault == RSP_CORRUPT;
    }
  }
}

// Master + 4 FAMs on one LIN bus, as in the thesis's HIL attempt (ch. 6: five FAMs). Every
// slave k has its own controller ctrl[k] (3.2) and its LIN port port[k]; the environment
// injects at most one fault per tick into one FAM. The properties are stated for slave 0
// (the slaves are symmetric up to their slot in the schedule).
system FamSystem4 {
  instance bus: MasterBus4;
  instance port[4]: FamPort;
  instance fam[4]: Fam(FAM_START);
  instance sbus: SlaveBus4;
  instance ctrl[4]: Controller;
  instance tie: Tie;
  instance env: Env4;
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
  connect port[3].runMode -> fam[3].runMode;
  connect port[3].swap -> fam[3].swap;
  connect port[3].targetPos -> fam[3].targetPos;
  connect port[3].cofNow -> fam[3].cofNow;
  connect fam[3].notCalib -> port[3].notCalib;
  connect fam[3].stall -> port[3].stall;
  connect fam[3].dir -> port[3].dir;
  connect fam[3].run -> port[3].run;
  connect fam[3].actualPos -> port[3].actualPos;
  connect fam[3].failureReg -> port[3].failureReg;
  connect port[3].rB1 -> sbus.rB13;
  connect port[3].rB2 -> sbus.rB23;
  connect port[3].rB5 -> sbus.rB53;
  connect port[3].rCk -> sbus.rCk3;
  connect ctrl[3].runMode -> bus.rm3;
  connect ctrl[3].swap -> bus.sw3;
  connect ctrl[3].targetPos -> bus.tp3;
  connect tie.k3 -> port[3].sna;
  connect tie.k3 -> ctrl[3].myId;
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
  connect env.stallNow3 -> fam[3].stallNow;
  connect env.hslFault3 -> fam[3].hslFault;
  connect env.epmFault3 -> fam[3].epmFault;
  connect env.otFault3 -> fam[3].otFault;
  connect env.fbfFault3 -> fam[3].fbfFault;
  connect env.ccfFault3 -> fam[3].ccfFault;
  connect env.powerLoss3 -> fam[3].powerLoss;
  connect env.ccm -> ctrl[3].ccm;
  connect env.rspCorrupt3 -> ctrl[3].corrupt;
  connect env.reqCorrupt -> bus.corrupt;
  order env, tie, bus, port, fam, sbus, ctrl;
  invariant fam_stall_blocks_run:
    !(in(fam[0].stallHandler.stallMode) && in(fam[0].moveHandler.running))
    assuming fam[0].runMode != FAILURE_RUN;
  invariant fam_failure_blocks_run:
    !(in(fam[0].failureHandler.failure) && in(fam[0].moveHandler.running))
    assuming fam[0].runMode != FAILURE_RUN;
  invariant fam_actualpos_in_range: fam[0].actualPos >= 0 && fam[0].actualPos <= 4095;
  invariant master_no_normal_run_on_failure:
    !(bus.reqSel == 1 && ctrl[0].runMode == NORMAL_RUN && (ctrl[0].rFail & MAJOR) != 0);
  invariant master_failure_before_stall:
    !(bus.reqSel == 1 && ctrl[0].runMode == STOP_STALL && (ctrl[0].rFail & MAJOR) != 0);
  invariant master_outputs_in_range: ctrl[0].targetPos >= 0 && ctrl[0].targetPos <= 4095;
  invariant master_target_outside_ends_only_calibrating:
    inRange(ctrl[0].targetPos, ctrl[0].endPos1) || ctrl[0].phase == CALIB;
}
