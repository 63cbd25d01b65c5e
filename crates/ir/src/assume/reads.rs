//! Which slots an expression reads: the classification behind evaluating an `assume` once up
//! front (inputs only), once per state (state only) or on every transition (both), and a
//! property once per new state instead of on every transition.

use crate::BinOp;
use crate::{ExprId, Node, Program};
use std::ops::Range;

/// True when expression `e` reads no slot outside `slots`. Every node kind is followed,
/// including the `Let`/`Local` pairs an inlined function call lowers to.
pub fn reads_only(p: &Program, e: ExprId, slots: Range<u32>) -> bool {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match p.nodes.get(e as usize) {
            Some(Node::Const(_) | Node::Local(_)) => {}
            Some(Node::Slot(s)) => {
                if !slots.contains(s) {
                    return false;
                }
            }
            Some(Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, _, _, _)) => stack.push(*a),
            Some(
                Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) | Node::Let(_, a, b),
            ) => stack.extend([*a, *b]),
            Some(Node::Ite(c, a, b)) => stack.extend([*c, *a, *b]),
            // An id outside the arena: assume it reads anything.
            None => return false,
        }
    }
    true
}

/// The slots of the persistent state.
pub fn state_slots(p: &Program) -> Range<u32> {
    0..p.n_state as u32
}

/// The input slots.
pub fn input_slots(p: &Program) -> Range<u32> {
    let lo = p.n_state as u32;
    lo..lo + p.inputs.len() as u32
}

/// The input slots `e` reads (sorted, deduplicated).
pub fn inputs_read(p: &Program, e: ExprId) -> Vec<u32> {
    let inputs = input_slots(p);
    let mut out = slots_read(p, e);
    out.retain(|s| inputs.contains(s));
    out
}

/// Every slot `e` reads (sorted, deduplicated).
pub fn slots_read(p: &Program, e: ExprId) -> Vec<u32> {
    let mut out = Vec::new();
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match p.nodes.get(e as usize) {
            Some(Node::Slot(s)) => out.push(*s),
            Some(Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, _, _, _)) => stack.push(*a),
            Some(
                Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) | Node::Let(_, a, b),
            ) => stack.extend([*a, *b]),
            Some(Node::Ite(c, a, b)) => stack.extend([*c, *a, *b]),
            _ => {}
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// The conjuncts of `e`: `a && b` split recursively (`&&` short-circuits to 0 exactly when a
/// conjunct is 0 or fails, so the conjunction holds exactly when every conjunct does).
pub fn conjuncts(p: &Program, e: ExprId, out: &mut Vec<ExprId>) {
    match p.nodes.get(e as usize) {
        Some(Node::Binary(BinOp::And, a, b, _)) => {
            conjuncts(p, *a, out);
            conjuncts(p, *b, out);
        }
        _ => out.push(e),
    }
}
