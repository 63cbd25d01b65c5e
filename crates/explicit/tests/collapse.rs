//! Collapse compression (`Options::collapse`) stores the same states as the plain visited
//! set: against counts derived by hand (`n` independent modulo-(m+1) counters, at most one
//! incremented per tick: (m+1)^n states after tick 0 plus the pre-start state; the wide
//! padding variables never change, they only widen the packed vector past 128 bits), with the
//! same transitions, verdict and counterexample as without it, on 1 and 2 threads, whether it
//! is on from the start or switched on by the memory limit on the way (`Collapse::Auto`).

mod common;

use common::program;
use statecheck_explicit::{verify, Collapse, Options, Verdict};

#[test]
fn collapse_stores_the_same_states_as_the_plain_set() {
    // 4 counters of 0..4 (3 bits each) with 2 × 40 padding bits each: 332 bits, 6 words.
    let (n, m) = (4, 4);
    let p = program(n, m, 2);
    let states = (m as u64 + 1).pow(n as u32) + 1;
    let mut seen = Vec::new();
    for collapse in [Collapse::Off, Collapse::On, Collapse::Auto] {
        for threads in [1, 2] {
            // Under Auto, a memory limit the plain set passes two fifths of on the way: its
            // 64 shards of at least 64 slots of 48 bytes take 196 KiB once each holds a
            // state, the compressed set under 100 KiB.
            let max_memory = (collapse == Collapse::Auto).then_some(300_000);
            let r = verify(
                &p,
                &Options {
                    threads,
                    collapse,
                    max_memory,
                    ..Options::default()
                },
                None,
            )
            .expect("runs");
            assert!(r.stats.state_bits > 256, "{} bits", r.stats.state_bits);
            assert!(r.stats.complete);
            assert_eq!(
                r.stats.states, states,
                "collapse {collapse:?}, {threads} threads"
            );
            // Each state: no event, or one of the n events.
            assert_eq!(r.stats.transitions, r.stats.states * (n as u64 + 1));
            let inv = &r.results[0];
            assert_eq!(inv.verdict, Verdict::Violated);
            // All counters at m need n·m increments, one per tick from tick 1.
            assert_eq!(inv.depth, (n * m) as u64 + 1);
            match (collapse, &r.stats.collapse_leaves) {
                (Collapse::Off, None) => {}
                (Collapse::On | Collapse::Auto, Some(l)) => {
                    // Two halves; the pair of numbers identifies a state, so the product of
                    // the distinct halves bounds the states, and no half outnumbers them.
                    assert_eq!(l.len(), 2);
                    assert!(l[0] * l[1] >= states && l[0] <= states && l[1] <= states);
                }
                (c, l) => panic!("collapse {c:?} but leaves {l:?}"),
            }
            let from = r.stats.collapse_from;
            match collapse {
                Collapse::Off => assert_eq!(from, None),
                Collapse::On => assert_eq!(from, Some(1)),
                // Switched on the way: some states were stored plain first.
                Collapse::Auto => assert!(from.is_some_and(|n| n > 1 && n < states), "{from:?}"),
            }
            seen.push((
                r.stats.states,
                r.stats.transitions,
                r.stats.depth,
                inv.counterexample.clone(),
            ));
        }
    }
    assert!(
        seen.iter().all(|s| *s == seen[0]),
        "same answer and counterexample with and without collapse, on 1 and 2 threads"
    );
}

#[test]
fn collapse_leaves_states_of_two_words_as_they_are() {
    // 3 counters of 0..3 and one padding variable each: 126 bits, one u128 key.
    let p = program(3, 3, 1);
    let r = verify(
        &p,
        &Options {
            collapse: Collapse::On,
            ..Options::default()
        },
        None,
    )
    .expect("runs");
    assert!(r.stats.state_bits <= 128);
    assert_eq!(r.stats.states, 4 * 4 * 4 + 1);
    assert_eq!(r.stats.collapse_leaves, None);
}
