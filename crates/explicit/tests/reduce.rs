//! The input abstraction (`Options::reduce_inputs`) explores the same states as stepping every
//! input vector: the reachable state count of each small model is enumerated independently (a
//! plain breadth-first search over every input vector, with the interpreter), and both runs
//! of the engine must find it, with the same verdicts, counterexamples and transition counts.

use statecheck_explicit::{verify, Backend, Options, Report};
use statecheck_ir::{Machine, Program};
use std::collections::{HashSet, VecDeque};

fn programs(text: &str) -> Vec<(String, Program)> {
    let (file, d1) = statecheck_syntax::parse(text);
    let (model, d2) = statecheck_model::check(&file);
    assert!(!d1.iter().chain(&d2).any(|d| d.is_error()), "{d1:?}{d2:?}");
    model
        .systems
        .iter()
        .map(|s| {
            let p = statecheck_ir::lower(&model, s).expect("lowers");
            (s.name.clone(), p)
        })
        .collect()
}

fn run(p: &Program, reduce: bool) -> Report {
    verify(
        p,
        &Options {
            threads: 2,
            backend: Backend::Interpreter,
            reduce_inputs: reduce,
            ..Options::default()
        },
        None,
    )
    .expect("runs")
}

/// Every raw input vector (first input fastest), or `None` when there are more than `max`.
fn vectors(p: &Program, max: usize) -> Option<Vec<Vec<i64>>> {
    let mut out = vec![Vec::new()];
    for inp in &p.inputs {
        let s = &p.slots[inp.slot as usize];
        let mut next = Vec::new();
        for x in s.lo..=s.hi {
            for v in &out {
                let mut v: Vec<i64> = v.clone();
                v.push(x);
                next.push(v);
            }
            if next.len() > max {
                return None;
            }
        }
        out = next;
    }
    Some(out)
}

/// Reachable states (the initial one included) by breadth-first search over every vector
/// that satisfies every assume, or `None` when there are more than `max`.
fn enumerate(p: &Program, max: usize) -> Option<usize> {
    let vs = vectors(p, 256)?;
    let mut m = Machine::new(p);
    let init = m.state().to_vec();
    let mut seen = HashSet::from([init.clone()]);
    let mut queue = VecDeque::from([init]);
    while let Some(s) = queue.pop_front() {
        for v in &vs {
            m.load(&s, v);
            let ok = p
                .assumes
                .iter()
                .all(|&a| matches!(m.eval(a), Ok(x) if x != 0));
            if !ok || m.step().is_err() {
                continue;
            }
            let next = m.state().to_vec();
            if seen.insert(next.clone()) {
                if seen.len() > max {
                    return None;
                }
                queue.push_back(next);
            }
        }
    }
    Some(seen.len())
}

fn check_file(path: &str) -> usize {
    let text = std::fs::read_to_string(path).expect("reads");
    let mut checked = 0;
    for (name, p) in programs(&text) {
        let Some(count) = enumerate(&p, 5_000) else {
            continue;
        };
        let (on, off) = (run(&p, true), run(&p, false));
        let what = format!("{path}, system {name}");
        assert!(on.stats.complete && off.stats.complete, "{what}");
        assert_eq!(on.stats.states, count as u64, "{what}: reduced");
        assert_eq!(off.stats.states, count as u64, "{what}: every vector");
        assert_eq!(on.stats.transitions, off.stats.transitions, "{what}");
        assert_eq!(on.results.len(), off.results.len(), "{what}");
        for (a, b) in on.results.iter().zip(&off.results) {
            assert_eq!(
                (a.verdict, a.depth, &a.counterexample),
                (b.verdict, b.depth, &b.counterexample),
                "{what}, property {}",
                a.name
            );
        }
        checked += 1;
    }
    checked
}

#[test]
fn the_reduction_finds_every_reachable_state_of_the_small_models() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let mut checked = 0;
    for dir in ["tests/verify", "tests/semantics", "examples/linear_drive"] {
        let mut files: Vec<_> = std::fs::read_dir(format!("{root}/{dir}"))
            .expect("dir")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "sc"))
            .collect();
        files.sort();
        for f in files {
            checked += check_file(&f.to_string_lossy());
        }
    }
    // Most of the systems are small enough to enumerate (a guard against a test that checks
    // nothing).
    assert!(checked >= 10, "only {checked} systems checked");
}

#[test]
fn inputs_read_only_in_some_states_are_stepped_there_only() {
    // In `A` only `a` is read, in `B` only `b`; `c` is never read. 8 vectors per tick.
    // States: pre-start, A, B (3). Transitions: 8 from each of the 3 states = 24 either way.
    // The reduction steps 1 vector from the pre-start state (the start tick reads no input),
    // 2 from A (a), 2 from B (b): 5 ticks instead of 24, which the counts below cannot see, but
    // the state count must stay 3.
    let text = "chart T {\n  input a: bool = false;\n  input b: bool = false;\n  input c: bool = false;\n  initial A;\n  state A { on [a] -> B; }\n  state B { on [b] -> A; }\n}\nsystem Sys {\n  instance t: T;\n  invariant never_b_with_c: !(in(t.B) && t.c);\n}\n";
    let (_, p) = programs(text).remove(0);
    assert_eq!(enumerate(&p, 100), Some(3));
    let (on, off) = (run(&p, true), run(&p, false));
    assert_eq!((on.stats.states, off.stats.states), (3, 3));
    assert_eq!((on.stats.transitions, off.stats.transitions), (24, 24));
    // The invariant reads input `c` (so `c` counts as read everywhere): it is violated by a
    // tick A -> B with c = true, at depth 2 (start, then the move), in both runs alike.
    assert_eq!(on.results[0].counterexample, off.results[0].counterexample);
    assert_eq!(on.results[0].depth, 2);
}
