//! Signal correspondence must not change any verdict: on every property of every small model
//! in `tests/` and `examples/` (those the explicit engine decides exhaustively, an independent
//! reference), IC3 on the reduced circuit, read back on the original, gives the explicit
//! engine's verdict; every counterexample replays on the original circuit (checked by
//! `Reduction::lift`) with the explicit engine's shortest length; every invariant that comes
//! back passes the certificate check on the original circuit.

#[path = "../../symbolic/tests/common_models.rs"]
mod common_models;

use statecheck_explicit::{Options, Verdict};
use statecheck_symbolic::aig::{Aig, Lit};
use statecheck_symbolic::check::problems;
use statecheck_symbolic::engine::{Limits, Outcome};
use statecheck_symbolic::scorr::{reduce, SPURIOUS};
use std::time::{Duration, Instant};

fn limits(secs: u64) -> Limits {
    Limits {
        deadline: Some(Instant::now() + Duration::from_secs(secs)),
        ..Limits::default()
    }
}

#[test]
fn reduction_keeps_every_verdict() {
    let (mut compared, mut merged, mut certified, mut spurious) = (0, 0, 0, 0);
    for (name, p) in common_models::programs() {
        let opts = Options {
            threads: 1,
            max_states: Some(50_000),
            ..Options::default()
        };
        let Ok(rep) = statecheck_explicit::verify(&p, &opts, None) else {
            continue;
        };
        if !rep.stats.complete && !rep.stats.all_decided {
            continue;
        }
        let (bl, idx) = problems(&p, &[]).expect("all properties");
        for (r, &(pi, _)) in rep.results.iter().zip(&idx) {
            if r.verdict == Verdict::Unknown || r.depth > 40 && r.counterexample.is_some() {
                continue;
            }
            let at = format!("{name}: {}", r.name);
            let g = bl.problem(pi);
            let red = reduce(&g, &limits(30)).unwrap_or_else(|e| panic!("{at}: {e}"));
            merged += red.stats.merged;
            assert!(red.aig.latches.len() <= g.latches.len(), "{at}");
            let out = red.lift(&g, statecheck_symbolic::ic3::ic3(&red.aig, &limits(30)));
            match (&out, r.verdict) {
                (Outcome::Proved(inv), Verdict::Proved | Verdict::Unreachable) => {
                    if let Some(inv) = inv {
                        statecheck_symbolic::cert::check(&g, inv)
                            .unwrap_or_else(|e| panic!("{at}: certificate: {e}"));
                        certified += 1;
                    }
                }
                (Outcome::Reached(t), Verdict::Violated | Verdict::Reachable) => {
                    assert_eq!(t.inputs.len() as u64, r.depth, "{at}: not shortest");
                }
                (Outcome::Unknown { why: w, .. }, Verdict::Violated | Verdict::Reachable)
                    if w == SPURIOUS =>
                {
                    spurious += 1;
                }
                (o, v) => panic!("{at}: explicit says {v:?}, reduced IC3 says {o:?}"),
            }
            compared += 1;
        }
    }
    eprintln!(
        "{compared} properties agree; {merged} nodes merged in all; {certified} invariants certified on the original; {spurious} reduced counterexamples did not replay"
    );
    assert!(compared > 100, "only {compared} properties compared");
}

/// Two latches that toggle in step from 0 are equal in every reachable state, so the bad
/// output "they differ" is the constant false after the reduction (derived by hand), and a
/// latch that starts at 1 and stays `l & l` is the constant true.
#[test]
fn equal_togglers_and_a_constant_latch_are_merged() {
    let mut g = Aig::new();
    let x = g.input(None);
    let a = g.latch(Some(false), None);
    let b = g.latch(Some(false), None);
    let c = g.latch(Some(true), None);
    g.set_next(0, !a);
    g.set_next(1, !b);
    let keep = g.and(c, c);
    g.set_next(2, keep);
    let differ = g.xor(a, b);
    let bad = g.and(differ, x);
    let bad = g.or(bad, !c);
    g.bad = vec![bad];
    let red = reduce(&g, &limits(10)).expect("tiny");
    assert_eq!(red.aig.bad, vec![Lit::FALSE]);
    assert_eq!(red.aig.latches.len(), 0);
    assert_eq!(red.stats.latches, (3, 0));
}
