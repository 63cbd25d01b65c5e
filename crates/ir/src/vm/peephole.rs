//! Jump threading and removal of instructions that do nothing, after compiling.
//!
//! A jump to an unconditional jump goes straight to the final target; a jump to `End` or `Ret`
//! becomes that instruction; a (conditional) jump to the next instruction and a call of a
//! procedure that returns at once are removed. Removing instructions renumbers the code: every
//! jump and call target, switch table entry, the step entry and the segment starts are
//! remapped. Repeated until nothing changes.

use super::compile::Compiled;
use super::op::Op;

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

fn thread(c: &mut Compiled) {
    for pc in 0..c.ops.len() {
        let mut op = c.ops[pc];
        if let Some(t) = op.target_mut() {
            *t = resolve(&c.ops, *t);
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
