//! The lowering compiles every property to the [`Goal`] its consumers read: each kind of
//! property is given its meaning here once, and an expression whose evaluation fails reads as
//! false.

use statecheck_ir::{lower, Goal, Machine, Program};

/// A counter `c` that counts 0, 1, 2, ... one per tick from tick 1, and an input `d`.
const MODEL: &str = r#"
chart Counter {
  input d: int[0..2];
  output c: int[0..9] = 0;
  initial Run;
  state Run {
    on [c < 9] / { c += 1; };
  }
}

system S {
  instance k: Counter;
  invariant small: k.c < 3 assuming k.d == 1;
  invariant divides: 6 / k.d > 0;
  reachable five: k.c == 5;
  respond answered: k.c == 1 => k.c == 9 within 2;
  observer over4 {
    initial Watch;
    state Watch { on [k.c > 4] -> error; }
    state error;
  }
}
"#;

fn program() -> Program {
    let (file, d1) = statecheck_syntax::parse(MODEL);
    let (model, d2) = statecheck_model::check(&file);
    assert!(d1.iter().chain(&d2).all(|d| !d.is_error()), "{d1:?} {d2:?}");
    lower(&model, &model.systems[0]).expect("lowers")
}

fn goal(p: &Program, name: &str) -> Goal {
    p.properties
        .iter()
        .find(|q| q.name == name)
        .map(|q| q.goal)
        .expect("property present")
}

/// Runs `ticks` ticks with input `d` and answers whether the state after the last decides
/// the property (`Goal::decided_by` with the machine's reading of an expression).
fn decided_after(p: &Program, name: &str, ticks: usize, d: i64) -> bool {
    let mut m = Machine::new(p);
    let slot = p.inputs[0].slot;
    for _ in 0..ticks {
        m.set(slot, d);
        m.step().expect("no run-time error");
    }
    let g = goal(p, name);
    g.decided_by(|e| m.eval(e).is_ok_and(|v| v != 0))
}

#[test]
fn each_kind_of_property_has_the_goal_its_meaning_gives() {
    let p = program();
    // Invariants: `when` is the `assuming`, `holds` the invariant.
    assert!(matches!(
        goal(&p, "small"),
        Goal::Always { when: Some(_), .. }
    ));
    assert!(matches!(
        goal(&p, "divides"),
        Goal::Always { when: None, .. }
    ));
    // Reachability is the only goal decided by a witness.
    assert!(goal(&p, "five").is_reach());
    // Bounded response and observers: always, no restriction.
    for name in ["answered", "over4"] {
        assert!(
            matches!(goal(&p, name), Goal::Always { when: None, .. }),
            "{name}"
        );
    }
}

#[test]
fn goals_are_decided_as_the_properties_mean() {
    let p = program();
    // After t ticks c = t - 1 (tick 0 enters Run, c counts from tick 1).
    // small: c < 3 assuming d == 1. With d = 1, c = 3 after 4 ticks violates it;
    // with d = 2 the restriction is off and nothing is violated.
    assert!(!decided_after(&p, "small", 3, 1));
    assert!(decided_after(&p, "small", 4, 1));
    assert!(!decided_after(&p, "small", 4, 2));
    // divides: 6 / d > 0. d = 2 holds; d = 0 is a division by zero, which reads as false:
    // the invariant is violated.
    assert!(!decided_after(&p, "divides", 2, 2));
    assert!(decided_after(&p, "divides", 2, 0));
    // five: c == 5 after 6 ticks, not after 5.
    assert!(!decided_after(&p, "five", 5, 1));
    assert!(decided_after(&p, "five", 6, 1));
    // over4: the observer enters `error` in the tick where c first exceeds 4: c = 5, tick 6.
    assert!(!decided_after(&p, "over4", 5, 1));
    assert!(decided_after(&p, "over4", 6, 1));
    // answered: c == 1 at tick 1 (after 2 ticks) is not followed by c == 9 by tick 1 + 2 = 3
    // (as tests/verify/respond.sc reads `within`): violated at tick 3, after 4 ticks.
    assert!(!decided_after(&p, "answered", 3, 1));
    assert!(decided_after(&p, "answered", 4, 1));
}
