//! Localization abstraction against the monolithic proof on the FAM closed loops (issue 22
//! asks for it on master + 1 and master + 2 FAMs): on the same circuit reduced by signal
//! correspondence, IC3 on the whole circuit and IC3 on refined abstractions give the same
//! verdict for every own property, and it is the thesis's (`examples/fam/expected.json`,
//! "thesis": App. C/D's verification table, ch. 5.3–5.4). A counterexample of either replays
//! on the circuit, and an invariant of either checks there as a certificate.

use statecheck_ir::Program;
use statecheck_symbolic::engine::{Limits, Outcome};
use statecheck_symbolic::localize::cegar_with_lemmas;
use std::path::Path;

fn program(file: &str) -> Program {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/fam")
        .join(file);
    let path = path.to_string_lossy().to_string();
    let src = std::fs::read_to_string(&path).expect("example exists");
    let loaded = statecheck_model::imports::load_with(&path, src.clone(), |k| {
        std::fs::read_to_string(k).ok()
    });
    let (model, diags) = statecheck_model::check(&loaded.file);
    assert!(!loaded.diags.iter().chain(&diags).any(|d| d.is_error()));
    // The system the entry file declares (its imports declare others).
    let sys = model
        .systems
        .iter()
        .find(|s| src.contains(&format!("system {} ", s.name)))
        .or_else(|| model.systems.iter().find(|s| s.name == "FamSystem"))
        .expect("a FAM system");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

/// The thesis's verdicts (expected.json, "thesis"): `true` when the property holds (an
/// invariant proved, or a `reachable` target unreachable), `false` when a trace reaches its
/// bad output (an invariant violated, or a `reachable` target reached).
fn thesis_holds(name: &str) -> bool {
    match name {
        "fam_stall_blocks_run"
        | "fam_failure_blocks_run"
        | "fam_actualpos_in_range"
        | "master_no_normal_run_on_failure"
        | "master_failure_before_stall"
        | "master_outputs_in_range"
        | "master_target_outside_ends_only_calibrating"
        | "master_failure_sequence" => true,
        // "proven false", and "possible" (a reachable target reached).
        "fam_cof_with_notcalib"
        | "fam_stall_running_possible"
        | "fam_failure_running_possible"
        | "master_target_outside_ends" => false,
        other => panic!("no thesis verdict for {other}"),
    }
}

/// Whether the property holds by this answer, after checking the answer's evidence on `g`.
fn holds(g: &statecheck_symbolic::aig::Aig, out: &Outcome, who: &str, name: &str) -> bool {
    match out {
        Outcome::Proved(inv) => {
            if let Some(inv) = inv {
                assert!(
                    statecheck_symbolic::cert::check(g, inv).is_ok(),
                    "{who}'s invariant for {name} does not check"
                );
            }
            true
        }
        Outcome::Reached(t) => {
            assert!(
                statecheck_symbolic::scorr::replays(g, t),
                "{who}'s trace for {name} does not replay"
            );
            false
        }
        other => panic!("{who} did not decide {name}: {other:?}"),
    }
}

/// Every own property of `file`: monolithic IC3 and localization on the reduced circuit agree
/// with each other and with the thesis.
fn agree(file: &str) {
    let p = program(file);
    let bl = statecheck_symbolic::blast::blast(&p);
    let shared = bl.shared_problem();
    let red =
        statecheck_symbolic::scorr::reduce(&shared.aig, &Limits::default()).expect("no limit set");
    let mut refined = 0;
    for (i, prop) in bl.props.iter().enumerate() {
        let Some(k) = shared.bad_index[i] else {
            continue;
        };
        let g = red.with_bad(k).aig;
        let mono = statecheck_symbolic::ic3::ic3(&g, &Limits::default());
        let (local, st) = cegar_with_lemmas(&g, &Limits::default(), &Vec::new());
        let expect = thesis_holds(&prop.name);
        assert_eq!(
            holds(&g, &mono, "IC3", &prop.name),
            expect,
            "{file}: {}",
            prop.name
        );
        assert_eq!(
            holds(&g, &local, "localization", &prop.name),
            expect,
            "{file}: {}",
            prop.name
        );
        refined += st.refinements;
        eprintln!("{file}: {} {expect} {st:?}", prop.name);
    }
    eprintln!("{file}: {refined} refinements in all");
}

#[test]
fn master_and_one_fam_localization_agrees_with_monolithic_ic3_and_the_thesis() {
    agree("fam_system.sc");
}

#[test]
fn master_and_two_fams_localization_agrees_with_monolithic_ic3_and_the_thesis() {
    agree("fam_system2.sc");
}

/// The thesis's bug (ch. 5.4: the controller's failure timeout shorter than a bus round) is
/// a real violation of `master_no_normal_run_on_failure`; localization must find a trace that
/// replays, however many spurious abstract ones it refutes first.
#[test]
fn the_short_timeout_bug_is_a_real_violation_under_localization() {
    let p = program("bug_short_timeout.sc");
    let bl = statecheck_symbolic::blast::blast(&p);
    let i = bl
        .props
        .iter()
        .position(|s| s.name == "master_no_normal_run_on_failure")
        .expect("the property");
    let g = bl.problem(i);
    let (out, _) = cegar_with_lemmas(&g, &Limits::default(), &Vec::new());
    assert!(!holds(
        &g,
        &out,
        "localization",
        "master_no_normal_run_on_failure"
    ));
}
