// lib/fam.sc — the FAM plant chart `Fam` and its helpers (no system: see ../fam.sc, FamAlone).
//
// Leaves to its importer, imported BEFORE this file: POS_TOP (the largest position the
// registers hold) and wrap12 (position arithmetic modulo 4096) — lib/modulus.sc, or
// lib/thesis_modulus.sc for the thesis's faulty modulus (bug_modulus.sc). `Fam(start)`:
// the position at power-up (default 0x800; the closed loops start at FAM_START).
//
// The EATON FAM (Flap Actuator Module), a LIN stepper actuator, as a plant chart.
//
// Source: the thesis "fam-stepper-supervisor-thesis" (../../../shared/seeds), Appendix C
// ("Specification of the EATON FAM model"), Appendix B (Table B.2, the FAM's variables) and
// chapter 3.1 (the Stateflow model: five parallel superstates communication, move, stall,
// failure and calibration, Fig. 3.1). Every rule below cites the table it comes from.
//
// What one tick is: one scheduling step of the actuator's motor control. Speeds are in
// positions per tick: SPEED_LOW = 1 (fixed 210 steps/s = 105 pos/s, Table C.3
// NORMAL_RUN_FIXED_LOW / FAILURE_RUN) and SPEED_HIGH = 3 (7.8 rpm ~ 275 pos/s at
// 0.17 deg/pos, Table C.3 NORMAL_RUN: a ratio of about 2.6, rounded to 3). So a tick is
// roughly 10 ms of real time; nothing in the rules depends on the exact figure.
//
// Interface (Table B.2):
//   request (Table C.1, DB1_REQ bits 7..5 run mode, bit 4 swap, bits 3..0 + DB2_REQ target):
//     runMode, swap, targetPos            — inputs here; the master and the LIN layer
//                                           (App. A) come later and will drive them.
//   response (Table C.5/C.6, DB1_RES bits 7..4 NOT-CALIB/STALL/DIR/RUN, 12-bit actual pos,
//     DB5_RES failure register):
//     notCalib, stall, dir, run, actualPos, failureReg
//     (DB3/DB4 Last Min/Max Torque are "not implemented in the FAM model", C.2.2.2–3.)
//   environment: one free bool per fault, so verification covers every fault at every tick.
//
// Structure (Fig. 3.1, minus the communication superstate, which the request inputs replace):
// parallel regions that run in this order every tick —
//   stallHandler   stall detection and acknowledgement                (Table C.7 STALL, C.3)
//   failureMonitor the failure register: activation and reset         (Tables C.8, C.9)
//   failureHandler `failure` while a major (non-COF) flag is set      (C.2.2.4, Fig. 3.5)
//   moveHandler    stopped / running, position calculus, DIR and RUN  (Tables C.3, C.4, C.7)
//   calibHandler   calibrated / notCalibrated                         (Table C.7 NOT-CALIB)
// The order is chosen so that the flags a tick sets are seen by the move region in the same
// tick: a stall or a failure stops the motor in the tick it is detected, never one later.
// Detection itself reads `in(moveHandler.running)` as it was at the start of the tick.

// ---------------------------------------------------------------------------------------
// Run modes, in the numeric order of Table C.2 (DB1_REQ bits 7..5): STOP_STALL = 0b000 ...
// NORMAL_RUN_HIGH = 0b111. (Chapter 5.3 of the thesis calls FAILURE_RUN "runMode==5" in its
// test cases; Table C.2 and Table D.1 both give FAILURE_RUN = 0b100 = 4, which we follow.)
enum RunMode {
  STOP_STALL,            // 0 b000  stop, clear (acknowledge) the stall flag
  STOP_FAILURE,          // 1 b001  stop, clear the failure flags
  NORMAL_RUN,            // 2 b010  closed loop, high or low speed by move length
  NORMAL_RUN_FIXED_LOW,  // 3 b011  closed loop, fixed speed 210 steps/s
  FAILURE_RUN,           // 4 b100  open loop, no stall detection, never inhibited
  NORMAL_RUN_LOW,        // 5 b101  closed loop, low speed
  CLEAR_NOT_CALIB,       // 6 b110  clear the notCalib flag
  NORMAL_RUN_HIGH,       // 7 b111  closed loop, high speed
}

// Positions (C.2.1.1): 12 bits, 0..4095.
const DEFAULT_POS: int = 0x800;      // Table C.9 bit 6: the position restored after a failed save
const SWAP_XOR: int = 0x800;         // Table C.4: shifted position = pos XOR 0x800 (half a turn)

// Table C.7 NOT-CALIB: an end stop met after a move shorter than 3.4 deg = 20 pos (40 steps).
const SHORT_MOVE: int = 20;
// Table C.3 NORMAL_RUN: low speed for movements shorter than 44 deg; one position is 0.17 deg
// (Table C.7: 20 pos = 3.4 deg), so 44 deg = 258.8 pos: a move of 259 positions or more is long.
const LOW_SPEED_LIMIT: int = 259;
const SPEED_LOW: int = 1;            // positions per tick
const SPEED_HIGH: int = 3;

// Failure register DB5_RES, Table C.8 (bit 7 .. bit 0); activation/reset rules in Table C.9.
const HSL: int = 0x80;   // bit 7  Hall sensor supply current limitation
const DPR: int = 0x40;   // bit 6  Default position restore (0x800)
const EPM: int = 0x20;   // bit 5  Extreme position maintainable
const OTF: int = 0x10;   // bit 4  Over voltage or over temperature
const COF: int = 0x08;   // bit 3  Communication failure
const FBF: int = 0x04;   // bit 2  Feedback failure
const CCF: int = 0x02;   // bit 1  Coil circuit failure or coil driver failure
const CPF: int = 0x01;   // bit 0  Calibration lost during movement when power failed
// C.2.2.4: "When a failure is set, except communication failure (bit3), the actuator is kept in
// stop mode until failure flag is cleared" — every flag but COF is a major (inhibiting) failure.
const MAJOR: int = 0xF7;

// ---------------------------------------------------------------------------------------
// Pure helpers.

// Position arithmetic modulo 4096. The thesis's own modulus function returned 4096 (ch. 5.3,
// the actualPos range test): this is the corrected one.
// wrap12(p) is declared by lib/modulus.sc (the corrected one) or lib/thesis_modulus.sc.

// Table C.4, "need of movement": case 1 (swap 0) targetPos - actualPos; case 2 (swap 1)
// (targetPos XOR 0x800) - (actualPos XOR 0x800). Negative = decremental (D.3.1.1).
fn need(actual: int[0..POS_TOP], target: int[0..4095], swapped: bool) -> int[-POS_TOP..POS_TOP] =
  if swapped then (target ^ SWAP_XOR) - (actual ^ SWAP_XOR) else target - actual;

// The closed-loop ("normal") run modes of Table C.2.
fn isNormalRun(m: RunMode) -> bool =
  m == NORMAL_RUN || m == NORMAL_RUN_FIXED_LOW || m == NORMAL_RUN_LOW || m == NORMAL_RUN_HIGH;

// Table C.3, "Actuator is stopped": a normal run mode starts a move unless the stall flag is
// unacknowledged or a failure other than COF is set ("The motor can not acknowledge this
// request if the motor is in failure (except communication failure) or if stall detection is
// not acknowledged"); FAILURE_RUN always starts ("No inhibition to run in this mode");
// STOP_STALL, STOP_FAILURE and CLEAR_NOT_CALIB never start a move.
fn mayStart(m: RunMode, stalled: bool, reg: int[0..255]) -> bool =
  m == FAILURE_RUN || (isNormalRun(m) && !stalled && (reg & MAJOR) == 0);

// Table C.3, "Actuator is running": STOP_STALL and STOP_FAILURE stop the actuator; a run mode
// keeps it moving towards the (possibly new) target; a stall or a major failure stops it
// unless the mode is FAILURE_RUN (Table C.7 STALL, C.2.2.4). CLEAR_NOT_CALIB while running
// only clears the flag (Table C.3), so the move in progress continues under the same
// inhibitions as a normal run — a modelling decision: the table does not say more.
fn mayContinue(m: RunMode, stalled: bool, reg: int[0..255]) -> bool =
  m == FAILURE_RUN
  || ((isNormalRun(m) || m == CLEAR_NOT_CALIB) && !stalled && (reg & MAJOR) == 0);

// Table C.3: stall detection is enabled in the closed-loop modes and disabled in FAILURE_RUN.
fn stallDetection(m: RunMode) -> bool = isNormalRun(m) || m == CLEAR_NOT_CALIB;

// Table C.3: NORMAL_RUN_HIGH is fast; NORMAL_RUN is fast for long moves (decided when the
// move starts, `fast`); FIXED_LOW, LOW, FAILURE_RUN (210 steps/s) and a move continued under
// CLEAR_NOT_CALIB are slow.
fn speed(m: RunMode, fast: bool) -> int[1..3] =
  if m == NORMAL_RUN_HIGH || (m == NORMAL_RUN && fast) then SPEED_HIGH else SPEED_LOW;

// One tick of motion towards the goal: at most `v` positions, never past it.
fn stepToward(n: int[-POS_TOP..POS_TOP], v: int[1..3]) -> int[-3..3] =
  if n > 0 then min(n, v) else if n < 0 then -min(-n, v) else 0;

// Table C.9 reset conditions, for a STOP_FAILURE request while the motor is stopped
// ("Failure flag is cleared when the motor has stopped completely", Table C.3): every flag
// is cleared except HSL, OTF and CCF while their cause is still present ("cleared when current
// has decreased below the limit and ...", "has to decrease ... until the failure flag can be
// cleared", "... and the failure has disappeared"). The result is the mask of cleared bits.
fn failClear(stopFailure: bool, hsl: bool, otf: bool, ccf: bool) -> int[0..255] =
  if stopFailure
  then 0xFF ^ ((if hsl then HSL else 0) | (if otf then OTF else 0) | (if ccf then CCF else 0))
  else 0;

// Table C.9 activation conditions, already combined with the motor state by the caller.
fn failDetect(hsl: bool, dpr: bool, epm: bool, otf: bool,
              cof: bool, fbf: bool, ccf: bool, cpf: bool) -> int[0..255] =
  (if hsl then HSL else 0) | (if dpr then DPR else 0) | (if epm then EPM else 0)
  | (if otf then OTF else 0) | (if cof then COF else 0) | (if fbf then FBF else 0)
  | (if ccf then CCF else 0) | (if cpf then CPF else 0);

// ---------------------------------------------------------------------------------------
plant chart Fam(start: int[0..4095] = 2048) {
  // Request fields (Table C.1 / Table B.2 "Input (LIN)"). Held until the next request.
  input runMode: RunMode = STOP_STALL;
  input swap: bool = false;
  input targetPos: int[0..4095] = 2048;

  // Environment: faults and physical events. Free in verification, every tick.
  input stallNow: bool = false;   // torque reaches the stall limit (Table C.7 STALL activation)
  input hslFault: bool = false;   // hall-sensor output above its current limit (bit 7 cause)
  input epmFault: bool = false;   // stopped actuator cannot hold its position (bit 5 cause)
  input otFault: bool = false;    // over-temperature or over-voltage present (bit 4 cause)
  input cofNow: bool = false;     // a LIN request frame was corrupted (bit 3 cause)
  input fbfFault: bool = false;   // hall/commutation synchronisation missed (bit 2 cause)
  input ccfFault: bool = false;   // open coil circuit present (bit 1 cause)
  input powerLoss: bool = false;  // U_bat < 8 V: the actuator resets in this tick (bits 0, 6)
  input saveFails: bool = false;  // with powerLoss: saving the position failed (bit 6)

  // Response fields (Table C.5/C.6 DB1_RES status bits, 12-bit actual position, DB5_RES).
  output notCalib: bool = false;          // bit 7: actualPos not accurate, calibrate
  output stall: bool = false;             // bit 6: actuator has stalled (until STOP_STALL)
  output dir: bool = false;               // bit 5: last/actual move decremental (true) or not
  output run: bool = false;               // bit 4: actuator is running
  output actualPos: int[0..POS_TOP] = start;  // 12-bit actual position (0x800 unless given)
  output failureReg: int[0..255] = 0;     // DB5_RES, bits as in the constants above

  local travelled: int[0..20] = 0;        // positions moved since the move started, saturated
  local fast: bool = false;               // NORMAL_RUN: the move was long when it started
  local endStopEarly: bool = false;       // stall after a short move, for calibHandler (same tick)

  // --- STALL flag, Table C.7 (bit #6) and Table C.3 STOP_STALL ---------------------------
  region stallHandler {
    initial noStall;
    state noStall {
      // "Flag is set when the torque reach the defined stall limit" — only while running
      // with stall detection enabled (not in FAILURE_RUN, Table C.3). An end stop met after
      // a move shorter than 20 positions also corrupts the position (Table C.7 NOT-CALIB).
      on [in(moveHandler.running) && stallNow && stallDetection(runMode)]
        / { if travelled < SHORT_MOVE { endStopEarly = true; } } -> stallMode;
    }
    state stallMode {
      entry { stall = true; }
      exit  { stall = false; }
      // "Flag is cleared when the master request the STOP_STALL" (Table C.7); "Stall flag is
      // cleared when the motor has stopped completely" (Table C.3 STOP_STALL, running).
      on [runMode == STOP_STALL && in(moveHandler.stopped)] -> noStall;
    }
  }

  // --- Failure register DB5_RES, Tables C.8 and C.9 ---------------------------------------
  region failureMonitor {
    initial monitoring;
    state monitoring {
      during {
        // First the reset (Table C.9: "cleared when the master requests the STOP_FAILURE
        // mode", once stopped, Table C.3), then this tick's activations, so a fault found in
        // a STOP_FAILURE tick is reported at least once. Activation conditions (Table C.9):
        //   HSL  while the hall-sensor current is above its limit;
        //   DPR  after a reset whose position save failed (position becomes 0x800);
        //   EPM  "when actuator is stopped and is unable to keep its position";
        //   OTF  while over-temperature / over-voltage is present;
        //   COF  on a corrupted request frame;
        //   FBF  when hall feedback and commutation lose synchronisation — needs the motor
        //        running with feedback, so not in FAILURE_RUN ("hall sensor feedback is
        //        disabled");
        //   CCF  "when actuator is stopped and an open coil circuit appears";
        //   CPF  "if power is lost when actuator is running".
        failureReg = (failureReg
                      & (0xFF ^ failClear(runMode == STOP_FAILURE && in(moveHandler.stopped),
                                          hslFault, otFault, ccfFault)))
                     | failDetect(hslFault,
                                  powerLoss && saveFails,
                                  epmFault && in(moveHandler.stopped),
                                  otFault,
                                  cofNow,
                                  fbfFault && in(moveHandler.running) && runMode != FAILURE_RUN,
                                  ccfFault && in(moveHandler.stopped),
                                  powerLoss && in(moveHandler.running));
      }
    }
  }

  // --- Failure superstate (Fig. 3.5): `failure` while a major flag is set ------------------
  // COF is reported in the register but "will not affect any other functionality (still able
  // to run actuator)" (Table C.9 bit 3), so it does not make this region enter `failure`.
  region failureHandler {
    initial noFailure;
    state noFailure {
      on [(failureReg & MAJOR) != 0] -> failure;
    }
    state failure {
      on [(failureReg & MAJOR) == 0] -> noFailure;
    }
  }

  // --- Move superstate (Fig. 3.3): Table C.3 per run mode, Table C.4 position calculus ----
  region moveHandler {
    initial stopped;
    state stopped {
      // Table C.9 bit 6: after a reset with a failed save the actuator "will retrieve the
      // position 0x800". A reset never starts a move.
      on [powerLoss && saveFails] / { actualPos = DEFAULT_POS; };
      on [!powerLoss && mayStart(runMode, stall, failureReg) && actualPos != targetPos]
        -> running;
    }
    state running {
      entry {
        run = true;                                       // Table C.7 RUN: set while running
        travelled = 0;
        fast = abs(need(actualPos, targetPos, swap)) >= LOW_SPEED_LIMIT;
        dir = need(actualPos, targetPos, swap) < 0;      // Table C.7 DIR: set = decremental
      }
      exit { run = false; }                               // cleared when stopped
      // A power loss resets the actuator: it stops (Table C.9 bit 0: "brake the rotor ...
      // before position is saved"); a failed save restores 0x800 (bit 6).
      on [powerLoss] / { if saveFails { actualPos = DEFAULT_POS; } } -> stopped;
      on [!mayContinue(runMode, stall, failureReg)] -> stopped;
      on [actualPos == targetPos] -> stopped;             // goal reached
      during {
        // Table C.4: move by the sign of the need of movement, in shifted coordinates when
        // swap is set. Moving a shifted position by d and shifting back is the same as
        // moving actualPos by d modulo 4096, so the swap only changes the direction.
        dir = need(actualPos, targetPos, swap) < 0;
        travelled = min(SHORT_MOVE,
                        travelled + abs(stepToward(need(actualPos, targetPos, swap),
                                                   speed(runMode, fast))));
        actualPos = wrap12(actualPos + stepToward(need(actualPos, targetPos, swap),
                                                  speed(runMode, fast)));
      }
    }
  }

  // --- Calibration superstate (Fig. 3.6), Table C.7 NOT-CALIB ------------------------------
  region calibHandler {
    initial calibrated;
    state calibrated {
      entry { notCalib = false; }
      // Set "when actuator has detected conditions which may have corrupted its actual
      // position. This condition are failure [every failure except COF, C.2.2.4], or when
      // actuator detects an end stop after a travel length move shorter than 3.4 deg".
      on [in(failureHandler.failure) || endStopEarly] / { endStopEarly = false; }
        -> notCalibrated;
    }
    state notCalibrated {
      entry { notCalib = true; }
      on [endStopEarly] / { endStopEarly = false; };      // already set: consume the report
      // "Flag is cleared when the master requests CLEAR_NOT-CALIB" (Table C.7), and, per
      // D.3.2.3, it "remains set until all (except bit #3) failure flags are cleared and the
      // master task has required the run mode CLEAR_NOT-CALIB".
      on [runMode == CLEAR_NOT_CALIB && !in(failureHandler.failure)] -> calibrated;
    }
  }
}
