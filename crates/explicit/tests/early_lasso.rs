//! Early accepting-cycle detection: when a limit stops the temporal graph, lassos are still
//! looked for in the part built, and one found is a counterexample; proofs stay `unknown`.

use statecheck_explicit::{ltl, Options, Verdict};

#[test]
fn a_lasso_in_a_partial_graph_is_a_violation() {
    // A counter saturating at 5000 on `inc`: 5001 states, more than the 10 allowed (the
    // limit is checked every 1024 states, so about 1025 are expanded). `F x == 5000` is
    // violated by "no inc, ever" (x stays 0: a lasso within the first states); `G x <= 5000`
    // holds (the type's range), which an incomplete graph cannot show; `G x < 3000` is
    // violated, but only by runs of at least 3001 ticks, beyond the part built.
    let text = "chart K {\n  input event inc;\n  output x: int[0..5000] = 0;\n  initial S;\n  state S {\n    on inc [x < 5000] / { x += 1; };\n  }\n}\nsystem Sys {\n  instance k: K;\n  ltl reaches_top: F k.x == 5000;\n  ltl bounded: G k.x <= 5000;\n  ltl stays_low: G k.x < 3000;\n}\n";
    let (file, d1) = statecheck_syntax::parse(text);
    let (model, d2) = statecheck_model::check(&file);
    assert!(!d1.iter().chain(&d2).any(|d| d.is_error()), "{d1:?}{d2:?}");
    let p = statecheck_ir::lower(&model, model.system("Sys").expect("Sys")).expect("lowers");
    let opts = Options {
        max_states: Some(10),
        ..Options::default()
    };
    let (r, _) = ltl::check(&p, None, &opts);
    let get = |n: &str| r.iter().find(|x| x.name == n).expect(n);
    let top = get("reaches_top");
    assert_eq!(top.verdict, Verdict::Violated, "{top:?}");
    assert_eq!(get("bounded").verdict, Verdict::Unknown);
    assert_eq!(get("stays_low").verdict, Verdict::Unknown);
    // The lasso replays: the state after tick loop_start - 1 recurs after the last tick, and
    // x never reaches 5000 on it.
    let ticks = top.counterexample.as_ref().expect("lasso");
    let k = top.loop_start.expect("loop") as usize;
    assert!(k >= 1 && k < ticks.len(), "loop {k} of {}", ticks.len());
    let mut m = statecheck_ir::Machine::new(&p);
    let mut states = Vec::new();
    for v in ticks {
        for (inp, &x) in p.inputs.iter().zip(v) {
            m.set(inp.slot, x);
        }
        m.step().expect("steps");
        states.push(m.state().to_vec());
    }
    assert_eq!(states[k - 1], states[ticks.len() - 1]);
}
