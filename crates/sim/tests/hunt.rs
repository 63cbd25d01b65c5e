//! The lasso hunt (`statecheck_sim::hunt`) finds a lasso that needs a fault held for 40 ticks
//! (a random run drawing each tick on its own would need 2^-40 luck), every lasso it reports
//! replays as a violation, and it reports none for a property that holds.

use statecheck_ir::{lower, Program};
use statecheck_sim::hunt::{hunt, HuntOptions};
use statecheck_sim::lasso::run_lasso;
use statecheck_sim::scenario::from_lasso;
use statecheck_sim::Options;

// `held` counts consecutive ticks with `fault`; the 40th in a row (held == 39 before it)
// enters `Dead`, where `stuck` stays set for ever. Outside `Dead`, `stuck` is set in a tick
// with `fault` and cleared in one without.
//
// Hand derivation:
// - `recovers` (`F G !fault => G(stuck => F !stuck)`) is violated exactly by the runs that
//   reach `Dead` and then have no fault from some tick on: outside `Dead` every `stuck` is
//   cleared by the first tick without fault, which `F G !fault` guarantees. Reaching `Dead`
//   needs 40 consecutive ticks with `fault` (tick 0 enters the initial state and counts
//   nothing, so ticks 1..40 at the earliest).
// - `holds` (`G(stuck => F(!stuck || in(Dead)))`) holds: in `Ok`, `stuck` lasts at most while
//   `fault` does, and after 40 ticks of it the chart is in `Dead`.
const MODEL: &str = r#"
chart C {
  input fault: bool = false;
  output held: int[0..40] = 0;
  output stuck: bool = false;
  initial Ok;
  state Ok {
    on [fault && held == 39] / { stuck = true; } -> Dead;
    on [fault] / { held += 1; stuck = true; };
    on [!fault] / { held = 0; stuck = false; };
  }
  state Dead { }
}
system Sys {
  instance c: C;
  ltl recovers: F G !c.fault => G(c.stuck => F !c.stuck);
  ltl holds: G(c.stuck => F(!c.stuck || in(c.Dead)));
}
"#;

fn program() -> Program {
    let (file, d1) = statecheck_syntax::parse(MODEL);
    let (model, d2) = statecheck_model::check(&file);
    assert!(d1.iter().chain(&d2).all(|d| !d.is_error()), "{d1:?} {d2:?}");
    lower(&model, &model.systems[0]).expect("lowers")
}

/// The longest run of consecutive ticks with `fault` in `inputs`.
fn longest_fault(inputs: &[Vec<i64>]) -> usize {
    let (mut best, mut cur) = (0, 0);
    for v in inputs {
        cur = if v[0] != 0 { cur + 1 } else { 0 };
        best = best.max(cur);
    }
    best
}

#[test]
fn hunt_finds_the_deep_lasso_and_it_replays() {
    let p = program();
    assert_eq!(p.inputs.len(), 1);
    let recovers = p
        .temporal
        .iter()
        .position(|t| t.name == "recovers")
        .expect("declared");
    let opts = HuntOptions {
        seed: 7,
        max_attempts: Some(20_000),
        ..Default::default()
    };
    let mut found = Vec::new();
    let stats = hunt(&p, &[recovers], &opts, &|_| true, &mut |f| found.push(f));
    assert_eq!(found.len(), 1, "no lasso in {stats:?}");
    let f = &found[0];
    assert_eq!(f.property, recovers);
    // Necessary by the derivation above: 40 consecutive faults after tick 0, and a loop
    // without any fault (`F G !fault`).
    assert!(longest_fault(&f.inputs[1..]) >= 40, "{:?}", f.inputs);
    assert!(f.inputs[f.loop_start..].iter().all(|v| v[0] == 0));
    // The simulator replays it: the loop closes and `recovers` is violated.
    let sc = from_lasso(&p, &f.inputs, f.loop_start);
    let run = run_lasso(&p, &sc, Options::default());
    assert!(run.broken.is_none(), "{:?}", run.broken);
    assert_eq!(run.violated, vec!["recovers".to_string()]);
}

#[test]
fn hunt_reports_nothing_for_a_property_that_holds() {
    let p = program();
    let holds = p
        .temporal
        .iter()
        .position(|t| t.name == "holds")
        .expect("declared");
    let opts = HuntOptions {
        seed: 3,
        max_attempts: Some(2_000),
        ..Default::default()
    };
    let mut found = Vec::new();
    let stats = hunt(&p, &[holds], &opts, &|_| true, &mut |f| found.push(f));
    assert!(found.is_empty(), "{found:?}");
    // The attempts did close loops (the hunt ran, it found nothing to report).
    assert!(stats.loops > 100, "{stats:?}");
}

// A job that finishes when `a` reads the same in a tick with `ph == 0` and the next one
// (`ph == 1`); `ph` counts ticks modulo 4 from tick 1 (tick 0 only enters `S`).
//
// Hand derivation: `finishes` (`F !waiting`) is violated exactly by the runs in which `a`
// differs between every tick with `ph == 0` and the next tick: once it reads equal, `waiting`
// is false for ever. So no lasso whose loop holds `a` constant violates it (the loop repeats
// for ever and takes in a `ph == 0` tick and the next one, as the loop is at least as long
// as the period 4 or repeats inside it), and the lasso that holds `a` and `!a` alternately
// does (consecutive ticks differ).
const PERIODIC: &str = r#"
chart C {
  input a: bool = false;
  output ph: int[0..3] = 0;
  output waiting: bool = true;
  local first: bool = false;
  initial S;
  state S {
    during {
      if ph == 0 { first = a; }
      if ph == 1 && a == first { waiting = false; }
      ph = (ph + 1) % 4;
    }
  }
}
system Sys {
  instance c: C;
  ltl finishes: F !c.waiting;
}
"#;

#[test]
fn hunt_finds_a_lasso_whose_loop_needs_a_periodic_input() {
    let (file, d1) = statecheck_syntax::parse(PERIODIC);
    let (model, d2) = statecheck_model::check(&file);
    assert!(d1.iter().chain(&d2).all(|d| !d.is_error()), "{d1:?} {d2:?}");
    let p = lower(&model, &model.systems[0]).expect("lowers");
    let opts = HuntOptions {
        seed: 11,
        max_attempts: Some(20_000),
        ..Default::default()
    };
    let mut found = Vec::new();
    let stats = hunt(&p, &[0], &opts, &|_| true, &mut |f| found.push(f));
    assert_eq!(found.len(), 1, "no lasso in {stats:?}");
    let f = &found[0];
    // Necessary by the derivation: `a` is not constant in the loop.
    let a = |v: &Vec<i64>| v[0];
    let lp = &f.inputs[f.loop_start..];
    assert!(lp.iter().any(|v| a(v) != a(&lp[0])), "{:?}", f.inputs);
    let sc = from_lasso(&p, &f.inputs, f.loop_start);
    let run = run_lasso(&p, &sc, Options::default());
    assert!(run.broken.is_none(), "{:?}", run.broken);
    assert_eq!(run.violated, vec!["finishes".to_string()]);
}
