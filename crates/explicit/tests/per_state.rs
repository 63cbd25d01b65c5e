//! Properties that read only the state are checked once per new state instead of on every
//! transition: the verdicts, depths and counterexamples must be those of the per-transition
//! check. The reference here is the same property made to read an input (so it is checked on
//! every transition) without changing its value.

use statecheck_explicit::{verify, Options, Verdict};

#[test]
fn per_state_checks_match_per_transition_checks() {
    // Two counters; `a` counts up on `inc`, `b` on `dec` down from 9. `k.x == 3 && k.y == 7`
    // needs 3 `inc`s and 2 `dec`s, one event per tick after the start tick: 6 ticks.
    let text = "chart K {\n  input event inc;\n  input event dec;\n  output x: int[0..9] = 0;\n  output y: int[0..9] = 9;\n  initial S;\n  state S {\n    on inc [x < 9] / { x += 1; };\n    on dec [y > 0] / { y -= 1; };\n  }\n}\nsystem Sys {\n  instance k: K;\n  assume !(k.inc && k.dec);\n  invariant state_only: !(k.x == 3 && k.y == 7);\n  invariant with_input: !(k.x == 3 && k.y == 7) || (k.inc && k.dec);\n  reachable r_state: k.x == 9 && k.y == 0;\n  reachable r_input: (k.x == 9 && k.y == 0) && !(k.inc && k.dec);\n}\n";
    let (file, d1) = statecheck_syntax::parse(text);
    let (model, d2) = statecheck_model::check(&file);
    assert!(!d1.iter().chain(&d2).any(|d| d.is_error()), "{d1:?}{d2:?}");
    let p = statecheck_ir::lower(&model, model.system("Sys").expect("Sys")).expect("lowers");
    for threads in [1, 2] {
        let r = verify(
            &p,
            &Options {
                threads,
                ..Options::default()
            },
            None,
        )
        .expect("runs");
        let [a, b, c, d] = [0, 1, 2, 3].map(|i| &r.results[i]);
        assert_eq!(a.verdict, Verdict::Violated);
        assert_eq!(a.depth, 6);
        assert_eq!(
            (a.verdict, a.depth, &a.counterexample),
            (b.verdict, b.depth, &b.counterexample)
        );
        // 9 incs and 9 decs after the start tick: 19 ticks.
        assert_eq!(c.verdict, Verdict::Reachable);
        assert_eq!(c.depth, 19);
        assert_eq!(
            (c.verdict, c.depth, &c.counterexample),
            (d.verdict, d.depth, &d.counterexample)
        );
    }
}
