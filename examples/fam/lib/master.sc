// lib/master.sc — the master task: the controller `Controller` (one per slave) and its
// procedures. Leaves to its importer, imported BEFORE this file: POS_TOP, MOD_TOP and mod12
// (lib/modulus.sc or lib/thesis_modulus.sc). The scheduler + LIN driver MasterBus(N) is
// in lib/bus.sc; it reads BUDGET, declared by the entry file (10; 5 in
// bug_short_timeout.sc).

// =======================================================================================
// The master task (thesis App. D, ch. 3.2): one `Controller` per slave (the thesis: "it is
// possible to use several instances of this controller in order to control several FAMs.
// These instances share the same bus. That is why there is a need for a scheduler"), and the
// scheduler + LIN driver `MasterBus(N)` (lib/bus.sc, written once for every N).
// =======================================================================================
//
// Positions in the closed loop are SCALED DOWN by 10 (the thesis §5.1 shrank its counters the
// same way): the flap range, the calibration overshoot (50 -> 5), the bounce step
// (100 -> 10), the gray zone, the back-off and the bit-2 opposite run (>= 17 -> 2) are
// tenths of what a real flap would use. The FAM's own constants (fam.sc) are not scaled.

// Factory range detection (D.3.1): the closed end stop E1F and the range. The range straddles
// position 0 (4090 .. 6), so every flap move near the closed end crosses zero and needs the
// swap flag (D.3.1.1, Fig. D.4), and Eq. D.1's modulus matters.
const E1F: int = 4090;
const RANGE: int = 12;
const OVER: int = 5;          // D.3.2.1: 50 positions past the end stop
const BOUNCE: int = 10;       // D.3.2.1 note: 100 positions at a time on bounce
const MAX_BOUNCE: int = 1;    // our bound on the bounce steps (the thesis gives none)
const GRAY: int = 2;          // D.3.2.2: width of the gray zone inside the range
const BACK_STEPS: int = 2;      // D.3.2.2: "move backwards a few positions"
const OPP: int = 2;           // D.3.2.3 bit 2: opposite direction, >= 17 positions
const FBF_RETRIES: int = 4;   // D.3.2.3 bit 2: "Repeat this routine 4 times"
const HSL_ROUNDS: int = 2;    // D.3.2.3 bit 7: "after some a certain timeout" (rounds)
// BUDGET (ch. 5.4: controller steps between a response and the next request) is declared by
// the entry file: 10, or 5 in bug_short_timeout.sc.
const REACH: int = OVER + MAX_BOUNCE * BOUNCE;   // how far past an end stop calibration goes

enum Phase {
  NORMAL,        // follow the CCM
  FAIL_WAIT,     // general solution: STOP_FAILURE until the flags are cleared
  HSL_PERM,      // bit 7 permanent: FAILURE_RUN
  FBF_RUN,       // bit 2: run again in the same direction
  FBF_OPP,       // bit 2: run once in the opposite direction
  FBF_PERM,      // bit 2 again: FAILURE_RUN until power off
  CALIB,         // D.3.2.1: move past the end stop until a stall
  STALL_ACK,     // D.3.2.2: STOP_STALL until the stall flag is cleared
  CLEAR_CALIB,   // D.3.2.1: CLEAR_NOT_CALIB after a calibration stall
  BACKOFF,       // D.3.2.2: hard flap point: move backwards, then push through
}

// Eq. D.1 with the 12-bit modulus (the thesis prints "mod 4095"; positions are 0..4095).
// mod12(p) is declared by lib/modulus.sc (or lib/thesis_modulus.sc).
// Signed circular distance from e to p, in -2048..2047.
fn sdist(p: int[0..4095], e: int[0..4095]) -> int[-2048..2047] = mod12(p - e + 2048) - 2048;
fn inRange(p: int[0..4095], e1: int[0..4095]) -> bool = mod12(p - e1) <= RANGE;
// The nearest position of [e1, e1 + RANGE].
fn clampR(p: int[0..4095], e1: int[0..4095]) -> int[0..4095] =
  if inRange(p, e1) then p
  else if sdist(p, e1) < 0 || sdist(p, e1) > RANGE + (4096 - RANGE) / 2 then e1
  else mod12(e1 + RANGE);
// Eq. D.1: targetPos = (endPos1 + Range * CCM / 1000) mod 4096.
fn ccmTarget(e1: int[0..4095], ccm: int[0..1000]) -> int[0..MOD_TOP] = mod12(e1 + RANGE * ccm / 1000);
// D.3.1.1: the master predicts a wrong direction when the need of movement exceeds half a
// turn and sets the swap flag. (The FAM of fam.sc shifts both the target and its actual
// position by 0x800 itself, Table C.4, so the master sends the absolute target with SWAP set:
// shifting it on both sides would cancel.)
fn predictSwap(target: int[0..MOD_TOP], actual: int[0..4095]) -> bool = abs(target - actual) > 2048;
// D.3.2.2: the gray zone: near a factory end stop, from GRAY inside the range to as far
// outside as calibration goes.
fn grayNear1(p: int[0..4095]) -> bool = sdist(p, E1F) >= -REACH && sdist(p, E1F) <= GRAY;
fn grayNear2(p: int[0..4095]) -> bool =
  sdist(p, mod12(E1F + RANGE)) >= -GRAY && sdist(p, mod12(E1F + RANGE)) <= REACH;
// The master's check of a response: all data bytes (padding included) plus the checksum add
// up to 0xFF. (The padding matters: for an all-zero DB1, DB2, DB5 — position 0, no flag — the
// sum with the 0xFF bytes is 0xFF and the checksum 0x00.)
fn rspOk(b1: int[0..255], b2: int[0..255], b5: int[0..255], ck: int[0..255]) -> bool =
  addc(sumRsp(b1, b2, b5), ck) == 0xFF;

chart Controller {
  input myId: int[0..4] = 0;             // which slave (fixed by an assume)
  input ccm: int[0..1000] = 0;           // Table B.3: desired flap opening 0..1000
  input rspSel: int[0..5] = 0;           // from the scheduler: k+1 in slave k's response slot
  input proc: bool = false;              // from the scheduler: a processing tick
  input sB1: int[0..255] = IDLE;         // the response field on the bus
  input sB2: int[0..255] = IDLE;
  input sB5: int[0..255] = IDLE;
  input sCk: int[0..255] = IDLE;
  input corrupt: bool = false;           // environment: the response frame is corrupted
  // The request fields (Table B.3 outputs), sent by the scheduler in this slave's request slot.
  output runMode: RunMode = STOP_STALL;
  output swap: bool = false;
  output targetPos: int[0..POS_TOP] = E1F;
  // The latest consistent response (Table B.3 inputs).
  output rNotCalib: bool = false;
  output rStall: bool = false;
  output rDir: bool = false;
  output rRun: bool = false;
  output rPos: int[0..4095] = FAM_START;
  output rFail: int[0..255] = 0;
  output phase: Phase = NORMAL;
  local endPos1: int[0..4095] = E1F;      // re-referenced by a stall in the gray zone
  local fbfCount: int[0..6] = 0;          // bit-2 occurrences in a row
  local hslRounds: int[0..2] = 0;         // rounds bit 7 stayed set under STOP_FAILURE
  local bounces: int[0..1] = 0;
  local grayStall: bool = false;

  initial waiting;
  // communicationHandler: wait for this slave's response; a frame with a bad checksum is
  // discarded and the previous request is repeated (D.1: consistency check).
  state waiting {
    on [rspSel == myId + 1 && rspOk(sB1, corruptByte(sB2, corrupt), sB5, sCk)]
      / { rNotCalib = (sB1 & 0x80) != 0; rStall = (sB1 & 0x40) != 0;
          rDir = (sB1 & 0x20) != 0; rRun = (sB1 & 0x10) != 0;
          rPos = ((sB1 & 0x0F) << 8) | sB2; rFail = sB5; } -> moveHandler;
  }
  // requestHandler. Each state below takes one processing tick (one state of the thesis's
  // Stateflow controller per scheduler step); the chain for a failure is six steps long,
  // which is why a budget of 5 steps is too short (ch. 5.4).
  // moveHandler: anything abnormal goes to the errorHandler (3.2.2).
  state moveHandler {
    on [proc && ((rFail & MAJOR) != 0 || rStall || rNotCalib || phase != NORMAL)] -> calibAndStall;
    on [proc] -> commit;
  }
  // errorHandler: calibAndStall is its default state; a failure is prioritized (3.2.3).
  state calibAndStall {
    on [proc && (rFail & MAJOR) != 0] -> failureHandler;
    on [proc] / {
      if phase == HSL_PERM || phase == FBF_PERM {
        // FAILURE_RUN until power off
      } else if rStall && phase != STALL_ACK {
        // D.3.2.2: a stall inside the gray zone is a new end reference; outside it is a hard
        // flap point. Hold the stall position.
        grayStall = grayNear1(rPos) || grayNear2(rPos);
        if grayNear1(rPos) { endPos1 = rPos; }
        else if grayNear2(rPos) { endPos1 = mod12(rPos - RANGE); }
        targetPos = clampR(rPos, endPos1);
        phase = STALL_ACK;
      } else if phase == STALL_ACK {
        if !rStall {
          if !grayStall { phase = BACKOFF;
                          targetPos = clampR(mod12(rPos + (if rDir then BACK_STEPS else -BACK_STEPS)), endPos1); }
          else if rNotCalib { phase = CLEAR_CALIB; }
          else { phase = NORMAL; }
        }
      } else if phase == CLEAR_CALIB {
        if !rNotCalib { phase = NORMAL; bounces = 0; }
      } else if phase == FAIL_WAIT {
        // the flags are cleared
        if fbfCount >= 1 && fbfCount <= FBF_RETRIES { phase = FBF_RUN; }
        else if fbfCount == FBF_RETRIES + 1 {
          phase = FBF_OPP;
          targetPos = clampR(mod12(rPos + (if rDir then OPP else -OPP)), endPos1);
        } else if rNotCalib { phase = CALIB; bounces = 0;
                              targetPos = if rDir then mod12(endPos1 - OVER) else mod12(endPos1 + RANGE + OVER); }
        else { phase = NORMAL; }
      } else if (phase == FBF_RUN && rPos == ccmTarget(endPos1, ccm) && !rRun)
                || (phase == FBF_OPP && rPos == targetPos && !rRun) {
        fbfCount = 0;
        phase = NORMAL;
      } else if phase == BACKOFF {
        if rPos == targetPos && !rRun { phase = NORMAL; }
      } else if phase == CALIB {
        if rPos == targetPos && !rRun {
          // no stall at the end stop: the flap bounced (D.3.2.1 note)
          if bounces < MAX_BOUNCE {
            bounces += 1;
            targetPos = if rDir then mod12(targetPos - BOUNCE) else mod12(targetPos + BOUNCE);
          } else { phase = NORMAL; bounces = 0; targetPos = clampR(rPos, endPos1); }
        }
      } else if phase == NORMAL && rNotCalib {
        phase = CALIB; bounces = 0;
        targetPos = if rDir then mod12(endPos1 - OVER) else mod12(endPos1 + RANGE + OVER);
      }
      if phase != CALIB { targetPos = clampR(targetPos, endPos1); }
    } -> commit;
  }
  state failureHandler { on [proc] -> bitCheck; }
  // The exceptions of D.3.2.3 for bits 7, 3 and 2, then the general solution.
  state bitCheck {
    on [proc] / {
      if phase == HSL_PERM || phase == FBF_PERM {
        // stays
      } else if (rFail & FBF) != 0 && phase != FAIL_WAIT {
        fbfCount = min(fbfCount + 1, FBF_RETRIES + 2);
        if fbfCount == FBF_RETRIES + 2 { phase = FBF_PERM; }
        else { phase = FAIL_WAIT; hslRounds = 0; }
      } else if (rFail & HSL) != 0 && phase == FAIL_WAIT {
        hslRounds = min(hslRounds + 1, HSL_ROUNDS);
        if hslRounds == HSL_ROUNDS { phase = HSL_PERM; }
      } else if phase != FAIL_WAIT {
        phase = FAIL_WAIT; hslRounds = 0;
      }
      // only a calibration move may aim outside [endPos1, endPos2]
      if phase != CALIB { targetPos = clampR(targetPos, endPos1); }
    } -> routine;
  }
  state routine { on [proc] -> commit; }
  // Write the request of this round from the phase.
  state commit {
    on [proc] / {
      if phase == NORMAL {
        targetPos = ccmTarget(endPos1, ccm);
        // bit 3 has the lowest priority: clear it once the actuator rests at its target
        runMode = if (rFail & COF) != 0 && !rRun && rPos == targetPos then STOP_FAILURE else NORMAL_RUN;
      } else if phase == FAIL_WAIT { runMode = STOP_FAILURE; }
      else if phase == HSL_PERM || phase == FBF_PERM {
        targetPos = ccmTarget(endPos1, ccm); runMode = FAILURE_RUN;
      } else if phase == FBF_RUN { targetPos = ccmTarget(endPos1, ccm); runMode = NORMAL_RUN; }
      else if phase == STALL_ACK { runMode = STOP_STALL; }
      else if phase == CLEAR_CALIB { runMode = CLEAR_NOT_CALIB; }
      else { runMode = NORMAL_RUN; }     // CALIB, BACKOFF, FBF_OPP: to the held target
      swap = predictSwap(targetPos, rPos);
    } -> waiting;
  }
}
