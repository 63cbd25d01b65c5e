//! Event renaming (`instance p1: Phil { take -> take1; }`, docs/synthesis.md): one chart type
//! instantiated with different alphabets gives exactly the automata of the copied charts it
//! replaces, renamed events synchronise by their new names (requirements included), the
//! controllability rule holds across renames, renames work inside components, and the tick
//! semantics keeps the chart's own input names.

mod common;
use common::{example, model_of, problem_of, sizes};

use statecheck_synth::{extract, Engine, Problem};

/// `philosophers_5_renamed.sc` (one `Phil`, one `Fork` chart, ten renaming instances) is the
/// generated `philosophers_5.sc` (ten copied charts): the same events in the same order, the
/// same automata (names, locations, marking, alphabets, transitions) — only the chart names
/// differ — and so the same supervisor, 81 states and 260 transitions (the generated family's
/// answer, which `benchmarks.rs` checks against the independent reference).
#[test]
fn renamed_philosophers_are_the_copied_charts() {
    let copied = problem_of(&example("philosophers_5.sc"), None);
    let renamed = problem_of(&example("philosophers_5_renamed.sc"), None);
    let events = |p: &Problem| {
        p.events
            .iter()
            .map(|e| (e.name.clone(), e.controllable))
            .collect::<Vec<_>>()
    };
    assert_eq!(events(&copied), events(&renamed));
    assert_eq!(copied.automata.len(), renamed.automata.len());
    for (a, b) in copied.automata.iter().zip(&renamed.automata) {
        assert_eq!(a.name, b.name);
        assert_eq!(a.kind, b.kind);
        assert_eq!(a.locs, b.locs);
        assert_eq!(a.marked, b.marked);
        assert_eq!(a.initial, b.initial);
        assert_eq!(a.alphabet, b.alphabet, "{}", a.name);
        assert_eq!(
            a.transitions().collect::<Vec<_>>(),
            b.transitions().collect::<Vec<_>>(),
            "{}",
            a.name
        );
    }
    let charts: Vec<&str> = renamed.automata.iter().map(|a| a.chart.as_str()).collect();
    assert_eq!(charts[..2], ["Phil", "Fork"]);
    for engine in [Engine::Explicit, Engine::Symbolic] {
        assert_eq!(sizes(&renamed, engine), Some((81, 260)), "{engine:?}");
    }
}

/// Wonham's small factory with ONE machine chart: `m1` and `m2` rename its events to
/// `start1`/`finish1`/… and `start2`/…, the buffer synchronises with `finish1` and `start2`.
const FACTORY: &str = "
plant chart Machine {
    controllable event start;
    uncontrollable event finish;
    uncontrollable event brk;
    controllable event repair;
    initial Idle;
    marked state Idle { on start -> Working; }
    state Working { on finish -> Idle; on brk -> Down; }
    state Down { on repair -> Idle; }
}
requirement chart Buffer {
    uncontrollable event put;
    controllable event get;
    initial Empty;
    marked state Empty { on put -> Full; }
    state Full { on get -> Empty; }
}
system SmallFactory {
    instance m1: Machine { start -> start1; finish -> finish1; brk -> break1; repair -> repair1; }
    instance m2: Machine { start -> start2; finish -> finish2; brk -> break2; repair -> repair2; }
    instance buf: Buffer { put -> finish1; get -> start2; }
}
system SmallFactoryRepair {
    instance m1: Machine { start -> start1; finish -> finish1; brk -> break1; repair -> repair1; }
    instance m2: Machine { start -> start2; finish -> finish2; brk -> break2; repair -> repair2; }
    instance buf: Buffer { put -> finish1; get -> start2; }
    requirement repair1 needs (!in(m2.Down));
}
component Line {
    instance m1: Machine { start -> start1; finish -> finish1; brk -> break1; repair -> repair1; }
    instance m2: Machine { start -> start2; finish -> finish2; brk -> break2; repair -> repair2; }
    instance buf: Buffer { put -> finish1; get -> start2; }
}
system InAComponent {
    instance line: Line;
}
";

/// The answers of `examples/synthesis/small_factory.sc` (two copied machine charts), which
/// are Wonham's: 12 states and 25 transitions with the buffer; with "repair M2 first"
/// (a `needs` on the renamed `repair1`), FACTSUPER's 12 states and 24 transitions. The same
/// from the machines inside a component (automata named by path, `line.m1`).
#[test]
fn renamed_events_synchronise_by_their_new_names() {
    let copied = problem_of(&example("small_factory.sc"), Some("SmallFactory"));
    for (system, expected) in [
        ("SmallFactory", (12, 25)),
        ("SmallFactoryRepair", (12, 24)),
        ("InAComponent", (12, 25)),
    ] {
        let p = problem_of(FACTORY, Some(system));
        for engine in [Engine::Explicit, Engine::Symbolic] {
            assert_eq!(sizes(&p, engine), Some(expected), "{system} {engine:?}");
        }
        let mut names: Vec<&str> = p.events.iter().map(|e| e.name.as_str()).collect();
        let mut want: Vec<&str> = copied.events.iter().map(|e| e.name.as_str()).collect();
        names.sort_unstable();
        want.sort_unstable();
        assert_eq!(names, want, "{system}");
    }
    let p = problem_of(FACTORY, Some("InAComponent"));
    let autos: Vec<&str> = p.automata.iter().map(|a| a.name.as_str()).collect();
    assert_eq!(autos, ["line.m1", "line.m2", "line.buf"]);
}

/// A rename cannot change an event's controllability: `go` is controllable in `A`, renamed to
/// `u`, which `B` declares uncontrollable — E0704, as for two charts declaring `u` both ways.
#[test]
fn a_rename_keeps_the_controllability_rule() {
    let text = "
plant chart A { controllable event go; initial S; state S { on go -> S; } }
plant chart B { uncontrollable event u; initial S; state S { on u -> S; } }
system S { instance a: A { go -> u; } instance b: B; }
";
    let model = model_of(text);
    let sys = extract::find_system(&model, Some("S")).expect("system");
    let diags = extract::extract(&model, sys).expect_err("E0704 expected");
    assert!(
        diags.iter().any(|d| d.code == "E0704"),
        "{:?}",
        diags.iter().map(|d| d.code).collect::<Vec<_>>()
    );
}

/// Only synthesis reads renames: in the tick semantics the instances' inputs keep the chart's
/// names (`m1.start`, not `start1`).
#[test]
fn the_tick_semantics_keeps_the_charts_input_names() {
    let model = model_of(FACTORY);
    let sys = model
        .systems
        .iter()
        .find(|s| s.name == "SmallFactory")
        .expect("system");
    let program = statecheck_ir::lower(&model, sys).expect("lower");
    let inputs: Vec<&str> = program.inputs.iter().map(|i| i.name.as_str()).collect();
    assert!(inputs.contains(&"m1.start"), "{inputs:?}");
    assert!(inputs.contains(&"buf.put"), "{inputs:?}");
    assert!(!inputs.iter().any(|n| n.ends_with("start1")), "{inputs:?}");
}
