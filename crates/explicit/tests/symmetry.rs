//! Symmetry reduction on arrays of identical, independent counters: the state counts with and
//! without it are derived by hand, the verdicts are equal, and every counterexample replays
//! (stepped here with the IR's `Machine`) to a state that decides its own property.

use statecheck_explicit::{verify, Options, Report, Verdict};
use statecheck_ir::symmetry::detect;
use statecheck_ir::{Machine, Program};
use std::sync::Arc;

/// `n` counters modulo `k`, each advanced by its own free input event; chart properties (one
/// per element) and a system property over no element.
fn counters(n: usize, k: usize, extra: &str) -> String {
    format!(
        "chart Counter {{\n  input event inc;\n  output c: int[0..{m}] = 0;\n  initial S;\n  state S {{ on inc / {{ c = (c + 1) % {k}; }}; }}\n  invariant below: c != {m};\n  reachable top: c == {m};\n}}\nchart Env {{\n  input go: bool = false;\n  output seen: bool = false;\n  initial S;\n  state S {{ during {{ seen = go; }} }}\n}}\nsystem Sys {{\n  instance e: Env;\n  instance a[{n}]: Counter;\n  invariant env_ok: e.seen || !e.seen;\n{extra}}}\n",
        m = k - 1
    )
}

fn program(text: &str) -> (statecheck_model::Model, Program) {
    let (file, d1) = statecheck_syntax::parse(text);
    let (model, d2) = statecheck_model::check(&file);
    assert!(!d1.iter().chain(&d2).any(|d| d.is_error()), "{d1:?}{d2:?}");
    let p = statecheck_ir::lower(&model, model.system("Sys").expect("Sys")).expect("lowers");
    (model, p)
}

fn run(model: &statecheck_model::Model, p: &Program, symmetry: bool) -> Report {
    let sym = symmetry.then(|| {
        let d = detect(model.system("Sys").expect("Sys"), p);
        Arc::new(d.symmetry)
    });
    verify(
        p,
        &Options {
            threads: 1,
            symmetry: sym,
            ..Options::default()
        },
        None,
    )
    .expect("runs")
}

fn binom(n: u64, k: u64) -> u64 {
    (1..=k).fold(1, |acc, i| acc * (n + 1 - i) / i)
}

/// Replay inputs from the initial state; the final state.
fn replay(p: &Program, run: &[Vec<i64>]) -> Vec<i64> {
    let mut m = Machine::new(p);
    for v in run {
        let s = m.state().to_vec();
        m.load(&s, v);
        m.step().expect("no run-time error");
    }
    m.state().to_vec()
}

#[test]
fn counters_store_one_state_per_multiset() {
    for (n, k) in [(2usize, 3usize), (3, 3), (3, 4), (4, 2)] {
        let (model, p) = program(&counters(n, k, ""));
        let d = detect(model.system("Sys").expect("Sys"), &p);
        assert!(d.diagnostics.is_empty(), "{:?}", d.diagnostics);
        assert_eq!(d.symmetry.groups.len(), 1);
        let full = run(&model, &p, false);
        let red = run(&model, &p, true);
        assert!(full.stats.complete && red.stats.complete);
        assert!(red.stats.symmetry, "{:?}", red.stats.symmetry_note);
        // By hand: the state before tick 0; tick 0 starts every chart (counters at 0, `seen`
        // false), and from tick 1 on each counter moves on its own input and `seen` copies
        // `go`: every vector of counter values with either `seen`. Without symmetry
        // 1 + k^n·2 states; with it 1 + C(n+k-1, n)·2 (multisets of counter values).
        let kn = (k as u64).pow(n as u32);
        assert_eq!(full.stats.states, 1 + kn * 2, "n={n} k={k}");
        assert_eq!(
            red.stats.states,
            1 + binom((n + k - 1) as u64, n as u64) * 2,
            "n={n} k={k}"
        );
        // Verdicts equal, member by member.
        for (a, b) in full.results.iter().zip(&red.results) {
            assert_eq!(a.name, b.name);
            assert_eq!((a.verdict, a.depth), (b.verdict, b.depth), "{}", a.name);
        }
    }
}

#[test]
fn counterexamples_under_symmetry_replay_to_their_own_element() {
    let (model, p) = program(&counters(3, 3, ""));
    let red = run(&model, &p, true);
    for i in 0..3 {
        let name = format!("a[{i}].below");
        let r = red.results.iter().find(|r| r.name == name).expect("row");
        // Tick 0 starts the counters at 0; two `inc`s of element i reach 2: 3 ticks.
        assert_eq!((r.verdict, r.depth), (Verdict::Violated, 3), "{name}");
        let cex = r.counterexample.as_ref().expect("counterexample");
        let end = replay(&p, cex);
        let slot = p
            .slots
            .iter()
            .position(|s| s.name == format!("a[{i}].c"))
            .expect("slot");
        assert_eq!(end[slot], 2, "{name}: {cex:?}");
        let reach = format!("a[{i}].top");
        let r = red.results.iter().find(|r| r.name == reach).expect("row");
        assert_eq!(r.verdict, Verdict::Reachable);
        let end = replay(&p, r.counterexample.as_ref().expect("witness"));
        assert_eq!(end[slot], 2, "{reach}");
    }
}

#[test]
fn a_property_naming_one_element_turns_symmetry_off() {
    let (model, p) = program(&counters(3, 3, "  invariant first: a[0].c != 2;\n"));
    let d = detect(model.system("Sys").expect("Sys"), &p);
    assert!(d.symmetry.groups.is_empty());
    assert_eq!(d.diagnostics.len(), 1);
    assert_eq!(d.diagnostics[0].code, "W0317");
    assert!(
        d.diagnostics[0].message.contains("`first`"),
        "{}",
        d.diagnostics[0].message
    );
    let red = run(&model, &p, true);
    assert!(!red.stats.symmetry);
    assert_eq!(red.stats.states, 1 + 27 * 2);
}

/// The guard against a wrong detection: a symmetry claimed by hand for a ring of elements
/// that read each other in index order (tests/semantics/array_order.sc) is refuted on the
/// step before the search, which then runs without it and says why. By hand: from (1, 2, 3)
/// after tick 1 the ring steps to (4, 5, 6); with the first two elements exchanged, (2, 1, 3)
/// steps to (4, 5, 6), not to the exchanged (5, 4, 6).
#[test]
fn a_wrongly_claimed_symmetry_is_refuted_on_the_step() {
    let text = "chart C {\n  input i: int[0..9] = 0;\n  output o: int[0..9] = 0;\n  initial S;\n  state S { during { o = min(i + 1, 9); } }\n}\nsystem Sys {\n  instance a[3]: C;\n  connect a[0].o -> a[1].i;\n  connect a[1].o -> a[2].i;\n  connect a[2].o -> a[0].i;\n  invariant small: a[0].o + a[1].o + a[2].o < 30;\n}\n";
    let (model, p) = program(text);
    let d = detect(model.system("Sys").expect("Sys"), &p);
    assert!(d.symmetry.groups.is_empty());
    assert!(d.diagnostics.iter().any(|d| d.code == "W0316"));
    let slot = |k: usize| {
        p.slots
            .iter()
            .position(|s| s.name == format!("a[{k}].o"))
            .expect("slot") as u32
    };
    let claimed = statecheck_ir::symmetry::Symmetry {
        groups: vec![statecheck_ir::symmetry::Group {
            array: "a".into(),
            blocks: (0..3).map(|k| vec![slot(k)]).collect(),
            inputs: vec![Vec::new(); 3],
            families: Vec::new(),
        }],
    };
    let r = verify(
        &p,
        &Options {
            threads: 1,
            symmetry: Some(Arc::new(claimed)),
            ..Options::default()
        },
        None,
    )
    .expect("runs");
    assert!(!r.stats.symmetry);
    let note = r.stats.symmetry_note.unwrap_or_default();
    assert!(note.contains("does not treat the elements alike"), "{note}");
}
