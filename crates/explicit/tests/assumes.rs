//! How `assume`s restrict the input vectors, against answers counted by hand.

use statecheck_explicit::{verify, Limit, Options, Report, Verdict};

fn program(text: &str, system: &str) -> statecheck_ir::Program {
    let (file, d1) = statecheck_syntax::parse(text);
    let (model, d2) = statecheck_model::check(&file);
    assert!(
        !d1.iter().chain(&d2).any(|d| d.is_error()),
        "{text}\n{d1:?}{d2:?}"
    );
    let sys = model.system(system).expect("system");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

fn run(p: &statecheck_ir::Program) -> Report {
    verify(
        p,
        &Options {
            threads: 2,
            ..Options::default()
        },
        None,
    )
    .expect("runs")
}

/// Two events `a` and `b` toggling their own bit, plus the `assume`s of each test.
fn toggles(assumes: &str) -> String {
    format!(
        "fn excl(x: bool, y: bool) -> bool = !(x && y);\nchart T {{\n  input event a;\n  input event b;\n  output x: int[0..1] = 0;\n  output y: int[0..1] = 0;\n  initial S;\n  state S {{\n    on a / {{ x = 1 - x; }};\n    on b / {{ y = 1 - y; }};\n  }}\n}}\nsystem Sys {{\n  instance t: T;\n{assumes}}}\n"
    )
}

#[test]
fn a_function_call_assume_over_inputs_is_solved_up_front() {
    // `excl(a, b)` reads only inputs (through the call's parameters): of the 4 vectors of two
    // booleans, it rules out only a = b = true, so 3 are left, counted once before exploring.
    let p = program(&toggles("  assume excl(t.a, t.b);\n"), "Sys");
    let r = run(&p);
    assert_eq!(r.stats.branching, 4);
    assert_eq!(r.stats.branching_after_assumes, Some(3));
    // States: the pre-start state, then (x, y) in {0,1}^2 — every pair is reachable by single
    // toggles — so 5; each has the same 3 transitions.
    assert_eq!(r.stats.states, 5);
    assert_eq!(r.stats.transitions, 15);
}

#[test]
fn a_state_reading_assume_does_not_stop_the_others_being_solved() {
    // The first assume reads only inputs (3 vectors, as above); the second reads the state
    // too (b only while y == 0), so it is evaluated per state and vector. The first is still
    // solved up front.
    let p = program(
        &toggles("  assume excl(t.a, t.b);\n  assume t.y == 0 || !t.b;\n"),
        "Sys",
    );
    let r = run(&p);
    assert_eq!(r.stats.branching_after_assumes, Some(3));
    // Once y is 1, b can no longer be pressed, so y stays 1: still all 4 (x, y) pairs.
    // Transitions: 3 from each state with y == 0 (the pre-start state has y == 0 too: 3 of
    // them), 2 (no event, a) from each state with y == 1 (2 of them): 3·3 + 2·2 = 13.
    assert_eq!(r.stats.states, 5);
    assert_eq!(r.stats.transitions, 13);
}

#[test]
fn a_state_only_assume_removes_every_successor_of_a_state() {
    // `t.x == 0` reads only the state: states with x == 1 have no successor at all. From
    // (0, y): no event or b keep x == 0; a gives x == 1. Reachable: pre-start, (0,0), (0,1),
    // (1,0), (1,1) — and the x == 1 states are dead ends. Transitions: 3 from each of the three
    // x == 0 states (pre-start included), none from the two others.
    let p = program(&toggles("  assume excl(t.a, t.b) && t.x == 0;\n"), "Sys");
    let r = run(&p);
    assert_eq!(r.stats.branching_after_assumes, Some(3));
    assert_eq!(r.stats.states, 5);
    assert_eq!(r.stats.transitions, 9);
}

/// One chart with `n` input events; event `i` sets `last` to `i + 1`.
fn buttons(n: usize, assume: &str) -> String {
    let inputs: String = (0..n).map(|i| format!("  input event e{i};\n")).collect();
    let ons: String = (0..n)
        .map(|i| format!("    on e{i} / {{ last = {}; }};\n", i + 1))
        .collect();
    format!(
        "chart B {{\n{inputs}  output last: int[0..{n}] = 0;\n  initial S;\n  state S {{\n{ons}  }}\n}}\nsystem Sys {{\n  instance b: B;\n  assume {assume};\n  reachable all_last: b.last == {n};\n}}\n"
    )
}

#[test]
fn many_inputs_with_a_small_allowed_space_are_explored() {
    // 24 boolean inputs: 2^24 raw vectors, too many to walk. "At most one is true" allows
    // exactly 25 (none, or one of 24), found by the pruned enumeration.
    let n = 24;
    let pairs: Vec<String> = (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| format!("!(b.e{i} && b.e{j})")))
        .collect();
    let p = program(&buttons(n, &pairs.join(" && ")), "Sys");
    let r = run(&p);
    assert_eq!(r.stats.branching, 1 << 24);
    assert_eq!(r.stats.branching_after_assumes, Some(25));
    assert!(r.stats.limit.is_none(), "{:?}", r.stats.limit);
    // `last` takes every value 0..=24 (each event sets it), plus the pre-start state: 26.
    assert_eq!(r.stats.states, 26);
    assert_eq!(r.stats.transitions, 26 * 25);
    assert_eq!(r.results[0].verdict, Verdict::Reachable);
}

#[test]
fn the_same_with_a_counting_assume() {
    // The same constraint written as a sum, which no conjunct split can take apart: the
    // interval evaluation still prunes every partial assignment with two events present.
    let n = 24;
    let sum: Vec<String> = (0..n)
        .map(|i| format!("(if b.e{i} then 1 else 0)"))
        .collect();
    let p = program(&buttons(n, &format!("{} <= 1", sum.join(" + "))), "Sys");
    let r = run(&p);
    assert_eq!(r.stats.branching_after_assumes, Some(25));
    assert_eq!(r.stats.states, 26);
}

#[test]
fn a_huge_allowed_space_is_still_refused() {
    // Only e0 and e1 are exclusive: 3 · 2^22 = 12,582,912 allowed vectors, far above the
    // million the engine enumerates per state, so the run is refused with the branching limit.
    let p = program(&buttons(24, "!(b.e0 && b.e1)"), "Sys");
    let r = run(&p);
    assert!(
        matches!(r.stats.limit, Some(Limit::Branching { .. })),
        "{:?}",
        r.stats.limit
    );
    assert_eq!(r.results[0].verdict, Verdict::Unknown);
    let msg = r
        .stats
        .limit
        .as_ref()
        .map(Limit::describe)
        .unwrap_or_default();
    assert!(msg.contains("assume") && msg.contains("ic3"), "{msg}");
}
