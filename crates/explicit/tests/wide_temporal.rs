//! The temporal graph under limits with wide inputs: the limits are read often enough that
//! a wide model stops near them (it ran minutes past `--timeout` before), and
//! `max_branching` refuses it as it does the safety search.

use statecheck_explicit::{ltl, Options, Verdict};

/// `x = a + 64 * b` every tick: 4,096 input vectors per tick, each leading to its own state
/// (4,097 states with the initial one).
const WIDE: &str = "chart W {\n  input a: int[0..63] = 0;\n  input b: int[0..63] = 0;\n  output x: int[0..4095] = 0;\n  initial S;\n  state S {\n    on [true] / { x = a + 64 * b; };\n  }\n}\nsystem Sys {\n  instance w: W;\n  ltl low: G w.x < 4000;\n}\n";

fn program() -> statecheck_ir::Program {
    let (file, d1) = statecheck_syntax::parse(WIDE);
    let (model, d2) = statecheck_model::check(&file);
    assert!(!d1.iter().chain(&d2).any(|d| d.is_error()), "{d1:?}{d2:?}");
    statecheck_ir::lower(&model, model.system("Sys").expect("Sys")).expect("lowers")
}

#[test]
fn the_graph_of_a_wide_model_stops_near_its_state_limit() {
    // The limits were read every 1024 states: with 4,096 vectors per state, 1024 expansions
    // (4 million ticks) before a limit of 3 states was noticed. Now they are read before
    // one state in max(1, 65536 / 4096) = 16, so at most 16 states are expanded: at most
    // 16 * 4096 transitions.
    let p = program();
    let limits = ltl::graph::GraphLimits {
        max_states: Some(3),
        ..Default::default()
    };
    let (g, why) = ltl::graph::build_partial(&p, &[], limits);
    assert_eq!(why, Some(ltl::graph::Stopped::States));
    assert!(g.transitions <= 16 * 4096, "{} transitions", g.transitions);
}

#[test]
fn a_temporal_property_of_a_too_wide_model_is_refused_like_a_safety_property() {
    // 4,096 vectors per tick over a `max_branching` of 1,000: unknown, nothing explored.
    let p = program();
    let opts = Options {
        max_branching: 1_000,
        ..Options::default()
    };
    let (r, _) = ltl::check(&p, None, &opts);
    let low = r.iter().find(|x| x.name == "low").expect("low");
    assert_eq!(low.verdict, Verdict::Unknown, "{low:?}");
    assert!(
        low.note.as_deref().is_some_and(|n| n.contains("Branching")),
        "{low:?}"
    );
}
