// master_policy.sc — the hand-written master of the thesis (App. D, our `lib/master.sc`)
// abstracted to the events of `runmode.sc`: which command it sends in each situation. It is a
// supervisor in the bridge form of docs/synthesis.md (one free input `ev`, the event proposed
// this tick; output `fire`, the event that occurs), so the independent checker can judge it:
//
//   statecheck verify examples/fam/synthesis/master_policy.sc \
//       --plant examples/fam/synthesis/runmode.sc
//
// and `run.sh` composes it with the synthesized supervisor to check that every event the master
// lets happen, the supervisor lets happen too.
//
// How lib/master.sc becomes an event policy:
// * The master decides once per round from the latest response. Here it decides after every
//   event, on the state that event leaves (what the next response reports): the master sees
//   every flag before its next request. (In the bus model a flag can rise between a response and
//   the next request; the FAM's own inhibition covers that gap, ch. 5.4.)
// * The phases, their order of evaluation and the counters are lib/master.sc's: failure before
//   stall (`bitCheck` before `calibAndStall`), FBF counted once per occurrence (4 retries in the
//   same direction, then the opposite direction once, then FAILURE_RUN until power off), HSL
//   counted per STOP_FAILURE round it survives (2 rounds, then FAILURE_RUN), COF cleared with
//   the lowest priority (STOP_FAILURE only while resting at the target), calibration with one
//   bounce step, a gray-zone stall (`endStop`) is a new end reference, a hard flap point
//   (`stall`) is backed off from.
// * A phase's request is sent again every round; only a request that differs from the held one
//   is an event. NORMAL, FBF_RUN and the FAILURE_RUN phases follow the CCM, which may change at
//   any time: their run command stays enabled. CALIB, BACKOFF and FBF_OPP aim at one fixed
//   target: one `normalRun` per step (`sent`). FAIL_WAIT re-sends STOP_FAILURE every round:
//   `stopFailure` stays enabled, and each one is a round for the HSL count.
// * The target positions, the gray zone arithmetic and the swap flag are gone (runmode.sc has
//   no positions); "the move of this phase reached its target" is the event `arrive`.

enum Event { none, normalRun, failureRun, stopStall, stopFailure, clearNotCalib, arrive, stall, endStop, hslOn, hslPermanent, otfOn, ccfOn, fbf, epm, powerLoss, powerLossNoSave, hslOff, otfOff, cof }

// lib/master.sc's phases.
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
  BACKOFF,       // D.3.2.2: hard flap point: move backwards, then on
}

// The master's picture of the FAM, one value per automaton of runmode.sc.
enum DriveLoc { AT_TARGET, HALTED, RUNNING, FAILURE_RUNNING }
enum HslLoc { HSL_CLEAR, HSL_SET, HSL_CAUSE_GONE, HSL_PERMANENT }
enum OtfLoc { OTF_CLEAR, OTF_SET, OTF_CAUSE_GONE }
enum CalLoc { CAL_OK, CAL_LOST, CAL_REFERENCED, CAL_LOST_FOR_GOOD }

const FBF_RETRIES: int = 4;   // D.3.2.3 bit 2: "Repeat this routine 4 times"
const HSL_ROUNDS: int = 2;    // D.3.2.3 bit 7: rounds before "permanent" (lib/master.sc)
const MAX_BOUNCE: int = 1;    // lib/master.sc's bound on bounce steps
// lib/master.sc handles a failure before a pending stall (the thesis's master_failure_before_stall)
// and then resumes the stall procedure: a stall at an end stop found *before* the failure still
// counts as the calibration stall, and CLEAR_NOT_CALIB follows without a calibration move after
// the failure (runmode.sc's requirement 4 is violated; see docs/synthesis.md). `true` makes a
// failure cancel the pending reference, so that the failure's notCalib leads to a calibration.
const FORGET_REFERENCE_ON_FAILURE: bool = false;
// lib/master.sc stays in FAILURE_RUN "until power off" once it assumes a failure permanent (bit 7
// after HSL_ROUNDS, bit 2 after the retries): it never sends STOP_STALL or STOP_FAILURE again,
// so a stall pending at that moment, an HSL whose cause did go away, the FBF flag (STOP_FAILURE
// clears it; the master assumes it would recur) or a later COF stay set for ever — blocking in
// the supervisory-control sense. `true` keeps acknowledging and clearing in those phases and
// leaves them once no major flag is left (to the stall procedure if a stall is pending, else
// to calibration, as the general solution's wait ends).
const RETRY_IN_FAILURE_RUN: bool = false;

fn running(d: DriveLoc) -> bool = d == RUNNING || d == FAILURE_RUNNING;
fn stopped(d: DriveLoc) -> bool = d == AT_TARGET || d == HALTED;
// A move stops at once on a stall or a major failure in the closed loop, never in FAILURE_RUN.
fn haltClosed(d: DriveLoc) -> DriveLoc = if d == RUNNING then HALTED else d;
// Every failure but COF sets notCalib (C.2.2.4); a permanent HSL keeps it for good.
fn lose(c: CalLoc) -> CalLoc = if c == CAL_LOST_FOR_GOOD then c else CAL_LOST;

chart MasterPolicy {
  input ev: Event;
  output fire: Event = Event.none;
  output phase: Phase = NORMAL;

  local drive: DriveLoc = AT_TARGET;
  local stalled: bool = false;
  local hsl: HslLoc = HSL_CLEAR;
  local otf: OtfLoc = OTF_CLEAR;
  local fbfSet: bool = false;
  local lossSet: bool = false;
  local cofSet: bool = false;
  local cal: CalLoc = CAL_OK;

  local fbfCount: int[0..6] = 0;     // bit-2 occurrences in a row
  local hslRounds: int[0..2] = 0;    // STOP_FAILURE rounds bit 7 survived
  local bounces: int[0..1] = 0;
  local grayStall: bool = false;     // the stall being acknowledged was at an end stop
  local lastGray: bool = false;      // the latest stall was at an end stop
  local sent: bool = false;          // CALIB, BACKOFF, FBF_OPP: this step's move is requested
  local major: bool = false;

  initial Run;
  state Run {
    during {
      major = hsl != HSL_CLEAR || otf != OTF_CLEAR || fbfSet || lossSet;
      fire = Event.none;

      // --- Does the proposed event occur? --------------------------------------------------
      // The FAM's events: whenever runmode.sc's plant can do them.
      if ev == Event.arrive && running(drive) { fire = ev; }
      if (ev == Event.stall || ev == Event.endStop) && drive == RUNNING && !stalled { fire = ev; }
      if (ev == Event.hslOn || ev == Event.hslPermanent)
         && (hsl == HSL_CLEAR || hsl == HSL_CAUSE_GONE) { fire = ev; }
      if ev == Event.hslOff && hsl == HSL_SET { fire = ev; }
      if ev == Event.otfOn && (otf == OTF_CLEAR || otf == OTF_CAUSE_GONE) { fire = ev; }
      if ev == Event.ccfOn && (otf == OTF_CLEAR || otf == OTF_CAUSE_GONE) && stopped(drive) {
        fire = ev;
      }
      if ev == Event.otfOff && otf == OTF_SET { fire = ev; }
      if ev == Event.fbf && drive == RUNNING && !fbfSet { fire = ev; }
      if ev == Event.epm && stopped(drive) { fire = ev; }
      if ev == Event.powerLoss && running(drive) { fire = ev; }
      if ev == Event.powerLossNoSave || ev == Event.cof { fire = ev; }
      // The master's commands: the request of its phase (lib/master.sc `commit`).
      if ev == Event.normalRun
         && (phase == NORMAL || phase == FBF_RUN
             || ((phase == CALIB || phase == BACKOFF || phase == FBF_OPP) && !sent)) {
        fire = ev;
      }
      if ev == Event.failureRun && (phase == HSL_PERM || phase == FBF_PERM) { fire = ev; }
      if ev == Event.stopStall
         && (phase == STALL_ACK
             || (RETRY_IN_FAILURE_RUN && (phase == HSL_PERM || phase == FBF_PERM) && stalled)) {
        fire = ev;
      }
      // Bit 3 has the lowest priority: cleared only once the actuator rests at its target.
      if ev == Event.stopFailure
         && (phase == FAIL_WAIT || (phase == NORMAL && cofSet && drive == AT_TARGET)
             || (RETRY_IN_FAILURE_RUN && (phase == HSL_PERM || phase == FBF_PERM)
                 && (major || cofSet))) {
        fire = ev;
      }
      // The FAM refuses CLEAR_NOT_CALIB while a major failure is set (runmode.sc).
      if ev == Event.clearNotCalib && phase == CLEAR_CALIB && !major { fire = ev; }

      // --- The FAM's response to it (runmode.sc's transitions) -------------------------------
      if fire == Event.normalRun { drive = RUNNING; }
      if fire == Event.failureRun { drive = FAILURE_RUNNING; }
      if fire == Event.stopStall {
        if running(drive) { drive = HALTED; }
        stalled = false;
      }
      if fire == Event.stopFailure {
        if running(drive) { drive = HALTED; }
        if hsl == HSL_CAUSE_GONE { hsl = HSL_CLEAR; }
        if otf == OTF_CAUSE_GONE { otf = OTF_CLEAR; }
        fbfSet = false; lossSet = false; cofSet = false;
      }
      if fire == Event.clearNotCalib {
        if drive == FAILURE_RUNNING { drive = RUNNING; }
        cal = CAL_OK;
      }
      if fire == Event.arrive { drive = AT_TARGET; }
      if fire == Event.stall || fire == Event.endStop {
        drive = HALTED; stalled = true;
        lastGray = fire == Event.endStop;
        if fire == Event.endStop && cal == CAL_LOST { cal = CAL_REFERENCED; }
      }
      if fire == Event.hslOn { drive = haltClosed(drive); hsl = HSL_SET; cal = lose(cal); }
      if fire == Event.hslPermanent {
        drive = haltClosed(drive); hsl = HSL_PERMANENT; cal = CAL_LOST_FOR_GOOD;
      }
      if fire == Event.hslOff { hsl = HSL_CAUSE_GONE; }
      if fire == Event.otfOn || fire == Event.ccfOn {
        drive = haltClosed(drive); otf = OTF_SET; cal = lose(cal);
      }
      if fire == Event.otfOff { otf = OTF_CAUSE_GONE; }
      if fire == Event.fbf { drive = HALTED; fbfSet = true; cal = lose(cal); }
      if fire == Event.epm { lossSet = true; cal = lose(cal); }
      if fire == Event.powerLoss || fire == Event.powerLossNoSave {
        drive = HALTED; lossSet = true; cal = lose(cal);
      }
      // lib/master.sc decides "gray zone or hard point" from the reported position; after a failed
      // save that is 0x800, outside both gray zones.
      if fire == Event.powerLossNoSave { lastGray = false; }
      if fire == Event.cof { cofSet = true; }

      // --- The master's next decision (lib/master.sc) ----------------------------------------
      if fire == Event.normalRun && (phase == CALIB || phase == BACKOFF || phase == FBF_OPP) {
        sent = true;
      }
      major = hsl != HSL_CLEAR || otf != OTF_CLEAR || fbfSet || lossSet;
      if fire != Event.none && major {
        // failureHandler -> bitCheck: the exceptions for bits 2 and 7, then the general solution.
        if phase == HSL_PERM || phase == FBF_PERM {
          // FAILURE_RUN until power off
        } else if fbfSet && phase != FAIL_WAIT {
          fbfCount = min(fbfCount + 1, FBF_RETRIES + 2);
          if fbfCount == FBF_RETRIES + 2 { phase = FBF_PERM; }
          else { phase = FAIL_WAIT; hslRounds = 0; }
        } else if hsl != HSL_CLEAR && phase == FAIL_WAIT && fire == Event.stopFailure {
          hslRounds = min(hslRounds + 1, HSL_ROUNDS);
          if hslRounds == HSL_ROUNDS { phase = HSL_PERM; }
        } else if phase != FAIL_WAIT {
          phase = FAIL_WAIT; hslRounds = 0;
        }
        if FORGET_REFERENCE_ON_FAILURE { lastGray = false; }
      } else if fire != Event.none && (stalled || cal != CAL_OK || phase != NORMAL) {
        // calibAndStall
        if RETRY_IN_FAILURE_RUN && (phase == HSL_PERM || phase == FBF_PERM) {
          // every major flag is cleared after all: end as the general solution's wait ends
          fbfCount = 0;
          phase = FAIL_WAIT;
        }
        if phase == HSL_PERM || phase == FBF_PERM {
          // FAILURE_RUN until power off
        } else if stalled && phase != STALL_ACK {
          grayStall = lastGray;
          phase = STALL_ACK;
        } else if phase == STALL_ACK {
          if !stalled {
            if !grayStall { phase = BACKOFF; sent = false; }
            else if cal != CAL_OK { phase = CLEAR_CALIB; }
            else { phase = NORMAL; }
          }
        } else if phase == CLEAR_CALIB {
          if cal == CAL_OK { phase = NORMAL; bounces = 0; }
        } else if phase == FAIL_WAIT {
          // the flags are cleared
          if fbfCount >= 1 && fbfCount <= FBF_RETRIES { phase = FBF_RUN; }
          else if fbfCount == FBF_RETRIES + 1 { phase = FBF_OPP; sent = false; }
          else if cal != CAL_OK { phase = CALIB; bounces = 0; sent = false; }
          else { phase = NORMAL; }
        } else if (phase == FBF_RUN || phase == FBF_OPP) && fire == Event.arrive {
          fbfCount = 0;
          phase = NORMAL;
        } else if phase == BACKOFF {
          if fire == Event.arrive && sent { phase = NORMAL; }
        } else if phase == CALIB {
          if fire == Event.arrive && sent {
            // no stall at the end stop: the flap bounced (D.3.2.1 note)
            if bounces < MAX_BOUNCE { bounces += 1; sent = false; }
            else { phase = NORMAL; bounces = 0; }
          }
        } else if phase == NORMAL && cal != CAL_OK {
          phase = CALIB; bounces = 0; sent = false;
        }
      }
    }
  }
}

// The master with its own picture of the FAM: `statecheck verify master_policy.sc` proves what it
// never does although the synthesized supervisor allows it (docs/synthesis.md).
system MasterLoop {
  instance master: MasterPolicy;

  // It moves in FAILURE_RUN only while a major failure is set: never to push through a stall
  // alone (D.3.2.2's alternative recommendation), never with the flags cleared.
  invariant master_failure_run_only_on_failure:
    master.drive != FAILURE_RUNNING || master.major;
  // After a calibration stall it sends CLEAR_NOT_CALIB before any new move.
  invariant master_clears_before_moving:
    !(master.cal == CAL_REFERENCED && master.drive == RUNNING);
}
