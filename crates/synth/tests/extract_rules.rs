//! Synthesis reads the checked model: the problem it extracts, and the rules E0701–E0712 a
//! synthesis system must follow (docs/synthesis.md), each on a model that breaks one rule.

use statecheck_synth::problem::Pred;
use statecheck_synth::{extract, Problem};

/// The checked model of `text` (which must check without errors) and the codes `extract`
/// reports for its only system, or the problem.
fn extract_text(text: &str) -> Result<Problem, Vec<&'static str>> {
    let (file, diags) = statecheck_syntax::parse(text);
    assert!(diags.is_empty(), "{diags:?}");
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
    let sys = extract::find_system(&model, None).expect("one system");
    extract::extract(&model, sys).map_err(|d| d.iter().map(|d| d.code).collect())
}

const MACHINE: &str = r#"
plant chart Machine {
    controllable event start;
    uncontrollable event finish;
    initial Idle;
    marked state Idle { on start -> Working; }
    state Working { on finish -> Idle; on start; }
}
"#;

#[test]
fn a_plant_and_a_requirement_become_automata_over_one_alphabet() {
    let p = extract_text(&format!(
        "{MACHINE}
requirement chart Once {{
    controllable event start;
    initial Ready;
    state Ready {{ on start -> Used; }}
    state Used;
}}
system S {{
    instance m: Machine;
    instance r: Once;
    requirement never (in(m.Working) && in(r.Used));
    requirement start needs (!in(r.Used));
}}"
    ))
    .expect("a valid synthesis system");
    // Events in order of first declaration; `start` is shared.
    let names: Vec<(&str, bool)> = p
        .events
        .iter()
        .map(|e| (e.name.as_str(), e.controllable))
        .collect();
    assert_eq!(names, [("start", true), ("finish", false)]);
    let m = &p.automata[0];
    assert_eq!(m.locs, ["Idle", "Working"]);
    assert_eq!(m.initial, 0);
    // Only Idle is marked.
    assert_eq!(m.marked, [true, false]);
    // Idle -start-> Working, Working -finish-> Idle, and `on start;` (no target) stays.
    assert_eq!(m.step(0, 0), Some(1));
    assert_eq!(m.step(1, 1), Some(0));
    assert_eq!(m.step(1, 0), Some(1));
    assert_eq!(m.step(0, 1), None);
    // A chart that marks no state has every state marked.
    assert_eq!(p.automata[1].marked, [true, true]);
    assert_eq!(p.automata[1].alphabet, [0]);
    assert_eq!(
        p.never,
        [Pred::And(
            Box::new(Pred::At(0, 1)),
            Box::new(Pred::At(1, 1))
        )]
    );
    assert_eq!(p.needs.len(), 1);
    assert_eq!(p.needs[0].event, 0);
    assert_eq!(p.needs[0].cond, Pred::Not(Box::new(Pred::At(1, 1))));
}

#[test]
fn each_rule_is_reported_with_its_code() {
    let cases: [(&str, &str); 10] = [
        // An instance array.
        ("system S { instance m[2]: Machine; }", "E0701"),
        // An ordinary chart.
        (
            "chart C { input event e; initial A; state A; }
system S { instance m: Machine; instance c: C; }",
            "E0702",
        ),
        // A variable in a plant chart.
        (
            "plant chart P { controllable event e; local x: int[0..1] = 0; initial A; state A { on e -> A; } }
system S { instance p: P; }",
            "E0703",
        ),
        // `start` declared uncontrollable here, controllable in Machine.
        (
            "plant chart P { uncontrollable event start; initial A; state A { on start -> A; } }
system S { instance m: Machine; instance p: P; }",
            "E0704",
        ),
        (
            "plant chart P { controllable event none; initial A; state A { on none -> A; } }
system S { instance p: P; }",
            "E0705",
        ),
        (
            "system S { instance m: Machine; requirement stop needs (in(m.Idle)); }",
            "E0706",
        ),
        (
            "requirement chart R { controllable event start; initial A; state A { on start -> A; } }
system S { instance r: R; }",
            "E0707",
        ),
        // A nested state.
        (
            "plant chart P { controllable event e; initial A; state A { initial B; state B { on e -> B; } } }
system S { instance p: P; }",
            "E0708",
        ),
        // A guard.
        (
            "plant chart P { controllable event e; initial A; state A { on e [true] -> A; } }
system S { instance p: P; }",
            "E0710",
        ),
        // A component port feeding two inner events of different names: after flattening a
        // connection from `x.a.take` to `x.b.grab`, which would not make them one event.
        (
            "plant chart P { controllable event take; initial A; state A { on take -> A; } }
plant chart Q { controllable event grab; initial A; state A { on grab -> A; } }
component Pair { input event go; instance a: P; instance b: Q; connect go -> a.take; connect go -> b.grab; }
system S { instance x: Pair; }",
            "E0734",
        ),
    ];
    for (text, code) in cases {
        let got = extract_text(&format!("{MACHINE}\n{text}")).expect_err(text);
        assert!(got.contains(&code), "{text}: expected {code}, got {got:?}");
    }
    // Nondeterminism: two transitions on `e` leave A for different states.
    let got = extract_text(
        "plant chart P { controllable event e; initial A; state A { on e -> A; on e -> B; } state B; }
system S { instance p: P; }",
    )
    .expect_err("nondeterministic");
    assert_eq!(got, ["E0711"]);
    // A state requirement that is not over locations.
    let got = extract_text(&format!(
        "{MACHINE}
plant chart Q {{ controllable event go; initial A; state A {{ on go -> A; }} }}
system S {{ instance m: Machine; instance q: Q; requirement never (in(m.Idle) == in(q.A)); }}"
    ))
    .expect_err("not a predicate");
    assert_eq!(got, ["E0712"]);
}
