//! Jump threading and removal of instructions that do nothing, after compiling.
//!
//! A jump to an unconditional jump goes straight to the final target; a conditional jump to a
//! conditional jump whose outcome it implies (`Jz a` to `Jz a`, the typical test of an absent
//! event repeated by each transition of a state) goes straight to where that one leads; a jump
//! to `End` or `Ret` becomes that instruction; a switch with one case placed right after it
//! becomes a compare-and-branch; a (conditional) jump to the next instruction and a call of a
//! procedure that returns at once are removed. Removing instructions renumbers the code: every
//! jump and call target, switch table entry, the step entry and the segment starts are
//! remapped. Repeated until nothing changes.

use super::compile::Compiled;
use super::constprop::decide;
use super::op::{Op, Reg};

/// Optimise compiled code in place.
pub(super) fn optimise(c: &mut Compiled) {
    loop {
        thread(c);
        if !remove(c) {
            break;
        }
    }
}

/// Follow unconditional jumps from `t`.
fn resolve(ops: &[Op], mut t: u32) -> u32 {
    for _ in 0..ops.len() {
        match ops[t as usize] {
            Op::Jmp { t: next } if next != t => t = next,
            _ => break,
        }
    }
    t
}

/// What taking conditional jump `op` tells about its register: `Ok(v)` that it holds `v`,
/// `Err(())` that it is non-zero.
fn taken_fact(op: &Op) -> Option<(Reg, Result<i64, ()>)> {
    match *op {
        Op::Jz { a, .. } => Some((a, Ok(0))),
        Op::JEqI { a, imm, .. } => Some((a, Ok(imm as i64))),
        Op::Jnz { a, .. } => Some((a, Err(()))),
        _ => None,
    }
}

/// Follow, from target `t` of conditional jump `op`, the conditional jumps whose outcome
/// taking `op` decides (they read only `op`'s register, which nothing between changes).
fn resolve_implied(ops: &[Op], op: &Op, mut t: u32) -> u32 {
    let Some((reg, fact)) = taken_fact(op) else {
        return t;
    };
    for _ in 0..ops.len() {
        let next = ops[t as usize];
        let taken = match (fact, next) {
            (Err(()), Op::Jz { a, .. }) if a == reg => Some(false),
            (Err(()), Op::Jnz { a, .. }) if a == reg => Some(true),
            (Ok(v), _) if next.is_cond_jump() => {
                let mut only_reg = true;
                jump_regs(next, |r| only_reg &= r == reg);
                if only_reg {
                    decide(&next, |r| (r == reg).then_some(v))
                } else {
                    None
                }
            }
            _ => None,
        };
        let mut jump = next;
        let goes = match taken {
            Some(true) => jump.target_mut().map(|n| *n),
            Some(false) => Some(t + 1),
            None => None,
        };
        match goes {
            Some(g) if g != t => t = resolve(ops, g),
            _ => break,
        }
    }
    t
}

/// The registers an instruction reads or writes.
fn jump_regs(mut op: Op, mut f: impl FnMut(Reg)) {
    op.for_each_reg(|r| f(*r));
}

fn thread(c: &mut Compiled) {
    for pc in 0..c.ops.len() {
        let mut op = c.ops[pc];
        // A switch with one case that follows it is a test of that case: `a` is 0 or the
        // switch goes to its end.
        if let Op::Switch { a, len: 1, table } = op {
            let (end, case) = (c.tables[table as usize], c.tables[table as usize + 1]);
            if case as usize == pc + 1 {
                op = Op::JNeI { a, imm: 0, t: end };
            }
        }
        let orig = op;
        if let Some(t) = op.target_mut() {
            *t = resolve(&c.ops, *t);
            if orig.is_cond_jump() {
                *t = resolve_implied(&c.ops, &orig, *t);
            }
        }
        if let Op::Jmp { t } = op {
            match c.ops[t as usize] {
                Op::End => op = Op::End,
                Op::Ret => op = Op::Ret,
                _ => {}
            }
        }
        c.ops[pc] = op;
        if let Some(r) = op.switch_entries() {
            for k in r {
                c.tables[k] = resolve(&c.ops, c.tables[k]);
            }
        }
    }
}

/// Remove useless instructions; false if there were none.
fn remove(c: &mut Compiled) -> bool {
    let n = c.ops.len();
    let keep: Vec<bool> = (0..n)
        .map(|pc| {
            let op = c.ops[pc];
            let to_next = |t: u32| t as usize == pc + 1;
            match op {
                Op::Jmp { t } => !to_next(t),
                Op::Call { t } => c.ops[t as usize] != Op::Ret,
                _ if op.is_cond_jump() => {
                    let mut op = op;
                    !op.target_mut().is_some_and(|t| to_next(*t))
                }
                _ => true,
            }
        })
        .collect();
    if keep.iter().all(|k| *k) {
        return false;
    }
    // Where each old index goes: a removed instruction's index goes to the next kept one.
    let mut new_index = Vec::with_capacity(n + 1);
    let mut kept = 0u32;
    for k in &keep {
        new_index.push(kept);
        kept += *k as u32;
    }
    new_index.push(kept);
    let map = |t: &mut u32| *t = new_index[*t as usize];
    let mut ops = Vec::with_capacity(kept as usize);
    let mut sites = Vec::with_capacity(kept as usize);
    for ((op, site), keep) in c.ops.iter().zip(&c.sites).zip(&keep) {
        if *keep {
            let mut op = *op;
            if let Some(t) = op.target_mut() {
                map(t);
            }
            ops.push(op);
            sites.push(*site);
        }
    }
    for op in &ops {
        if let Some(r) = op.switch_entries() {
            for k in r {
                map(&mut c.tables[k]);
            }
        }
    }
    map(&mut c.step);
    for (start, _) in c.exprs.values_mut() {
        map(start);
    }
    c.ops = ops;
    c.sites = sites;
    true
}
