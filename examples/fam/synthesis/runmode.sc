// runmode.sc — the FAM's run-mode behaviour as a supervisory-control plant (Ramadge–Wonham), and
// the forbidden states of the thesis as requirements. `statecheck synth` computes the maximally
// permissive run-mode supervisor; `master_policy.sc` is the hand-written master of App. D over the
// same events, for the comparison (docs/synthesis.md, "FAM run-mode supervisor").
//
// Source: ../../../../shared/seeds/fam-stepper-supervisor-thesis.txt — App. C (Table C.2 run modes,
// Table C.3 what each mode does while running / stopped, Table C.7 STALL and NOT-CALIB, C.2.2.4
// and Tables C.8/C.9 failure flags), App. D.3.2 (calibration, stall, failure procedures), ch. 5.3
// (the forbidden states: "Can the FAM be in stall-mode and still be running?", "... in
// failure-mode and still be running?" — possible only with FAILURE_RUN).
//
// ---------------------------------------------------------------------------------------------
// The event view. `fam.sc` is a tick model with a 12-bit position, eight run modes and a failure
// register; here only what decides *which command may be sent when* is kept:
//
// * An event is a change. The master sends a request every round (Fig. D.1); a request equal to
//   the one the FAM already holds changes nothing and is not an event. So `normalRun` means "a
//   NORMAL_RUN request with a new target" (a move start or a retarget), and `stopFailure` is
//   one STOP_FAILURE request (the master repeats it every round while it waits, each repetition
//   is another `stopFailure`: that is when the FAM clears the flags whose cause is gone).
// * Commands are controllable: the master may always decline to send them.
//     normalRun      NORMAL_RUN, NORMAL_RUN_FIXED_LOW, NORMAL_RUN_LOW, NORMAL_RUN_HIGH with a new
//                    target (Table C.2 b010, b011, b101, b111). The four closed-loop modes
//                    differ only in speed (Table C.3): one event. Whether the target is a CCM
//                    target (Eq. D.1), a calibration target past the end stop (D.3.2.1) or a
//                    back-off target (D.3.2.2) is the master's business; the FAM does the same.
//     failureRun     FAILURE_RUN (b100) with a target: open loop, no stall detection, "no
//                    inhibition to run in this mode" (Table C.3).
//     stopStall      STOP_STALL (b000): stops; clears (acknowledges) the stall flag.
//     stopFailure    STOP_FAILURE (b001): stops; clears the failure flags whose cause is gone.
//     clearNotCalib  CLEAR_NOT_CALIB (b110): clears notCalib.
// * What the FAM and its environment do is uncontrollable:
//     arrive         the move reaches its target (RUN flag cleared, Table C.7).
//     stall          stall detected at a hard flap point, outside the gray zone (D.3.2.2).
//     endStop        stall detected at an end stop (inside the gray zone, D.3.2.2; what a
//                    calibration move looks for, D.3.2.1).
//     hslOn          bit 7 HSL: hall-sensor supply current above its limit, cause transient.
//     hslPermanent   bit 7 HSL whose cause stays for ever (D.3.2.3: "assume that this failure
//                    is permanent" is the one failure the thesis treats as possibly permanent).
//     hslOff         the HSL cause goes away (the flag stays set until STOP_FAILURE, Table C.9).
//     otfOn          bit 4 OTF: over-voltage or over-temperature (any time).
//     ccfOn          bit 1 CCF: open coil circuit (only while stopped, Table C.9).
//     otfOff         the OTF/CCF cause goes away (cool-down, voltage back, coil closed).
//     fbf            bit 2 FBF: hall feedback lost; only while running with feedback, i.e. not
//                    in FAILURE_RUN ("hall sensor feedback is disabled", Table C.9 bit 7).
//     epm            bit 5 EPM: the stopped actuator cannot hold its position.
//     powerLoss      U_bat < 8 V while running: the actuator resets and stops, bit 0 CPF.
//     powerLossNoSave  a reset whose position save failed: position 0x800, bit 6 DPR (the FAM
//                    is no longer at its target). A power loss while stopped whose save works
//                    changes nothing and is not an event.
//     cof            bit 3 COF: a corrupted request frame. The frame is scrapped, so the command
//                    it carried simply does not happen.
//
// Failure classes. What the supervisor can see a difference in is: does the flag inhibit a
// normal run (all but COF, C.2.2.4), when can it appear, and does STOP_FAILURE clear it at once
// or only once its cause is gone (Table C.9). That gives five automata:
//     hslFlag   bit 7            cause-held; the cause can be permanent
//     otfFlag   bits 4 and 1     cause-held, cause transient (OTF and CCF share the automaton,
//                                 which tracks one cause: with both present, one `otfOff` lets
//                                 STOP_FAILURE clear both — a simplification; the guards only
//                                 ever ask whether the flag is set)
//     fbfFlag   bit 2            cleared by STOP_FAILURE; occurs only in a closed-loop move
//     lossFlag  bits 5, 6 and 0  EPM, DPR, CPF: cleared by STOP_FAILURE
//     cofFlag   bit 3            cleared by STOP_FAILURE; does not inhibit anything
//
// What the plant deliberately leaves OUT is the FAM's own start inhibition: Table C.3 says the
// FAM refuses a normal run "if the motor is in failure (except communication failure) or if
// stall detection is not acknowledged". Here `normalRun` always starts a closed-loop move, so a
// normal run commanded while stalled or failed *would* run: the forbidden states of ch. 5.3 are
// reachable in the plant, and the supervisor has to find the inhibition rule itself. What the
// plant keeps is what no command can prevent: a detected stall or a major failure stops a
// closed-loop move at once (Table C.7 STALL, C.2.2.4, Table C.9 "the actuator stops"), and
// FAILURE_RUN is never stopped by a flag (Table C.3, as fam.sc's mayContinue).
//
// Abstractions, each an over- or an under-approximation as said:
// * positions, speeds, swap and the CCM are gone; "at target" is a location of `drive`.
// * the FAM stops and clears at once: "flag is cleared when the motor has stopped completely"
//   (Table C.3) becomes one event (STOP_STALL/STOP_FAILURE while running stops and clears).
// * CLEAR_NOT_CALIB: the FAM keeps notCalib while a major failure is set (D.3.2.3); here the
//   command is refused (not an event) while one is set. While running it "only clears the
//   flag" (Table C.3), and, as in fam.sc, a FAILURE_RUN move continues in the closed loop.
// * notCalib is also set by an end stop after a move shorter than 20 positions (Table C.7);
//   not modelled (positions are gone). With it (an uncontrollable `stallShort` that sets the
//   stall flag and notCalib) the supervisor has the same 456 states and guards and 6 more
//   transitions: it only adds ways into states that failures reach anyway.
// * nonblocking is reachability: "the cause may go away" (hslOff, otfOff) and "the stall may be
//   at the end stop" are possibilities, not guarantees; there is no fairness.

// --- The drive: stopped at target / stopped short of it / running closed-loop / running open-loop.
plant chart Drive {
    controllable event normalRun;
    controllable event failureRun;
    controllable event stopStall;
    controllable event stopFailure;
    controllable event clearNotCalib;
    uncontrollable event arrive;
    uncontrollable event stall;
    uncontrollable event endStop;
    uncontrollable event hslOn;
    uncontrollable event hslPermanent;
    uncontrollable event otfOn;
    uncontrollable event ccfOn;
    uncontrollable event fbf;
    uncontrollable event epm;
    uncontrollable event powerLoss;
    uncontrollable event powerLossNoSave;
    initial AtTarget;
    // The task is done when the actuator rests at the target it was sent to.
    marked state AtTarget {
        on normalRun -> Running;
        on failureRun -> FailureRunning;
        on stopStall; on stopFailure; on clearNotCalib;
        on hslOn; on hslPermanent; on otfOn; on ccfOn; on epm;
        on powerLossNoSave -> Halted;       // position 0x800: no longer at the target
    }
    // Stopped before its target: by a stall, a failure, a stop request or a power loss.
    state Halted {
        on normalRun -> Running;
        on failureRun -> FailureRunning;
        on stopStall; on stopFailure; on clearNotCalib;
        on hslOn; on hslPermanent; on otfOn; on ccfOn; on epm;
        on powerLossNoSave;
    }
    // A closed-loop run mode (normal runs; a move continued under CLEAR_NOT_CALIB): stall
    // detection on (Table C.3), and a stall or a major failure stops the motor.
    state Running {
        on normalRun;                         // a new target: keep moving (Table C.3)
        on failureRun -> FailureRunning;
        on stopStall -> Halted;
        on stopFailure -> Halted;
        on clearNotCalib;
        on arrive -> AtTarget;
        on stall -> Halted;
        on endStop -> Halted;
        on hslOn -> Halted; on hslPermanent -> Halted; on otfOn -> Halted; on fbf -> Halted;
        on powerLoss -> Halted; on powerLossNoSave -> Halted;
    }
    // FAILURE_RUN: no stall detection, no feedback (so no FBF), never stopped by a flag.
    state FailureRunning {
        on normalRun -> Running;
        on failureRun;
        on stopStall -> Halted;
        on stopFailure -> Halted;
        on clearNotCalib -> Running;          // CLEAR_NOT_CALIB is a closed-loop mode (fam.sc)
        on arrive -> AtTarget;
        on hslOn; on hslPermanent; on otfOn;
        on powerLoss -> Halted; on powerLossNoSave -> Halted;
    }
}

// --- STALL flag (DB1_RES bit 6, Table C.7): set by a detected stall, cleared by STOP_STALL.
plant chart StallFlag {
    uncontrollable event stall;
    uncontrollable event endStop;
    controllable event stopStall;
    initial Clear;
    marked state Clear { on stall -> Set; on endStop -> Set; on stopStall; }
    state Set { on stopStall -> Clear; }
}

// --- HSL (bit 7): cleared by STOP_FAILURE only once the current is below the limit.
plant chart HslFlag {
    uncontrollable event hslOn;
    uncontrollable event hslPermanent;
    uncontrollable event hslOff;
    controllable event stopFailure;
    controllable event clearNotCalib;
    initial Clear;
    marked state Clear {
        on hslOn -> Set; on hslPermanent -> Permanent;
        on stopFailure; on clearNotCalib;
    }
    state Set { on hslOff -> CauseGone; on stopFailure; }
    state CauseGone { on stopFailure -> Clear; on hslOn -> Set; on hslPermanent -> Permanent; }
    // The flag can never be cleared: a task can be complete with it set.
    marked state Permanent { on stopFailure; }
}

// --- OTF (bit 4) and CCF (bit 1): cleared by STOP_FAILURE once the cause has disappeared.
plant chart OtfFlag {
    uncontrollable event otfOn;
    uncontrollable event ccfOn;
    uncontrollable event otfOff;
    controllable event stopFailure;
    controllable event clearNotCalib;
    initial Clear;
    marked state Clear { on otfOn -> Set; on ccfOn -> Set; on stopFailure; on clearNotCalib; }
    state Set { on otfOff -> CauseGone; on stopFailure; }
    state CauseGone { on stopFailure -> Clear; on otfOn -> Set; on ccfOn -> Set; }
}

// --- FBF (bit 2): cleared by STOP_FAILURE.
plant chart FbfFlag {
    uncontrollable event fbf;
    controllable event stopFailure;
    controllable event clearNotCalib;
    initial Clear;
    marked state Clear { on fbf -> Set; on stopFailure; on clearNotCalib; }
    state Set { on stopFailure -> Clear; }
}

// --- EPM (bit 5), DPR (bit 6), CPF (bit 0): cleared by STOP_FAILURE.
plant chart LossFlag {
    uncontrollable event epm;
    uncontrollable event powerLoss;
    uncontrollable event powerLossNoSave;
    controllable event stopFailure;
    controllable event clearNotCalib;
    initial Clear;
    marked state Clear {
        on epm -> Set; on powerLoss -> Set; on powerLossNoSave -> Set;
        on stopFailure; on clearNotCalib;
    }
    state Set { on epm; on powerLoss; on powerLossNoSave; on stopFailure -> Clear; }
}

// --- COF (bit 3): cleared by STOP_FAILURE; "will not affect any other functionality".
plant chart CofFlag {
    uncontrollable event cof;
    controllable event stopFailure;
    initial Clear;
    marked state Clear { on cof -> Set; on stopFailure; }
    state Set { on cof; on stopFailure -> Clear; }
}

// --- NOT-CALIB (DB1_RES bit 7, Table C.7), refined by its history: `Lost` and `Referenced`
// both mean "notCalib set"; `Referenced` records that an end stop has been found since the
// position was lost, which is what calibration is for (D.3.2.1). Every failure but COF sets
// the flag (C.2.2.4); the FAM clears it on CLEAR_NOT_CALIB whatever the history.
plant chart NotCalib {
    uncontrollable event hslOn;
    uncontrollable event hslPermanent;
    uncontrollable event otfOn;
    uncontrollable event ccfOn;
    uncontrollable event fbf;
    uncontrollable event epm;
    uncontrollable event powerLoss;
    uncontrollable event powerLossNoSave;
    uncontrollable event endStop;
    controllable event clearNotCalib;
    initial Ok;
    marked state Ok {
        on hslOn -> Lost; on otfOn -> Lost; on ccfOn -> Lost; on fbf -> Lost; on epm -> Lost;
        on powerLoss -> Lost; on powerLossNoSave -> Lost;
        on hslPermanent -> LostForGood;
        on endStop; on clearNotCalib;
    }
    state Lost {
        on hslOn; on otfOn; on ccfOn; on fbf; on epm; on powerLoss; on powerLossNoSave;
        on hslPermanent -> LostForGood;
        on endStop -> Referenced;
        on clearNotCalib -> Ok;               // the FAM obeys; requirement 4 says when to ask
    }
    state Referenced {
        on hslOn -> Lost; on otfOn -> Lost; on ccfOn -> Lost; on fbf -> Lost; on epm -> Lost;
        on powerLoss -> Lost; on powerLossNoSave -> Lost;
        on hslPermanent -> LostForGood;
        on endStop;
        on clearNotCalib -> Ok;
    }
    // A permanent HSL keeps notCalib set for ever (D.3.2.3): marked, as `hslFlag.Permanent`.
    marked state LostForGood {
        on hslOn; on otfOn; on ccfOn; on fbf; on epm; on powerLoss; on powerLossNoSave; on endStop;
    }
}

system RunMode {
    instance drive: Drive;
    instance stallFlag: StallFlag;
    instance hslFlag: HslFlag;
    instance otfFlag: OtfFlag;
    instance fbfFlag: FbfFlag;
    instance lossFlag: LossFlag;
    instance cofFlag: CofFlag;
    instance notCalib: NotCalib;

    // 1. fam_stall_blocks_run (ch. 5.3): never stalled and running, except in FAILURE_RUN.
    requirement never (in(drive.Running) && in(stallFlag.Set));

    // 2. fam_failure_blocks_run (ch. 5.3): never a failure (any flag but COF, C.2.2.4) and
    //    running, except in FAILURE_RUN.
    requirement never (in(drive.Running)
        && (!in(hslFlag.Clear) || !in(otfFlag.Clear) || in(fbfFlag.Set) || in(lossFlag.Set)));

    // 3. FAILURE_RUN is the exception, not a way of running: only while a normal run is
    //    inhibited, by a stall or a failure (Table C.3: "This mode could be used when the motor
    //    is in failure, which can not be cleared"; D.3.2.2: push through a hard flap point in
    //    FAILURE_RUN, then STOP_STALL).
    requirement failureRun needs (in(stallFlag.Set)
        || !in(hslFlag.Clear) || !in(otfFlag.Clear) || in(fbfFlag.Set) || in(lossFlag.Set));

    // 4. The position is declared accurate only after it has been referenced at an end stop
    //    since it was lost (D.3.2.1: "When the stall flag has been reset by the stall
    //    procedure, the master should request the run mode CLEAR_NOT-CALIB").
    requirement clearNotCalib needs (!in(notCalib.Lost));
}
