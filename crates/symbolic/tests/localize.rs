//! Localization abstraction with refinement (`localize`): answers derived by hand on small
//! circuits, a spurious abstract counterexample refined rather than reported, and the same
//! verdicts as monolithic IC3 on the FAM closed loops.

use statecheck_symbolic::aig::{Aig, Lit};
use statecheck_symbolic::engine::{Limits, Outcome};
use statecheck_symbolic::localize::cegar_with_lemmas;
use statecheck_symbolic::scorr::replays;

/// Latch `a` (reset false) becomes `b ∧ (x ∨ c)`; `b` (reset false) keeps its value; `c`
/// (reset false) becomes input `y`; eight more latches count with input `z` and feed `c`'s
/// cone nowhere. Bad: `a`.
///
/// By hand: `b` is false forever, so `a` is false after the reset and forever: the property
/// holds. The first abstraction keeps only `a` (what the bad output reads) and frees `b`, so
/// it has a counterexample of depth 1 (`a` becomes a free `b`): spurious, it must be refined
/// (by `b`, which the concrete refutation uses), never reported.
fn needs_b() -> Aig {
    let mut g = Aig::new();
    let x = g.input(Some("x".into()));
    let y = g.input(Some("y".into()));
    let z = g.input(Some("z".into()));
    let a = g.latch(Some(false), Some("a".into()));
    let b = g.latch(Some(false), Some("b".into()));
    let c = g.latch(Some(false), Some("c".into()));
    let counter: Vec<Lit> = (0..8)
        .map(|i| g.latch(Some(false), Some(format!("k{i}"))))
        .collect();
    let xc = g.or(x, c);
    let na = g.and(b, xc);
    g.set_next(0, na);
    g.set_next(1, b);
    g.set_next(2, y);
    // A ripple counter that increments when `z` holds (never read by `a`, `b` or `c`).
    let mut carry = z;
    for (i, &k) in counter.iter().enumerate() {
        let n = g.xor(k, carry);
        carry = g.and(k, carry);
        g.set_next(3 + i, n);
    }
    // The bad output reads `a` and, through a gate that is false whenever `a` is, the counter's
    // top bit: the counter is in the property's cone but not needed for the proof.
    let top = g.and(a, counter[7]);
    g.bad = vec![g.or(a, top)];
    g.bad_names = vec![Some("a".into())];
    g
}

#[test]
fn a_spurious_abstract_counterexample_is_refined_and_the_property_proved() {
    let g = needs_b();
    let (out, st) = cegar_with_lemmas(&g, &Limits::default(), &Vec::new());
    let Outcome::Proved(Some(inv)) = out else {
        panic!("`a` never holds (by hand), got {out:?}");
    };
    // The depth-1 counterexample of the first abstraction was refuted on the concrete
    // circuit, and the proof did not need every latch (`c` and the counter stay free).
    assert!(st.refinements >= 1, "{st:?}");
    assert_eq!(st.depths.first(), Some(&1), "{st:?}");
    assert!(st.kept < st.latches, "{st:?}");
    // The invariant found on the abstraction is an inductive invariant of the concrete
    // circuit (the independent certificate check).
    assert!(statecheck_symbolic::cert::check(&g, &inv).is_ok());
}

/// A shift register `l0 → l1 → l2 → l3` (all reset false), `l0` loaded from input `x`; bad:
/// `l3`.
///
/// By hand: `x` true in frame 0 makes `l0` true in frame 1, `l1` in 2, `l2` in 3 and `l3` in
/// frame 4: the shortest counterexample has five frames. Every abstraction that frees a latch
/// of the chain has a shorter counterexample, which is spurious.
fn shift() -> Aig {
    let mut g = Aig::new();
    let x = g.input(Some("x".into()));
    let l: Vec<Lit> = (0..4)
        .map(|i| g.latch(Some(false), Some(format!("l{i}"))))
        .collect();
    g.set_next(0, x);
    for i in 1..4 {
        g.set_next(i, l[i - 1]);
    }
    g.bad = vec![l[3]];
    g.bad_names = vec![Some("l3".into())];
    g
}

#[test]
fn a_real_counterexample_is_found_after_refuting_the_shorter_spurious_ones() {
    let g = shift();
    let (out, st) = cegar_with_lemmas(&g, &Limits::default(), &Vec::new());
    let Outcome::Reached(t) = out else {
        panic!("l3 holds in frame 4 (by hand), got {out:?}");
    };
    assert_eq!(t.inputs.len(), 5);
    assert!(t.inputs[0][0], "x must be loaded in frame 0");
    assert!(replays(&g, &t));
    // The first abstraction (l3 alone) has a counterexample of depth 1; at most one
    // refinement per latch of the chain before the concrete one is found.
    assert_eq!(st.depths.first(), Some(&1), "{st:?}");
    assert!((1..=3).contains(&st.refinements), "{st:?}");
}

/// Two latches that swap (`p` reset true, `q` reset false, `p' = q`, `q' = p`) under the
/// constraint `p ≠ q`, and a latch `r` (reset false) that becomes `p ∧ q`; bad: `r`.
///
/// By hand: `p` and `q` swap values, so exactly one holds in every state and `r` stays false.
/// The first abstraction keeps only `r`: `p` and `q` become free inputs, but the constraint
/// still restricts their free values in every frame, so `p ∧ q` is false there too and the
/// property is proved without refinement.
#[test]
fn constraints_restrict_freed_latches_and_the_property_is_proved() {
    let mut g = Aig::new();
    let p = g.latch(Some(true), Some("p".into()));
    let q = g.latch(Some(false), Some("q".into()));
    let r = g.latch(Some(false), Some("r".into()));
    g.set_next(0, q);
    g.set_next(1, p);
    let both = g.and(p, q);
    g.set_next(2, both);
    let differ = g.xor(p, q);
    g.constraints = vec![differ];
    g.bad = vec![r];
    g.bad_names = vec![Some("r".into())];
    let (out, st) = cegar_with_lemmas(&g, &Limits::default(), &Vec::new());
    assert!(matches!(out, Outcome::Proved(Some(_))), "{out:?}");
    assert_eq!(st.refinements, 0, "{st:?}");
    assert_eq!(st.kept, 1, "{st:?}");
}
