//! The SAT engines' temporal checks (liveness-to-safety with IC3, k-induction and BMC;
//! k-liveness with IC3) on `tests/verify/temporal.sc`, whose LTL verdicts are derived by hand
//! in its comments. Every lasso is replayed in the interpreter: it must close on the whole
//! state, stay within the `assume`s, and violate the formula by the IR's own lasso semantics
//! (`holds_on_lasso`, independent of the automaton).

use statecheck_ir::temporal::{holds_on_lasso, TemporalFormula};
use statecheck_ir::verdict::Verdict;
use statecheck_ir::Program;
use statecheck_symbolic::blast::blast;
use statecheck_symbolic::check::Engine;
use statecheck_symbolic::engine::Limits;
use statecheck_symbolic::live::{decide, Method};
use std::time::{Duration, Instant};

fn program(system: &str) -> Program {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let src = std::fs::read_to_string(format!("{root}/tests/verify/temporal.sc")).expect("model");
    let (file, _) = statecheck_syntax::parse(&src);
    let (model, d) = statecheck_model::check(&file);
    assert!(!d.iter().any(|d| d.is_error()), "{d:?}");
    let sys = model
        .systems
        .iter()
        .find(|s| s.name == system)
        .expect("system");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

fn limits() -> Limits {
    Limits {
        deadline: Some(Instant::now() + Duration::from_secs(60)),
        max_depth: Some(40),
        ..Limits::default()
    }
}

/// Hand-derived verdicts (tests/verify/temporal.sc): `true` = the property holds.
const EXPECT: &[(&str, &[(&str, bool)])] = &[
    (
        "Free",
        &[
            ("reaches3", false),
            ("bounded", true),
            ("gf_zero", false),
            ("resets", true),
        ],
    ),
    ("FairInc", &[("reaches3", false), ("gf_inc", true)]),
    ("NoReset", &[("reaches3", true), ("stays3", true)]),
    ("Compassion", &[("past_one", true), ("reaches2", false)]),
    ("NoCompassion", &[("past_one", false)]),
    ("Deadlock", &[("never2", true), ("reaches2", false)]),
];

#[test]
fn liveness_engines_match_hand_derived_verdicts() {
    for (system, props) in EXPECT {
        let p = program(system);
        let bl = blast(&p);
        for (name, holds) in *props {
            let t = p
                .temporal
                .iter()
                .position(|t| t.name == *name)
                .expect("property");
            let methods = [
                Method::L2s(Engine::Ic3),
                Method::L2s(Engine::Bmc),
                Method::L2s(Engine::Kind),
                Method::KLive,
            ];
            for m in methods {
                let r = decide(&p, &bl, t, m, &limits());
                let v = r.result.verdict;
                let what = format!("{system}.{name} by {}: {v:?} {:?}", m.as_str(), r.reason);
                match (holds, m) {
                    // BMC never proves (bounded); k-induction may not either.
                    (true, Method::L2s(Engine::Bmc)) => assert_eq!(v, Verdict::Bounded, "{what}"),
                    (true, Method::L2s(Engine::Kind)) => {
                        assert!(matches!(v, Verdict::Proved | Verdict::Unknown), "{what}")
                    }
                    (true, _) => assert_eq!(v, Verdict::Proved, "{what}"),
                    (false, Method::KLive) => assert_eq!(v, Verdict::Unknown, "{what}"),
                    (false, _) => {
                        assert_eq!(v, Verdict::Violated, "{what}");
                        replay(&p, t, &r.result, &what);
                    }
                }
            }
        }
    }
}

/// The lasso closes on the whole state, every tick is allowed, and the formula fails on it.
fn replay(p: &Program, t: usize, r: &statecheck_ir::verdict::PropResult, what: &str) {
    let ticks = r.counterexample.as_ref().expect(what);
    let k = r.loop_start.expect(what) as usize;
    assert!(
        k >= 1 && k < ticks.len(),
        "{what}: loop {k} of {}",
        ticks.len()
    );
    let mut m = statecheck_ir::Machine::new(p);
    let mut states = Vec::new();
    let mut positions = Vec::new();
    for v in ticks {
        for (inp, &x) in p.inputs.iter().zip(v) {
            m.set(inp.slot, x);
        }
        for &a in &p.assumes {
            assert_eq!(m.eval(a).ok(), Some(1), "{what}: an assume fails");
        }
        m.step().expect(what);
        states.push(m.state().to_vec());
        positions.push(m.slots().to_vec());
    }
    assert_eq!(
        states[k - 1],
        states[ticks.len() - 1],
        "{what}: the loop does not close"
    );
    let TemporalFormula::Ltl(f) = &p.temporal[t].formula else {
        panic!("{what}: not LTL")
    };
    let atom = |e, i: usize| statecheck_ir::eval(&p.nodes, &positions[i], e).is_ok_and(|v| v != 0);
    assert!(
        !holds_on_lasso(f, &atom, ticks.len(), k),
        "{what}: the lasso satisfies the formula"
    );
}

/// A response that takes 101 ticks (bounded persistence, `live::persistence`). After `req`
/// in `Idle`, `Busy` counts n from 0 to 100, one per tick, and sets `done` on leaving; `req`
/// in `Busy` is ignored. By hand: a position with `req` and `Busy` active has `done` within
/// 102 positions, whatever the inputs, so `answered` holds; the Büchi state of
/// `F((req && in(Busy)) && G !done)` that reads `G !done` is a sink (absorbing). Without the
/// `in(Busy)` guard the property is violated: `req` in tick 0 is not seen (R1), so no run
/// starts and `done` never holds (lasso: `req`, then nothing) — bounded persistence must not
/// prove that one.
const SLOW: &str = r#"
chart Slow {
  input event req;
  output n: int[0..100] = 0;
  output done: bool = false;
  initial Idle;
  state Idle {
    on req / { n = 0; done = false; } -> Busy;
  }
  state Busy {
    on [n == 100] / { done = true; } -> Idle;
    on [n < 100] / { n += 1; } -> Busy;
  }
}
system SlowResponse {
  instance c: Slow;
  ltl answered: G((c.req && in(c.Busy)) => F c.done);
  ltl answered_always: G(c.req => F c.done);
}
"#;

#[test]
fn bounded_persistence_proves_a_slow_response() {
    use statecheck_symbolic::live::{justice_of, persistence, LiveOutcome};
    let (file, _) = statecheck_syntax::parse(SLOW);
    let (model, d) = statecheck_model::check(&file);
    assert!(!d.iter().any(|d| d.is_error()), "{d:?}");
    let p = statecheck_ir::lower(&model, &model.systems[0]).expect("lowers");
    let bl = blast(&p);
    let j = justice_of(&p, &bl, "answered")
        .expect("property")
        .expect("LTL");
    let r = persistence(&j, &limits());
    assert!(matches!(r, LiveOutcome::Proved), "{r:?}");
    // k-liveness (which tries bounded persistence first) proves it too.
    let t = p.temporal.iter().position(|t| t.name == "answered");
    let r = decide(&p, &bl, t.expect("property"), Method::KLive, &limits());
    assert_eq!(r.result.verdict, Verdict::Proved, "{:?}", r.reason);
    // The violated one: never proved; liveness-to-safety with BMC finds the lasso.
    let j = justice_of(&p, &bl, "answered_always")
        .expect("property")
        .expect("LTL");
    let short = Limits {
        deadline: Some(Instant::now() + Duration::from_secs(5)),
        ..Limits::default()
    };
    let r = persistence(&j, &short);
    assert!(matches!(r, LiveOutcome::Unknown(_)), "{r:?}");
    let t = p.temporal.iter().position(|t| t.name == "answered_always");
    let t = t.expect("property");
    let r = decide(&p, &bl, t, Method::L2s(Engine::Bmc), &limits());
    assert_eq!(r.result.verdict, Verdict::Violated, "{:?}", r.reason);
    replay(&p, t, &r.result, "answered_always by bmc");
}
