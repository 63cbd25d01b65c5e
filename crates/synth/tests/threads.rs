//! The explicit engine's two-thread pipeline numbers states exactly as one thread does: on
//! every benchmark family (with `needs` requirements and forbidden states among them), the
//! store, the successor lists, the kept states and the figures are equal;
//! and a limit ends the two-thread run as it ends the one-thread run (no hang).

mod common;
use common::{example, problem_of};

use statecheck_synth::families::{self, scaled};
use statecheck_synth::{explicit, Budget, ErrorKind, Limits, Problem};

/// The instances: every family at a size of a few thousand to ~10^5 reachable states, so the
/// pipeline's batches and channels are exercised many times over.
fn instances() -> Vec<(String, Problem)> {
    let mut v: Vec<(String, Problem)> = vec![
        (
            "philosophers_9".into(),
            problem_of(&families::philosophers(9), None),
        ),
        ("line_6".into(), problem_of(&families::line(6), None)),
        (
            "small_factory repair".into(),
            problem_of(&example("small_factory.sc"), Some("SmallFactoryRepair")),
        ),
        (
            "cat_mouse".into(),
            problem_of(&example("cat_mouse.sc"), None),
        ),
    ];
    for (fam, n, k) in [
        ("tl", 4, 2),
        ("dp", 6, 2),
        ("cm", 2, 3),
        ("at", 4, 3),
        ("bw", 5, 2),
        ("ta", 4, 2),
    ] {
        let text = scaled::generate(fam, n, k).expect("family");
        v.push((format!("{fam}({n},{k})"), problem_of(&text, None)));
    }
    v
}

#[test]
fn two_threads_number_states_as_one_does() {
    let budget = Budget::new(&Limits::default());
    for (name, p) in instances() {
        let one = explicit::run_on(&p, &budget, 1).expect("one thread");
        let two = explicit::run_on(&p, &budget, 2).expect("two threads");
        assert!(one.product_states > 10, "{name}: {}", one.product_states);
        assert_eq!(one.product_states, two.product_states, "{name}");
        assert!(one.store == two.store, "{name}: stores differ");
        assert!(
            one.succ_off == two.succ_off,
            "{name}: successor offsets differ"
        );
        assert!(one.succ == two.succ, "{name}: successor lists differ");
        assert!(one.kept == two.kept, "{name}: kept states differ");
        assert_eq!(one.rounds, two.rounds, "{name}");
        assert_eq!(
            (one.size(), one.transitions()),
            (two.size(), two.transitions()),
            "{name}"
        );
    }
}

/// A state limit hit in the middle of the exploration (philosophers_9: 3^9 · 3^9-ish product,
/// 13 k reachable states) ends both runs with the limit and the states counted so far.
#[test]
fn a_limit_ends_the_two_thread_run() {
    let p = problem_of(&families::philosophers(9), None);
    let budget = Budget::new(&Limits {
        max_states: Some(1000),
        ..Limits::default()
    });
    for threads in [1, 2] {
        match explicit::run_on(&p, &budget, threads) {
            Err(e) => match e.kind {
                ErrorKind::Limit { partial, .. } => {
                    assert_eq!(partial.phase, "reachability", "{threads}");
                    assert!(partial.states >= 1000.0, "{threads}: {}", partial.states);
                }
                other => panic!("{threads}: not a limit: {other:?}"),
            },
            Ok(_) => panic!("{threads}: the limit was ignored"),
        }
    }
}
