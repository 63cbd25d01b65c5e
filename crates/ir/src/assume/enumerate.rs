//! Listing the input vectors that input-only `assume`s allow, without walking the whole raw
//! space: a depth-first assignment of the inputs (last input first, so vectors come out in
//! increasing index order) that prunes a partial assignment as soon as the interval evaluation
//! ([`super::interval`]) of one conjunct is certainly false. Each complete vector is then
//! decided by the exact evaluator, so pruning only saves work and never changes the list.
//!
//! Example: 24 boolean inputs under "at most one is true" (written as pairwise exclusions)
//! visit a few hundred partial assignments instead of 2^24 vectors.

use super::interval::IntervalEval;
use super::reads::{conjuncts, inputs_read};
use crate::{ExprId, Machine, Program, SlotId};

/// Bounds of one enumeration.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Budget {
    /// Most vectors listed.
    pub vectors: usize,
    /// Most values stored (vectors × inputs).
    pub values: usize,
    /// Most partial assignments visited.
    pub nodes: u64,
}

/// The allowed vectors, flat (`slots.len()` values each, in input order) in increasing index
/// order, and how many there are; `None` when the budget ran out.
pub(crate) fn allowed(
    p: &Program,
    slots: &[SlotId],
    bounds: &[(i64, i64)],
    assumes: &[ExprId],
    budget: Budget,
) -> Option<(Vec<i64>, usize)> {
    let base = p.n_state as u32;
    let mut parts = Vec::new();
    for &a in assumes {
        conjuncts(p, a, &mut parts);
    }
    // Each conjunct is tested whenever one of its inputs is assigned (its interval can only
    // narrow then): a sum over all inputs prunes as soon as the assigned part exceeds it.
    let mut at_input: Vec<Vec<ExprId>> = vec![Vec::new(); slots.len()];
    let mut at_root = Vec::new();
    for &c in &parts {
        let read = inputs_read(p, c);
        if read.is_empty() {
            at_root.push(c);
        }
        for s in read {
            at_input[(s - base) as usize].push(c);
        }
    }
    let mut iv = IntervalEval::new(p);
    if at_root.iter().any(|&c| iv.eval(c).is_false()) {
        return Some((Vec::new(), 0));
    }
    let mut dfs = Dfs {
        slots,
        bounds,
        at_input,
        assumes,
        iv,
        m: Machine::new(p),
        cur: bounds.iter().map(|b| b.0).collect(),
        out: Vec::new(),
        count: 0,
        nodes: 0,
        budget,
    };
    let done = dfs.assign(slots.len());
    done.then_some((dfs.out, dfs.count))
}

struct Dfs<'a> {
    slots: &'a [SlotId],
    bounds: &'a [(i64, i64)],
    at_input: Vec<Vec<ExprId>>,
    assumes: &'a [ExprId],
    iv: IntervalEval<'a>,
    m: Machine<'a>,
    cur: Vec<i64>,
    out: Vec<i64>,
    count: usize,
    nodes: u64,
    budget: Budget,
}

impl Dfs<'_> {
    /// Assign inputs `k-1` down to 0 under the current assignment of the others; false when
    /// the budget ran out.
    fn assign(&mut self, k: usize) -> bool {
        let Some(i) = k.checked_sub(1) else {
            return self.leaf();
        };
        let slot = self.slots[i] as usize;
        let (lo, hi) = self.bounds[i];
        for v in lo..=hi {
            self.nodes += 1;
            if self.nodes > self.budget.nodes {
                return false;
            }
            self.iv.known[slot] = Some(v);
            self.cur[i] = v;
            let at = &self.at_input[i];
            let mut pruned = false;
            for &c in at {
                if self.iv.eval(c).is_false() {
                    pruned = true;
                    break;
                }
            }
            if !pruned && !self.assign(i) {
                return false;
            }
        }
        self.iv.known[slot] = None;
        true
    }

    /// A complete vector: keep it when every assume holds exactly (an evaluation error counts
    /// as false, as everywhere else).
    fn leaf(&mut self) -> bool {
        for (&s, &v) in self.slots.iter().zip(&self.cur) {
            self.m.set(s, v);
        }
        let m = &mut self.m;
        if self
            .assumes
            .iter()
            .all(|&a| matches!(m.eval(a), Ok(x) if x != 0))
        {
            self.out.extend_from_slice(&self.cur);
            self.count += 1;
            if self.count > self.budget.vectors || self.out.len() > self.budget.values {
                return false;
            }
        }
        true
    }
}
