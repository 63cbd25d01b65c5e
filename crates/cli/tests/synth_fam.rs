//! The FAM run-mode supervisor end to end (docs/synthesis.md, "FAM run-mode supervisor"):
//! `statecheck synth` on `examples/fam/synthesis/runmode.sc` with both engines, the independent
//! supervisor check, and the comparison with the hand-written master (`master_policy.sc`,
//! `containment.part`).

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_statecheck"))
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../../examples/fam/synthesis/{name}"))
}

/// A scratch directory removed at the end of the test.
struct Scratch(PathBuf);

impl Scratch {
    fn new(tag: &str) -> Scratch {
        let d =
            std::env::temp_dir().join(format!("statecheck-synth-fam-{tag}-{}", std::process::id()));
        std::fs::create_dir_all(&d).expect("temp dir");
        Scratch(d)
    }
    fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Run the binary; (exit code, stdout).
fn run(args: &[&Path]) -> (i32, String) {
    let o = bin().args(args).output().expect("runs");
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    let err = String::from_utf8_lossy(&o.stderr);
    (o.status.code().unwrap_or(-1), format!("{out}{err}"))
}

fn p(s: &str) -> &Path {
    Path::new(s)
}

/// Synthesize the supervisor with `engine` into `out`; returns stdout.
fn synth(engine: &str, out: &Path) -> String {
    let model = example("runmode.sc");
    let (code, stdout) = run(&[
        p("synth"),
        &model,
        p("--engine"),
        p(engine),
        p("--check"),
        p("-o"),
        out,
    ]);
    assert_eq!(code, 0, "{stdout}");
    stdout
}

// The supervisor's size, derived by hand from runmode.sc (before the tool was run).
//
// States. The supervisor keeps every reachable state that is not forbidden: no blocking state
// has to be removed, because from every state a cause may go away (`hslOff`, `otfOff`),
// STOP_FAILURE/STOP_STALL clear what can be cleared, a normal run can meet the end stop
// (`endStop`), and FAILURE_RUN moves while a failure is set. Reachable combinations, with
// "major" = hslFlag, otfFlag, fbfFlag or lossFlag not Clear:
// - no major flag: notCalib is Ok, Lost or Referenced (3); (drive, stallFlag) is (AtTarget,
//   Clear), (Halted, Clear), (Running, Clear), (AtTarget, Set), (Halted, Set),
//   (FailureRunning, Set) (6: Running while stalled is forbidden, FailureRunning is only
//   allowed while stalled or failed and no flag clears while it runs); cofFlag 2:
//   3 * 6 * 2 = 36.
// - some major flag: notCalib is LostForGood if hslFlag is Permanent, else Lost (determined);
//   drive is AtTarget, Halted or FailureRunning (3); cofFlag 2; hslFlag 4 * otfFlag 3 *
//   lossFlag 2 = 24 combinations. With fbfFlag Clear (23, the all-Clear one has no major
//   flag) stallFlag is free (2): 23 * 2 * 3 * 2 = 276. With fbfFlag Set stallFlag is Clear
//   (an FBF needs a closed-loop move, which a stall forbids, and a stall needs one, which the
//   FBF forbids): 24 * 1 * 3 * 2 = 144.
// Total 36 + 276 + 144 = 456.
//
// Transitions: the events the supervisor allows, summed over those states.
// - no major flag: 7 events in every state (hslOn, hslPermanent, otfOn, powerLossNoSave, cof,
//   stopStall, stopFailure), 1 of normalRun/failureRun (normalRun when the stall flag is
//   Clear, else failureRun), plus by drive state: AtTarget, Halted 2 (ccfOn, epm), Running 5
//   (arrive, stall, endStop, fbf, powerLoss), FailureRunning 2 (arrive, powerLoss). Over the
//   6 (drive, stall) pairs: 10 + 10 + 13 + 10 + 10 + 10 = 63, plus clearNotCalib in the 5
//   pairs other than FailureRunning when notCalib is Ok or Referenced: 63 * 3 + 5 * 2 = 199,
//   times cofFlag 2 = 398.
// - some major flag: 5 events in every state (failureRun, stopStall, stopFailure,
//   powerLossNoSave, cof), 1 for otf (otfOn unless Set, then otfOff), h for hsl (hslOn and
//   hslPermanent unless Set or Permanent: 2 for Clear and CauseGone, hslOff: 1 for Set, 0 for
//   Permanent), and by drive: AtTarget, Halted 1 (epm) + 1 (ccfOn unless otf Set),
//   FailureRunning 2 (arrive, powerLoss). Summed over the 3 drive states: 18 + 3h + (6 if otf
//   is not Set else 4). Summed over hsl and otf: 88 + 79 + 88 + 70 = 325. Times the rest:
//   fbf and loss Clear (325 - 30 for the all-Clear combination) * 2 (stall) * 2 (cof) = 1180;
//   loss Set, fbf Clear 325 * 4 = 1300; fbf Set 325 * 2 for each loss value = 1300.
//   Total 3780.
// Total 398 + 3780 = 4178.
const STATES: u32 = 456;
const TRANSITIONS: u32 = 4178;

/// The guards the tool prints: Table C.3's inhibition for normalRun (derived from the forbidden
/// states: nothing in the model states it), requirement 3 for failureRun, and requirement 4
/// plus "not while pushing through a stall in FAILURE_RUN" for clearNotCalib.
const GUARDS: &[&str] = &[
    "  normalRun: in(stallFlag.Clear) && in(hslFlag.Clear) && in(otfFlag.Clear) && in(fbfFlag.Clear) && in(lossFlag.Clear)",
    "  failureRun: !(in(stallFlag.Clear) && in(hslFlag.Clear) && in(otfFlag.Clear) && in(fbfFlag.Clear) && in(lossFlag.Clear))",
    "  stopStall: true",
    "  stopFailure: true",
    "  clearNotCalib: ((in(drive.AtTarget) || in(drive.Halted)) && (in(notCalib.Ok) || in(notCalib.Referenced))) || (in(drive.Running) && (in(notCalib.Ok) || in(notCalib.Referenced)))",
];

#[test]
fn both_engines_give_the_hand_counted_supervisor() {
    let tmp = Scratch::new("engines");
    let mut texts = Vec::new();
    for engine in ["explicit", "symbolic"] {
        let out = tmp.path(&format!("sup_{engine}.sc"));
        let stdout = synth(engine, &out);
        assert!(
            stdout.contains(&format!(
                "supervisor: {STATES} states, {TRANSITIONS} transitions"
            )),
            "{engine}: {stdout}"
        );
        for g in GUARDS {
            assert!(
                stdout.lines().any(|l| l == *g),
                "{engine}: no `{g}` in\n{stdout}"
            );
        }
        // `--check`: the independent checker visits exactly the supervisor's states.
        assert!(
            stdout.contains(&format!("({STATES} plant states)")),
            "{engine}: {stdout}"
        );
        assert!(
            stdout.contains("supervisor check: controllable, nonblocking, requirements hold"),
            "{engine}: {stdout}"
        );
        texts.push(std::fs::read_to_string(&out).expect("written"));
    }
    assert_eq!(texts[0], texts[1], "the engines emit different supervisors");
}

#[test]
fn supervisor_passes_the_independent_check_and_its_own_properties() {
    let tmp = Scratch::new("check");
    let sup = tmp.path("sup.sc");
    synth("explicit", &sup);
    let model = example("runmode.sc");
    let (code, stdout) = run(&[p("verify"), &sup, p("--plant"), &model]);
    assert_eq!(code, 0, "{stdout}");
    assert!(
        stdout.contains(&format!("({STATES} plant states)"))
            && stdout.contains("controllable, nonblocking, requirements hold"),
        "{stdout}"
    );
    // Two automata mark two states each: each disjunction must be one group (it was not: `&&`
    // bound tighter than the `||` of hslFlag's and notCalib's marked states).
    let text = std::fs::read_to_string(&sup).expect("written");
    assert!(
        text.contains(
            "reachable all_marked: (in(drive.AtTarget)) && (in(stallFlag.Clear)) && \
             ((in(hslFlag.Clear)) || (in(hslFlag.Permanent))) && (in(otfFlag.Clear)) && \
             (in(fbfFlag.Clear)) && (in(lossFlag.Clear)) && (in(cofFlag.Clear)) && \
             ((in(notCalib.Ok)) || (in(notCalib.LostForGood)));"
        ),
        "{text}"
    );
    let v = verify_json(&[&sup]);
    for (name, verdict) in [
        ("mirror_drive", "proved"),
        ("mirror_notCalib", "proved"),
        ("never_1", "proved"),
        ("never_2", "proved"),
        ("all_marked", "reachable"),
    ] {
        assert_eq!(verdict_of(&v, name).0, verdict, "{name}: {v}");
    }
}

/// `statecheck verify ARGS --json`.
fn verify_json(args: &[&Path]) -> Value {
    let mut all: Vec<&Path> = vec![p("verify")];
    all.extend_from_slice(args);
    all.extend([p("--engine"), p("explicit"), p("--json")]);
    let (_, stdout) = run(&all);
    let json = stdout
        .lines()
        .filter(|l| l.starts_with('{'))
        .collect::<String>();
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {stdout}"))
}

/// (verdict, depth) of a property in `verify --json` output.
fn verdict_of(v: &Value, name: &str) -> (String, u64) {
    let r = v["results"]
        .as_array()
        .and_then(|rs| rs.iter().find(|r| r["property"] == name))
        .unwrap_or_else(|| panic!("no property {name}: {v}"));
    (
        r["verdict"].as_str().unwrap_or("").to_string(),
        r["depth"].as_u64().unwrap_or(0),
    )
}

/// master_policy.sc with the given constants set to true, written to `dir`.
fn master(tmp: &Scratch, name: &str, consts: &[&str]) -> PathBuf {
    let mut text = std::fs::read_to_string(example("master_policy.sc")).expect("reads");
    for c in consts {
        let from = format!("const {c}: bool = false;");
        assert!(text.contains(&from), "no `{from}`");
        text = text.replace(&from, &format!("const {c}: bool = true;"));
    }
    let path = tmp.path(&format!("{name}.sc"));
    std::fs::write(&path, text).expect("write");
    path
}

/// The kinds of violations `verify SUP --plant` reports (the text before " after "), and the
/// whole first line of each kind.
fn violations(stdout: &str) -> Vec<(String, String)> {
    let mut kinds: Vec<(String, String)> = Vec::new();
    for l in stdout.lines().filter(|l| l.starts_with("violation: ")) {
        let kind = l.split(" after ").next().unwrap_or(l).to_string();
        if !kinds.iter().any(|(k, _)| *k == kind) {
            kinds.push((kind, l.to_string()));
        }
    }
    kinds
}

const R4: &str = "violation: event `clearNotCalib` violates the requirements";
const BLOCKING: &str = "violation: blocking: no marked state can be reached";

#[test]
fn the_master_as_written_violates_requirement_4_and_blocks() {
    let tmp = Scratch::new("master");
    let m = master(&tmp, "master", &[]);
    let (code, stdout) = run(&[p("verify"), &m, p("--plant"), &example("runmode.sc")]);
    assert_eq!(code, 1, "{stdout}");
    let kinds = violations(&stdout);
    let names: Vec<&str> = kinds.iter().map(|(k, _)| k.as_str()).collect();
    // Nothing else: controllable, never in a forbidden state, FAILURE_RUN only when allowed.
    assert_eq!(names, [R4, BLOCKING], "{stdout}");
    // A stall at the end stop, a failure before it is acknowledged, the failure handled first:
    // the stale end stop then serves as the calibration (D.3.2.1, master_failure_before_stall).
    assert!(
        kinds[0].1.starts_with(&format!(
            "{R4} after normalRun endStop epm stopFailure stopStall ("
        )),
        "{stdout}"
    );
    // FAILURE_RUN "until power off": the stall pending when the HSL came is never acknowledged.
    assert!(
        kinds[1]
            .1
            .starts_with(&format!("{BLOCKING} after normalRun stall hslPermanent (")),
        "{stdout}"
    );
    // Measured, not derived: how many of the supervisor's 456 states the master reaches.
    assert!(stdout.contains("(410 plant states)"), "{stdout}");
}

#[test]
fn each_master_change_removes_one_finding() {
    let tmp = Scratch::new("variants");
    let model = example("runmode.sc");
    for (consts, expected, reached) in [
        (&["FORGET_REFERENCE_ON_FAILURE"][..], &[BLOCKING][..], 410),
        (&["RETRY_IN_FAILURE_RUN"][..], &[R4][..], 438),
        (
            &["FORGET_REFERENCE_ON_FAILURE", "RETRY_IN_FAILURE_RUN"][..],
            &[][..],
            438,
        ),
    ] {
        let m = master(&tmp, &consts.join("_"), consts);
        let (code, stdout) = run(&[p("verify"), &m, p("--plant"), &model]);
        let kinds = violations(&stdout);
        let names: Vec<&str> = kinds.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(names, expected, "{consts:?}: {stdout}");
        assert_eq!(code, if expected.is_empty() { 0 } else { 1 }, "{stdout}");
        assert!(
            stdout.contains(&format!("({reached} plant states)")),
            "{consts:?}: {stdout}"
        );
        if expected.is_empty() {
            assert!(
                stdout.contains("supervisor check: controllable, nonblocking, requirements hold"),
                "{stdout}"
            );
        }
    }
}

/// The master in series with the synthesized supervisor (containment.part).
fn containment(tmp: &Scratch, sup: &Path, master: &Path) -> PathBuf {
    let sup_text = std::fs::read_to_string(sup).expect("reads");
    let master_text = std::fs::read_to_string(master).expect("reads");
    let enum_line = |t: &str| {
        t.lines()
            .find(|l| l.starts_with("enum Event "))
            .map(str::to_string)
            .expect("an enum Event")
    };
    // The master declares the supervisor's alphabet itself, in the same order.
    assert_eq!(enum_line(&sup_text), enum_line(&master_text));
    let mut text: String = sup_text
        .lines()
        .filter(|l| !l.starts_with("enum Event "))
        .map(|l| format!("{l}\n"))
        .collect();
    text.push_str(&master_text);
    text.push_str(&std::fs::read_to_string(example("containment.part")).expect("reads"));
    let name = master.file_stem().and_then(|s| s.to_str()).unwrap_or("m");
    let path = tmp.path(&format!("containment_{name}.sc"));
    std::fs::write(&path, text).expect("write");
    path
}

#[test]
fn every_master_event_is_permitted_by_the_supervisor_except_the_stale_clear() {
    let tmp = Scratch::new("contain");
    let sup = tmp.path("sup.sc");
    synth("explicit", &sup);
    // As written: the one command the supervisor refuses is requirement 4's CLEAR_NOT_CALIB.
    let c = containment(&tmp, &sup, &master(&tmp, "as_written", &[]));
    let (code, stdout) = run(&[
        p("verify"),
        &c,
        p("--engine"),
        p("explicit"),
        p("--system"),
        p("Containment"),
    ]);
    assert_eq!(code, 1, "{stdout}");
    let v = verify_json(&[&c, p("--system"), p("Containment")]);
    assert_eq!(
        verdict_of(&v, "master_within_supervisor"),
        ("violated".to_string(), 7),
        "{v}"
    );
    let last = stdout
        .lines()
        .find(|l| l.trim_start().starts_with("6  master: Run"))
        .unwrap_or_else(|| panic!("no tick 6 in\n{stdout}"));
    assert!(
        // A connected signal is shown once, named by its connection (docs/tools.md).
        last.contains("master.fire->sup.ev=clearNotCalib") && last.contains("sup.fire=none"),
        "{last}"
    );
    // With a failure cancelling the pending reference, every master event is permitted, with
    // and without retrying in FAILURE_RUN.
    for consts in [
        &["FORGET_REFERENCE_ON_FAILURE"][..],
        &["FORGET_REFERENCE_ON_FAILURE", "RETRY_IN_FAILURE_RUN"][..],
    ] {
        let c = containment(&tmp, &sup, &master(&tmp, &consts.join("_"), consts));
        let v = verify_json(&[&c, p("--system"), p("Containment")]);
        assert_eq!(
            verdict_of(&v, "master_within_supervisor").0,
            "proved",
            "{consts:?}: {v}"
        );
    }
}

#[test]
fn the_master_is_more_restrictive_than_the_supervisor() {
    let tmp = Scratch::new("restrictive");
    // What the master never does (its own system) ...
    let v = verify_json(&[&example("master_policy.sc")]);
    for name in [
        "master_failure_run_only_on_failure",
        "master_clears_before_moving",
    ] {
        assert_eq!(verdict_of(&v, name).0, "proved", "{name}: {v}");
    }
    // ... the supervisor does: FAILURE_RUN through a stall (4 ticks: run, end stop, FAILURE_RUN)
    // and a move before CLEAR_NOT_CALIB (7 ticks: the position lost, cleared, a calibration
    // stall, STOP_STALL, a new move).
    let sup = tmp.path("sup.sc");
    synth("explicit", &sup);
    let c = containment(&tmp, &sup, &example("master_policy.sc"));
    let v = verify_json(&[&c, p("--system"), p("SupervisorReach")]);
    assert_eq!(
        verdict_of(&v, "sup_failure_run_without_failure"),
        ("reachable".to_string(), 4),
        "{v}"
    );
    assert_eq!(
        verdict_of(&v, "sup_moves_before_clearing"),
        ("reachable".to_string(), 7),
        "{v}"
    );
}
