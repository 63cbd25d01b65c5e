//! A scenario is stored one entry per line of its file: `* N` costs one entry, not N, and
//! lookups by tick, edits of one tick and the canonical writer see the ticks it stands for.

use statecheck_ir::{lower, Program};
use statecheck_sim::scenario::{self, Scenario};

const MODEL: &str = r#"
chart C {
  input event go;
  input level: int[0..3];
  output n: int[0..9] = 0;
  initial S;
  state S { on go [n < 9] / { n += 1; }; }
}
system Sys { instance c: C; }
"#;

fn program() -> Program {
    let (file, d1) = statecheck_syntax::parse(MODEL);
    let (model, d2) = statecheck_model::check(&file);
    assert!(d1.iter().chain(&d2).all(|d| !d.is_error()), "{d1:?} {d2:?}");
    lower(&model, &model.systems[0]).expect("lowers")
}

#[test]
fn a_repeat_of_a_hundred_million_ticks_is_one_entry() {
    let p = program();
    let go = p
        .inputs
        .iter()
        .position(|i| i.name == "c.go")
        .expect("c.go");
    let level = p
        .inputs
        .iter()
        .position(|i| i.name == "c.level")
        .expect("c.level");
    let sc = scenario::parse("level = 2\n- * 99999998\ngo\n", &p).expect("parses");
    // 1 + 99,999,998 + 1 ticks.
    assert_eq!(sc.len(), 100_000_000);
    assert_eq!(sc.tick(0), Some(&[(level, 2)][..]));
    assert_eq!(sc.tick(1), Some(&[][..]));
    assert_eq!(sc.tick(99_999_998), Some(&[][..]));
    assert_eq!(sc.tick(99_999_999), Some(&[(go, 1)][..]));
    assert_eq!(sc.tick(100_000_000), None);
    // The canonical writer folds the run back into one line.
    let text = scenario::format(&sc, &p);
    assert!(text.contains("- * 99999998\n"), "{text}");
}

#[test]
fn editing_one_tick_of_a_repeat_splits_it() {
    let p = program();
    let go = p
        .inputs
        .iter()
        .position(|i| i.name == "c.go")
        .expect("c.go");
    let mut sc = Scenario::new();
    sc.push_repeated(vec![], 5);
    sc.set_tick(2, vec![(go, 1)]);
    let ticks: Vec<&[(usize, i64)]> = sc.ticks().collect();
    // Ticks 0..4: only tick 2 has the event.
    assert_eq!(ticks, vec![&[][..], &[], &[(go, 1)], &[], &[]]);
    assert_eq!(sc.len(), 5);
    // Equal consecutive pushes merge: the 5 ticks of `- ` then 3 more are one line.
    let mut merged = Scenario::new();
    merged.push_repeated(vec![], 5);
    merged.push_repeated(vec![], 3);
    assert_eq!(merged.len(), 8);
    assert_eq!(scenario::format(&merged, &p).lines().nth(1), Some("- * 8"));
}
