//! Every benchmark of `examples/synthesis/` with both engines: supervisor sizes against the
//! published or hand-derived answers, and every synthesized supervisor emitted as `.sc`,
//! lowered through the normal pipeline and checked in the closed loop by `check` (which shares
//! no code with the fixpoints).

mod common;
use common::{example, problem_of};

use statecheck_synth::{check, emit, families, synthesize, Engine, Outcome, Problem};

/// Check an emitted supervisor text in the closed loop.
fn check_text(p: &Problem, text: &str) -> check::Report {
    let (file, diags) = statecheck_syntax::parse(text);
    assert!(diags.is_empty(), "{diags:?}\n{text}");
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}\n{text}");
    let sys = model.systems.iter().find(|s| !s.implicit).expect("system");
    let program = statecheck_ir::lower(&model, sys).expect("lower");
    check::check(p, &model, &program).expect("check runs")
}

/// Synthesize with both engines, compare, verify the emitted chart; returns (states, transitions).
fn both(p: &Problem) -> (u128, u128) {
    let mut sizes = Vec::new();
    for engine in [Engine::Explicit, Engine::Symbolic] {
        let s = synthesize(p, engine).expect("synthesis");
        let Outcome::Supervisor(sup) = s.outcome else {
            panic!("{engine:?}: empty supervisor");
        };
        let text = emit::emit(p, &sup, "test");
        let r = check_text(p, &text);
        assert!(r.violations.is_empty(), "{engine:?}: {:?}", r.violations);
        // Maximal permissiveness seen from outside: the closed loop visits exactly the
        // supervisor's states.
        assert_eq!(r.plant_states as u128, sup.states, "{engine:?}");
        sizes.push((sup.states, sup.transitions));
    }
    assert_eq!(sizes[0], sizes[1], "engines disagree");
    sizes[0]
}

#[test]
fn small_factory() {
    let text = example("small_factory.sc");
    // Buffer only: 12 states (see the model's comment). Transitions, counted by hand: M1 has
    // 3 (start, buffer empty) + 6 (finish/break) + 3 (repair) = 12; M2 has 1 (start, buffer
    // full, M1 idle) + 8 (finish/break in the 4 states where it works) + 4 (repair) = 13.
    assert_eq!(both(&problem_of(&text, Some("SmallFactory"))), (12, 25));
    // With "repair M2 first": Wonham's FACTSUPER (12, 24): repair1 is disabled in the one
    // reachable state where both machines are down.
    assert_eq!(
        both(&problem_of(&text, Some("SmallFactoryRepair"))),
        (12, 24)
    );
}

#[test]
fn cat_and_mouse() {
    // The published supervisor: 6 states, 9 transitions.
    assert_eq!(both(&problem_of(&example("cat_mouse.sc"), None)), (6, 9));
}

#[test]
fn transfer_line() {
    // Wonham's TLSUP: (28, 65).
    assert_eq!(
        both(&problem_of(&example("transfer_line.sc"), None)),
        (28, 65)
    );
}

#[test]
fn line_family_sizes() {
    // 3 * 4^(n-1) states (derivation in `families::line`).
    for n in 2..=6u32 {
        let (states, _) = both(&problem_of(&families::line(n as usize), None));
        assert_eq!(states, 3 * 4u128.pow(n - 1), "n = {n}");
    }
}

#[test]
fn philosophers() {
    // Two philosophers, derived by hand: the plant reaches 6 states — both thinking; one
    // holding its left fork or eating while the other thinks (2 + 2); both holding their left
    // fork, a deadlock (1). Only the deadlock goes (its entries are controllable `take`s), so
    // the supervisor has 5 states.
    let (states, _) = both(&problem_of(&families::philosophers(2), None));
    assert_eq!(states, 5);
    let _ = both(&problem_of(&families::philosophers(3), None));
}

#[test]
fn generated_examples_are_current() {
    assert_eq!(example("philosophers_5.sc"), families::philosophers(5));
    assert_eq!(example("line_4.sc"), families::line(4));
    assert_eq!(example("line_12.sc"), families::line(12));
}

const EMPTY: &str = "
plant chart Tank {
    controllable event fill;
    uncontrollable event leak;
    initial Low;
    marked state Low { on fill -> High; on leak -> Empty; }
    state High { on leak -> Low; }
    state Empty;
}
system S {
    instance t: Tank;
    requirement never (in(t.Empty));
}
";

#[test]
fn empty_supervisor_has_a_reason() {
    let p = problem_of(EMPTY, None);
    for engine in [Engine::Explicit, Engine::Symbolic] {
        match synthesize(&p, engine).expect("runs").outcome {
            Outcome::Empty(why) => {
                assert!(why.contains("`leak`"), "{why}");
                assert!(why.contains("t.Empty"), "{why}");
            }
            Outcome::Supervisor(_) => panic!("{engine:?} found a supervisor"),
        }
    }
}

#[test]
fn check_catches_bad_supervisors() {
    let p = problem_of(&example("small_factory.sc"), Some("SmallFactory"));
    let Outcome::Supervisor(sup) = synthesize(&p, Engine::Explicit).expect("runs").outcome else {
        panic!("empty");
    };
    let good = emit::emit(&p, &sup, "test");
    // Not controllable: the supervisor refuses M1's (uncontrollable) finish.
    let bad = good.replacen(
        "if ev == Event.finish1 && at_m1 == Loc_m1.Working {",
        "if ev == Event.finish1 && false {",
        1,
    );
    assert_ne!(bad, good);
    let r = check_text(&p, &bad);
    assert!(
        r.violations.iter().any(|v| v.contains("not controllable")),
        "{:?}",
        r.violations
    );
    // Blocking: M2 may never start, so a finished part stays in the buffer forever.
    let bad = good.replace("allow_start2 = ", "allow_start2 = false && ");
    let r = check_text(&p, &bad);
    assert!(
        r.violations.iter().any(|v| v.starts_with("blocking")),
        "{:?}",
        r.violations
    );
    // Requirement violated: M1 may start on a full buffer.
    let bad = good.replace("allow_start1 = ", "allow_start1 = at_m1 == Loc_m1.Idle || ");
    let r = check_text(&p, &bad);
    assert!(
        r.violations
            .iter()
            .any(|v| v.contains("violates the requirements")),
        "{:?}",
        r.violations
    );
}

/// The reference implementation's figures (`examples/synthesis/reference.py`, which builds
/// the automata itself from the families' descriptions): (product, supervisor states,
/// transitions).
fn reference(family: &str, n: usize, k: usize) -> (f64, u128, u128) {
    let script = format!(
        "{}/../../examples/synthesis/reference.py",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = std::process::Command::new("python3")
        .args([&script, family, &n.to_string(), &k.to_string()])
        .output()
        .expect("python3 runs");
    assert!(out.status.success(), "{out:?}");
    let text = String::from_utf8_lossy(&out.stdout);
    let w: Vec<&str> = text.split_whitespace().collect();
    // "reference T product P supervisor S states N transitions"
    let num = |key: &str| -> &str {
        let i = w.iter().position(|x| *x == key).expect(key);
        w[i + 1]
    };
    (
        num("product").parse().expect("product"),
        num("supervisor").parse().expect("states"),
        w[w.len() - 2].parse().expect("transitions"),
    )
}

#[test]
fn scaled_families_match_the_reference() {
    for (family, n, k) in [
        ("tl", 2, 1),
        ("tl", 3, 2),
        ("dp", 3, 1),
        ("dp", 3, 2),
        ("cm", 1, 1),
        ("cm", 2, 1),
        ("at", 2, 2),
        ("at", 3, 2),
        ("bw", 2, 2),
        ("bw", 3, 1),
        ("ta", 2, 2),
        ("ta", 3, 1),
    ] {
        let text = families::scaled::generate(family, n, k).expect("in range");
        let p = problem_of(&text, None);
        let (product, states, transitions) = reference(family, n, k);
        let s = synthesize(&p, Engine::Symbolic).expect("runs");
        assert_eq!(s.product_states, product, "{family}({n},{k}) product");
        assert_eq!(both(&p), (states, transitions), "{family}({n},{k})");
    }
    // TL(n, 1) is the line family, whose size is derived by hand (3 * 4^(n-1)).
    assert_eq!(
        reference("tl", 3, 1).1,
        48,
        "reference disagrees with the hand derivation"
    );
}

#[test]
fn removals_cascade_over_three_rounds() {
    // Derived by hand, one round at a time (the explicit engine recomputes nonblocking
    // incrementally after the first round, so this walks that path twice):
    // round 1: `Dead` reaches no marked state and goes; round 2: `B` has the uncontrollable
    // `u1` into `Dead` and goes, then `Z` (whose only way on was `B`) blocks and goes;
    // round 3: `W` has the uncontrollable `u2` into `Z` and goes; `S0` (marked) and `E` stay.
    // Supervisor: {S0, E} with `c6` and `u3`: 2 states, 2 transitions.
    let text = "
plant chart P {
    controllable event c1; controllable event c2; controllable event c3;
    controllable event c4; controllable event c5; controllable event c6;
    uncontrollable event u1; uncontrollable event u2; uncontrollable event u3;
    initial S0;
    marked state S0 { on c1 -> Z; on c2 -> W; on c6 -> E; }
    state Z { on c3 -> B; }
    state B { on u1 -> Dead; on c4 -> S0; }
    state Dead { }
    state W { on u2 -> Z; on c5 -> S0; }
    state E { on u3 -> S0; }
}
system Cascade { instance p: P; }
";
    let p = problem_of(text, None);
    assert_eq!(both(&p), (2, 2));
    let x =
        statecheck_synth::explicit::run(&p, &statecheck_synth::Budget::new(&Default::default()))
            .expect("explicit");
    assert_eq!((x.product_states, x.rounds), (6, 3));
}
