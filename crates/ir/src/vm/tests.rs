//! Tests of the register code on the FAM plant: how many instructions a step executes.

use super::run::run_counting;
use super::{Code, Op};
use crate::Program;

fn fam() -> Program {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/fam/fam.sc");
    let source = std::fs::read_to_string(path).expect("the FAM example is readable");
    // fam.sc imports the FAM chart from lib/: follow its imports.
    let program =
        statecheck_model::imports::load_with(path, source, |k| std::fs::read_to_string(k).ok());
    let (model, _) = statecheck_model::check(&program.file);
    let sys = model
        .systems
        .iter()
        .find(|s| !s.implicit)
        .expect("the FAM example has a system");
    crate::lower(&model, sys).expect("the FAM example lowers")
}

/// Executed instructions per step, and per instruction, over `steps` random steps.
fn profile(p: &Program, code: &Code, steps: u64) -> (f64, Vec<u64>) {
    let mut counts = vec![0u64; code.ops.len()];
    let mut regs = code.init_regs.clone();
    let mut rng = 42u64;
    for _ in 0..steps {
        for inp in &p.inputs {
            let s = &p.slots[inp.slot as usize];
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            regs[inp.slot as usize] = s.lo + (rng % ((s.hi - s.lo + 1) as u64)) as i64;
        }
        if run_counting(code, &mut regs, code.step, &mut counts).is_err() {
            regs = code.init_regs.clone();
        }
    }
    let total: u64 = counts.iter().sum();
    (total as f64 / steps as f64, counts)
}

/// The benchmark's model stays cheap: a regression guard on the instructions a step executes
/// (91 before the instruction set was specialised). `--nocapture` prints the code and profile.
#[test]
fn a_fam_step_executes_few_instructions() {
    let p = fam();
    let code = p.code();
    assert!(code.runnable);
    let (per_step, counts) = profile(&p, code, 20_000);
    for (pc, op) in code.ops.iter().enumerate() {
        println!("{pc:4} {:7.3} {op:?}", counts[pc] as f64 / 20_000.0);
    }
    println!(
        "{} instructions, {} registers, {per_step:.2} executed per step",
        code.ops.len(),
        code.init_regs.len()
    );
    assert!(per_step < 60.0, "{per_step} instructions per step");
}

/// A one-chart system from source.
fn program(source: &str) -> Program {
    let (file, d1) = statecheck_syntax::parse(source);
    let (model, d2) = statecheck_model::check(&file);
    assert!(!d1.iter().chain(&d2).any(|d| d.is_error()), "{d1:?} {d2:?}");
    let sys = model
        .systems
        .iter()
        .find(|s| !s.implicit)
        .expect("a system");
    crate::lower(&model, sys).expect("lowers")
}

const FLAGS: &str = "
chart Flags {
  input a: bool = false;
  input b: bool = false;
  output flags: int[0..255] = 0;
  output small: int[0..127] = 0;
  region r {
    initial s;
    state s {
      during {
        flags = (if a then 0x80 else 0) | (if b then 0x40 else 0) | 1;
        small = (if a then 0x80 else 0) | (if b then 0x40 else 0) | 1;
      }
    }
  }
}
system S { instance f: Flags; }
";

fn range_checks(code: &Code) -> usize {
    code.ops
        .iter()
        .filter(|op| matches!(op, Op::Check { .. } | Op::CheckMov { .. }))
        .count()
}

/// The check on `flags` cannot fail and is dropped; the one on `small` can and stays, and
/// reports the same error at the same site as the reference evaluator.
#[test]
fn range_checks_are_dropped_only_when_they_cannot_fail() {
    let p = program(FLAGS);
    let checked = |name: &str| {
        let slot = p.slots.iter().position(|s| s.name.ends_with(name));
        fn find(b: &[crate::Stmt], slot: u32) -> Option<Option<u32>> {
            b.iter().find_map(|s| match s {
                crate::Stmt::Assign { slot: s, site, .. } if *s == slot => Some(*site),
                crate::Stmt::If {
                    then, otherwise, ..
                } => find(then, slot).or_else(|| find(otherwise, slot)),
                crate::Stmt::Switch { cases, .. } => cases.iter().find_map(|c| find(c, slot)),
                _ => None,
            })
        }
        let slot = slot.expect("slot") as u32;
        std::iter::once(&p.step[..])
            .chain(p.procs.iter().map(|q| &q.body[..]))
            .find_map(|b| find(b, slot))
            .flatten()
    };
    // The lowering checks both assignments; the register code only the one to `small`.
    assert!(checked("flags").is_some());
    let small_site = checked("small").expect("`small` is range checked");
    let code = p.code();
    assert_eq!(range_checks(code), 1);
    let slot = |name: &str| {
        p.inputs
            .iter()
            .find(|i| i.name.ends_with(name))
            .expect("input")
            .slot
    };
    for (a, b, want) in [
        (0, 0, None),
        (0, 1, None),
        (1, 0, Some(0x81)),
        (1, 1, Some(0xC1)),
    ] {
        let mut fast = crate::Machine::new(&p);
        let mut slow = crate::Machine::new(&p);
        for m in [&mut fast, &mut slow] {
            m.set(slot("a"), a);
            m.set(slot("b"), b);
            m.step().expect("the initialisation tick");
        }
        let (x, y) = (fast.step(), slow.step_reference());
        assert_eq!(x, y);
        assert_eq!(fast.slots(), slow.slots());
        match want {
            None => assert!(x.is_ok()),
            Some(value) => assert_eq!(
                x,
                Err(crate::RuntimeError {
                    kind: crate::RuntimeErrorKind::Range {
                        value,
                        lo: 0,
                        hi: 127
                    },
                    site: small_site,
                })
            ),
        }
    }
}

/// A chart whose two transitions are triggered by the same event tests the event once when it
/// is absent: the first test's jump is threaded past the second (which it decides), and a tick
/// without the event runs the started test, the switch, one event test and `End`.
#[test]
fn an_absent_event_is_tested_once() {
    let p = program(
        "chart Counter {
  input event inc;
  output c: int[0..7] = 0;
  initial Run;
  state Run {
    on inc [c < 7] / { c += 1; };
    on inc / { c = 0; };
  }
}
system S { instance k: Counter; }",
    );
    let code = p.code();
    let inc = p.inputs[0].slot as u16;
    for op in &code.ops {
        if let Op::Jz { a, t } = *op {
            if a == inc {
                let target = code.ops[t as usize];
                assert!(
                    !matches!(target, Op::Jz { a, .. } if a == inc),
                    "{op:?} jumps to {target:?}"
                );
            }
        }
    }
    let mut regs = code.init_regs.clone();
    let mut counts = vec![0u64; code.ops.len()];
    // The initialisation tick, then one without the event.
    for _ in 0..2 {
        run_counting(code, &mut regs, code.step, &mut counts).expect("no run-time error");
    }
    counts.iter_mut().for_each(|c| *c = 0);
    run_counting(code, &mut regs, code.step, &mut counts).expect("no run-time error");
    assert_eq!(counts.iter().sum::<u64>(), 4, "{:?}", code.ops);
}

/// `Machine::load` sets what `load_state` and `set` set, and a prepared expression holds
/// exactly when evaluating it gives non-zero (an error counts as false): on the FAM plant,
/// over random states reached by random ticks, for every property, assumption and `&&`
/// conjunct of an assumption.
#[test]
fn load_and_prepared_expressions_agree_with_the_plain_calls() {
    let p = fam();
    let mut exprs: Vec<crate::ExprId> = p.assumes.clone();
    let mut stack = p.assumes.clone();
    while let Some(e) = stack.pop() {
        if let crate::Node::Binary(statecheck_syntax::ast::BinOp::And, a, b, _) =
            p.nodes[e as usize]
        {
            exprs.extend([a, b]);
            stack.extend([a, b]);
        }
    }
    for prop in &p.properties {
        exprs.extend(prop.goal.exprs());
    }
    let prepared: Vec<_> = exprs.iter().map(|&e| p.prepare(e)).collect();
    let mut walk = crate::Machine::new(&p);
    let mut rng = 7u64;
    let mut next = |lo: i64, hi: i64| {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        lo + (rng % ((hi - lo + 1) as u64)) as i64
    };
    for _ in 0..2000 {
        let inputs: Vec<i64> = p
            .inputs
            .iter()
            .map(|i| next(p.slots[i.slot as usize].lo, p.slots[i.slot as usize].hi))
            .collect();
        let state = walk.state().to_vec();
        let mut loaded = crate::Machine::new(&p);
        loaded.load(&state, &inputs);
        let mut set = crate::Machine::new(&p);
        set.load_state(&state);
        for (i, &x) in p.inputs.iter().zip(&inputs) {
            set.set(i.slot, x);
        }
        assert_eq!(loaded.slots(), set.slots());
        for (&e, &q) in exprs.iter().zip(&prepared) {
            let want = matches!(set.eval(e), Ok(v) if v != 0);
            assert_eq!(loaded.holds(q), want, "expression {e}");
        }
        walk.load(&state, &inputs);
        if walk.step().is_err() {
            walk = crate::Machine::new(&p);
        }
    }
}
