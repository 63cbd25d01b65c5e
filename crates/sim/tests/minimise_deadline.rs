//! Minimising a counterexample stops undoing input changes once its deadline has passed
//! (`verify --timeout` bounds the whole command, counterexamples included), and what it
//! returns still shows the target.

use statecheck_ir::{lower, Program};
use statecheck_sim::minimise::{minimise, minimise_until, Target};

// `n` counts `go` up to 3; `noise` is read by nothing. The property fails when `n` reaches 3.
const MODEL: &str = r#"
chart C {
  input event go;
  input noise: bool;
  output n: int[0..3] = 0;
  initial S;
  state S { on go [n < 3] / { n += 1; }; }
}
system Sys { instance c: C; invariant below3: c.n < 3; }
"#;

fn program() -> Program {
    let (file, d1) = statecheck_syntax::parse(MODEL);
    let (model, d2) = statecheck_model::check(&file);
    assert!(d1.iter().chain(&d2).all(|d| !d.is_error()), "{d1:?} {d2:?}");
    lower(&model, &model.systems[0]).expect("lowers")
}

/// Inputs in `program.inputs` order, one vector per tick: `go` in every tick and `noise`
/// toggling. Tick 0 enters the initial state (its `go` counts nothing), ticks 1, 2, 3 each
/// count once, so `below3` is violated at tick 3, the last.
fn trace(p: &Program) -> Vec<Vec<i64>> {
    (0..4)
        .map(|t| {
            p.inputs
                .iter()
                .map(|i| match i.name.as_str() {
                    "c.go" => 1,
                    "c.noise" => (t % 2 == 0) as i64,
                    other => panic!("unexpected input {other}"),
                })
                .collect()
        })
        .collect()
}

#[test]
fn minimising_after_the_deadline_keeps_the_trace_as_found() {
    let p = program();
    let raw = trace(&p);
    let target = Target::Violation("below3".into());
    let noise = p
        .inputs
        .iter()
        .position(|i| i.name == "c.noise")
        .expect("c.noise");
    let go = p
        .inputs
        .iter()
        .position(|i| i.name == "c.go")
        .expect("c.go");
    // Without a deadline, `noise` (read by nothing) goes back to its previous value, false (its
    // initial value), in every tick, and so does tick 0's `go`; the other three are needed.
    let min = minimise(&p, &raw, &target).expect("shows the violation");
    assert!(min.iter().all(|v| v[noise] == 0), "{min:?}");
    assert_eq!(min.iter().map(|v| v[go]).collect::<Vec<_>>(), [0, 1, 1, 1]);
    // A deadline already passed: nothing is undone, and the trace still shows the target.
    let past = std::time::Instant::now();
    let kept = minimise_until(&p, &raw, &target, Some(past)).expect("shows the violation");
    assert_eq!(kept, raw);
}
