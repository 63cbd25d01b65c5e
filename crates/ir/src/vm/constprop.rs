//! Branches on registers whose value is known where they are tested.
//!
//! A forward pass over the code tracks the registers that hold a known value at each
//! instruction: the constants, and registers set by `MovI` (or copied from a known register)
//! on every path to it. A conditional jump or switch whose outcome is then known becomes an
//! unconditional jump, or a jump to the next instruction when it is never taken (which the
//! peephole pass removes). The typical case is the flag that tells a parallel state's later
//! regions to skip their tick: cleared at the start of the tick and tested before every region,
//! it is never set in a chart without transitions out of parallel states.
//!
//! Nothing is known at an entry point (the step, a procedure, an expression segment): registers
//! keep their values between runs. A call forgets everything. All jumps go forward (the
//! compiler emits no loops), so one pass in code order sees every predecessor first; code with
//! a backward jump is left alone.

use super::compile::Compiled;
use super::op::{Op, Reg};

/// Known register values, sorted by register.
type Facts = Vec<(Reg, i64)>;

fn meet(a: Facts, b: &Facts) -> Facts {
    a.into_iter().filter(|f| b.contains(f)).collect()
}

/// At most this many facts are kept at a time (a bound on the pass's cost for large programs;
/// forgetting a fact is always sound).
const MAX_FACTS: usize = 64;

fn set(facts: &mut Facts, r: Reg, v: Option<i64>) {
    match (facts.binary_search_by_key(&r, |f| f.0), v) {
        (Ok(i), Some(v)) => facts[i].1 = v,
        (Ok(i), None) => {
            facts.remove(i);
        }
        (Err(i), Some(v)) if facts.len() < MAX_FACTS => facts.insert(i, (r, v)),
        (Err(_), _) => {}
    }
}

/// The outcome of a conditional jump when its operands are known: `Some(taken)`.
pub(super) fn decide(op: &Op, known: impl Fn(Reg) -> Option<i64>) -> Option<bool> {
    let imm = |a: Reg, k: i32, f: fn(i64, i64) -> bool| known(a).map(|x| f(x, k as i64));
    let two = |a: Reg, b: Reg, f: fn(i64, i64) -> bool| Some(f(known(a)?, known(b)?));
    match *op {
        Op::Jz { a, .. } => known(a).map(|x| x == 0),
        Op::Jnz { a, .. } => known(a).map(|x| x != 0),
        Op::JEq { a, b, .. } => two(a, b, |x, y| x == y),
        Op::JNe { a, b, .. } => two(a, b, |x, y| x != y),
        Op::JLt { a, b, .. } => two(a, b, |x, y| x < y),
        Op::JLe { a, b, .. } => two(a, b, |x, y| x <= y),
        Op::JEqI { a, imm: k, .. } => imm(a, k, |x, y| x == y),
        Op::JNeI { a, imm: k, .. } => imm(a, k, |x, y| x != y),
        Op::JLtI { a, imm: k, .. } => imm(a, k, |x, y| x < y),
        Op::JLeI { a, imm: k, .. } => imm(a, k, |x, y| x <= y),
        Op::JGtI { a, imm: k, .. } => imm(a, k, |x, y| x > y),
        Op::JGeI { a, imm: k, .. } => imm(a, k, |x, y| x >= y),
        Op::JAnyI { a, imm: k, .. } => imm(a, k, |x, y| x & y != 0),
        Op::JNoneI { a, imm: k, .. } => imm(a, k, |x, y| x & y == 0),
        Op::JIn { a, set, .. } => known(a).map(|x| (x as u64) < 32 && (set >> x) & 1 != 0),
        Op::JNotIn { a, set, .. } => known(a).map(|x| !((x as u64) < 32 && (set >> x) & 1 != 0)),
        _ => None,
    }
}

/// Replace branches with a known outcome; false if none was found.
pub(super) fn fold_branches(c: &mut Compiled) -> bool {
    let n = c.ops.len();
    let mut entry = vec![false; n];
    entry[c.step as usize] = true;
    for (start, _) in c.exprs.values() {
        entry[*start as usize] = true;
    }
    for op in &c.ops {
        if let Op::Call { t } = op {
            entry[*t as usize] = true;
        }
    }
    let forward = c.ops.iter().enumerate().all(|(pc, op)| {
        let mut op = *op;
        let jump_ok =
            matches!(op, Op::Call { .. }) || op.target_mut().is_none_or(|t| *t as usize > pc);
        let table_ok = op
            .switch_entries()
            .is_none_or(|r| c.tables[r].iter().all(|t| *t as usize > pc));
        jump_ok && table_ok
    });
    if !forward {
        // Not produced by the compiler; leave the code alone rather than reason about loops.
        return false;
    }
    let const_base = c.const_base as usize;
    let mut incoming: Vec<Option<Facts>> = vec![None; n];
    let mut flow: Option<Facts> = None;
    let mut changed = false;
    for pc in 0..n {
        let mut facts = match (flow.take(), incoming[pc].take()) {
            (Some(a), Some(b)) => meet(a, &b),
            (Some(a), None) | (None, Some(a)) => a,
            (None, None) => Vec::new(),
        };
        if entry[pc] {
            facts.clear();
        }
        let known = |r: Reg| {
            if r as usize >= const_base {
                c.init_regs.get(r as usize).copied()
            } else {
                facts
                    .binary_search_by_key(&r, |f| f.0)
                    .ok()
                    .map(|i| facts[i].1)
            }
        };
        let mut op = c.ops[pc];
        if let Some(taken) = decide(&op, known) {
            let t = op.target_mut().map_or(0, |t| *t);
            op = Op::Jmp {
                t: if taken { t } else { pc as u32 + 1 },
            };
        }
        if let Op::Switch { a, len, table } = op {
            if let Some(v) = known(a) {
                let k = if (v as u64) < len as u64 {
                    1 + v as usize
                } else {
                    0
                };
                op = Op::Jmp {
                    t: c.tables[table as usize + k],
                };
            }
        }
        if op != c.ops[pc] {
            c.ops[pc] = op;
            changed = true;
        }
        // The facts after the instruction.
        match op {
            Op::MovI { d, imm } => set(&mut facts, d, Some(imm as i64)),
            Op::Mov { d, a } => {
                let v = known(a);
                set(&mut facts, d, v);
            }
            Op::Call { .. } => facts.clear(),
            _ => {
                if let Some(d) = op.dest() {
                    set(&mut facts, d, None);
                }
            }
        }
        // Pass them on along every edge.
        let mut targets = Vec::new();
        let mut jump = op;
        if let Some(t) = jump.target_mut() {
            if !matches!(op, Op::Call { .. }) {
                targets.push(*t as usize);
            }
        }
        if let Some(r) = op.switch_entries() {
            targets.extend(c.tables[r].iter().map(|t| *t as usize));
        }
        for t in targets {
            incoming[t] = Some(match incoming[t].take() {
                Some(f) => meet(f, &facts),
                None => facts.clone(),
            });
        }
        if !matches!(op, Op::Jmp { .. } | Op::Switch { .. } | Op::Ret | Op::End) {
            flow = Some(facts);
        }
    }
    changed
}
