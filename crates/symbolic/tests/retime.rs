//! The retimed problem of a property (its bad output read on the latches one tick later,
//! `Blasted::retimed_problem`) and localization on it (`--engine cegar`): answers derived by
//! hand on a small counter, including an `assume` that leaves the violating state without a
//! successor, and the same verdicts as the engines on the original problem.

use statecheck_ir::verdict::Verdict;
use statecheck_ir::{Machine, Program};
use statecheck_symbolic::blast::{blast, retimed_trace};
use statecheck_symbolic::check::{decide, problems, Engine, Reductions};
use statecheck_symbolic::engine::{Limits, Outcome};
use statecheck_symbolic::localize::cegar_reducing;

/// `x` counts the ticks in which `go` is true (from 0, saturating at 5); `seen` latches
/// `peek`, an input.
///
/// By hand (the first tick enters `S`, its `during` runs from the second tick on): `x <= 2`
/// is first violated after four ticks, the last three with `go` (x = 3); `x <= 5` holds
/// (saturation); `x != 4` is violated after five ticks in `Free`, but in `Stuck` the assume
/// `c.x < 3` (read on the pre-state) forbids every tick from x = 3, so x = 4 is unreachable
/// there while `x <= 2` is still violated after four ticks — the tick into x = 3 starts from
/// x = 2, and nothing is asked of the tick after the violating one. `peek_low` reads an
/// input, so it has no retimed form.
const SRC: &str = r#"
chart Count {
  input go: bool = false;
  input peek: int[0..3] = 0;
  output x: int[0..5] = 0;
  initial S;
  state S { during { if go && x < 5 { x = x + 1; } } }
}
system Free {
  instance c: Count;
  invariant at_most_two: c.x <= 2;
  invariant at_most_five: c.x <= 5;
  invariant never_four: c.x != 4;
  invariant peek_low: c.peek <= 2;
}
system Stuck {
  instance c: Count;
  assume c.x < 3;
  invariant at_most_two: c.x <= 2;
  invariant never_four: c.x != 4;
}
"#;

fn program(system: &str) -> Program {
    let (file, pd) = statecheck_syntax::parse(SRC);
    assert!(!pd.iter().any(|d| d.is_error()), "{pd:?}");
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
    let sys = model
        .systems
        .iter()
        .find(|s| s.name == system)
        .expect("system");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

/// The tick (1-based) at which replaying `vectors` on the IR's machine first violates
/// property `name`, if any.
fn violated_at(p: &Program, name: &str, vectors: &[Vec<i64>]) -> Option<usize> {
    let k = p.properties.iter().position(|q| q.name == name)?;
    let goal = p.properties[k].goal;
    let mut m = Machine::new(p);
    for (t, v) in vectors.iter().enumerate() {
        for (i, inp) in p.inputs.iter().enumerate() {
            m.set(inp.slot, v[i]);
        }
        m.step().ok()?;
        if goal.decided_by(|e| {
            let e = p.prepare(e);
            m.holds(e)
        }) {
            return Some(t + 1);
        }
    }
    None
}

/// Localization on the retimed problem of `name` in `system`, its answer read back.
fn localized(system: &str, name: &str) -> (Program, Outcome) {
    let p = program(system);
    let bl = blast(&p);
    let i = bl
        .props
        .iter()
        .position(|q| q.name == name)
        .expect("property");
    let (g, _) = bl.retimed_problem(i).expect("reads only state");
    let mut progress = Default::default();
    let (out, _) = cegar_reducing(&g, &Limits::default(), &mut progress);
    let out = match out {
        Outcome::Reached(t) => Outcome::Reached(retimed_trace(t)),
        o => o,
    };
    (p, out)
}

#[test]
fn a_violation_is_found_at_its_tick_and_replays() {
    for system in ["Free", "Stuck"] {
        let (p, out) = localized(system, "at_most_two");
        let Outcome::Reached(t) = out else {
            panic!("{system}: at_most_two is violated after 4 ticks (by hand), got {out:?}");
        };
        assert_eq!(
            t.inputs.len(),
            4,
            "{system}: the start tick and three with go"
        );
        let bl = blast(&p);
        let vectors = statecheck_symbolic::check::input_vectors(&bl, &t);
        assert_eq!(
            violated_at(&p, "at_most_two", &vectors),
            Some(4),
            "{system}"
        );
    }
    let (p, out) = localized("Free", "never_four");
    let Outcome::Reached(t) = out else {
        panic!("never_four is violated after 5 ticks in Free (by hand), got {out:?}");
    };
    let vectors = statecheck_symbolic::check::input_vectors(&blast(&p), &t);
    assert_eq!(violated_at(&p, "never_four", &vectors), Some(5));
}

#[test]
fn properties_that_hold_are_proved() {
    for (system, name) in [("Free", "at_most_five"), ("Stuck", "never_four")] {
        let (_, out) = localized(system, name);
        assert!(
            matches!(out, Outcome::Proved(_)),
            "{system}: {name} holds (by hand), got {out:?}"
        );
    }
}

#[test]
fn a_property_that_reads_an_input_has_no_retimed_form() {
    let p = program("Free");
    let bl = blast(&p);
    let i = bl
        .props
        .iter()
        .position(|q| q.name == "peek_low")
        .expect("property");
    assert!(bl.retimed_problem(i).is_none());
    // `--engine cegar` still decides it (on the original problem): violated in one tick.
    let (bl, idx) = problems(&p, &["peek_low".to_string()]).expect("known");
    let (pi, kind) = idx[0];
    let red = Reductions::new(bl.props.len());
    let r = decide(&p, &bl, pi, kind, Engine::Cegar, &Limits::default(), &red);
    assert_eq!(r.result.verdict, Verdict::Violated);
    assert_eq!(r.result.depth, 1);
}

/// Every own property of both systems: localization through the engines' path
/// (`check::decide`, `Engine::Cegar`) gives the verdict and depth of BMC and IC3 on the
/// original problem.
#[test]
fn the_engines_path_agrees_with_ic3_and_bmc_on_the_original_problem() {
    for system in ["Free", "Stuck"] {
        let p = program(system);
        let (bl, idx) = problems(&p, &[]).expect("all");
        for &(pi, kind) in &idx {
            if bl.props[pi].builtin.is_some() {
                continue;
            }
            let lim = Limits {
                max_depth: None,
                ..Limits::default()
            };
            let by =
                |e: Engine| decide(&p, &bl, pi, kind, e, &lim, &Reductions::new(bl.props.len()));
            let (c, i3) = (by(Engine::Cegar), by(Engine::Ic3));
            let name = &bl.props[pi].name;
            assert_eq!(c.result.verdict, i3.result.verdict, "{system}: {name}");
            // A proof's certificate is about the original problem (`--check-certificate`
            // reads that one) and checks there.
            if let Some((aig, inv)) = &c.invariant {
                assert_eq!(aig.latches.len(), bl.problem(pi).latches.len());
                assert!(
                    statecheck_symbolic::cert::check(aig, inv).is_ok(),
                    "{system}: {name}"
                );
            }
            if c.result.verdict == Verdict::Proved {
                assert!(c.invariant.is_some(), "{system}: {name}: a certificate");
            }
            if c.result.verdict == Verdict::Violated {
                let b = by(Engine::Bmc);
                assert_eq!(c.result.depth, b.result.depth, "{system}: {name}");
            }
        }
    }
}
