//! Ternary (0, 1, X) simulation of one time frame: lifting a predecessor state to a sub-cube
//! without a SAT call.
//!
//! A predecessor found by the solver is a full assignment of latches and inputs under which
//! some required outputs (the constraints, the next-state literals of a target cube, or the bad
//! output) have given values. Lifting tries one latch at a time: it becomes X, the change
//! propagates through its fan-out only (event-driven, in topological order), and the latch stays
//! X when every required output keeps its binary value; otherwise the change is undone. Ternary
//! simulation over-approximates the values of every completion of the X's, so every state of
//! the lifted cube, with the same inputs, gives the required outputs (Eén, Mishchenko and
//! Brayton, "Efficient implementation of property directed reachability", 2011).

use crate::aig::{Aig, Lit, Node};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

const ZERO: u8 = 0;
const ONE: u8 = 1;
const X: u8 = 2;

/// A ternary simulator of one frame of an AIG, with its fan-out lists built once.
pub struct Ternary<'a> {
    aig: &'a Aig,
    /// The gates reading each variable.
    fanout: Vec<Vec<u32>>,
    /// The current value of each variable.
    val: Vec<u8>,
    /// Whether a variable is a required output in the current lift.
    required: Vec<bool>,
    /// Values overwritten by the current trial, to undo it.
    trail: Vec<(u32, u8)>,
    /// Gates waiting to be re-evaluated, lowest variable first.
    queue: BinaryHeap<Reverse<u32>>,
    queued: Vec<bool>,
    /// Whether a variable is in the fan-in cone of the current required outputs: only those
    /// are simulated, and latches outside it are dropped without a trial.
    in_cone: Vec<bool>,
    /// The variables marked in `in_cone`, to clear them after the lift.
    cone: Vec<u32>,
    /// Variables picked by the justification of the current lift.
    needed: Vec<bool>,
}

fn lit_val(val: &[u8], l: Lit) -> u8 {
    let v = val[l.var() as usize];
    if v == X || !l.is_neg() {
        v
    } else {
        v ^ 1
    }
}

fn and3(a: u8, b: u8) -> u8 {
    if a == ZERO || b == ZERO {
        ZERO
    } else if a == ONE && b == ONE {
        ONE
    } else {
        X
    }
}

impl<'a> Ternary<'a> {
    /// A simulator of `aig`.
    pub fn new(aig: &'a Aig) -> Ternary<'a> {
        let n = aig.nodes.len();
        let mut fanout = vec![Vec::new(); n];
        for (v, node) in aig.nodes.iter().enumerate() {
            if let Node::And(a, b) = *node {
                fanout[a.var() as usize].push(v as u32);
                if b.var() != a.var() {
                    fanout[b.var() as usize].push(v as u32);
                }
            }
        }
        Ternary {
            aig,
            fanout,
            val: vec![X; n],
            required: vec![false; n],
            trail: Vec::new(),
            queue: BinaryHeap::new(),
            queued: vec![false; n],
            in_cone: vec![false; n],
            cone: Vec::new(),
            needed: vec![false; n],
        }
    }

    /// Shrink `state` (latch index and value, sorted; latches not listed are X) to the latches
    /// that the required outputs depend on, with the inputs at `inputs` (missing ones false):
    /// every listed output literal must keep the value `true` in every completion. `None` when
    /// the full assignment itself does not give the required values.
    pub fn lift(
        &mut self,
        state: &[(usize, bool)],
        inputs: &[bool],
        required: &[Lit],
    ) -> Option<Vec<(usize, bool)>> {
        let aig = self.aig;
        self.mark_cone(required);
        // Latches of the cone that `state` leaves out are X (stale values elsewhere are never
        // read: the cone is closed under fan-in).
        for &v in &self.cone {
            if matches!(aig.nodes[v as usize], Node::Latch(_)) {
                self.val[v as usize] = X;
            }
        }
        self.val[0] = ZERO;
        for (k, &var) in aig.inputs.iter().enumerate() {
            self.val[var as usize] = u8::from(inputs.get(k).copied().unwrap_or(false));
        }
        for &(j, b) in state {
            self.val[aig.latches[j].var as usize] = u8::from(b);
        }
        // The cone in increasing variable order is a topological order.
        self.cone.sort_unstable();
        self.simulate_cone();
        let result = if required.iter().any(|&l| lit_val(&self.val, l) != ONE) {
            None
        } else {
            for &l in required {
                self.required[l.var() as usize] = true;
            }
            // A justification picks the latches one controlling fan-in at a time would need;
            // the others go to X at once, and only the picked ones are tried one by one.
            self.justify(required);
            for &(j, _) in state {
                let var = aig.latches[j].var as usize;
                if self.in_cone[var] && !self.needed[var] {
                    self.val[var] = X;
                }
            }
            self.simulate_cone();
            let justified = required.iter().all(|&l| lit_val(&self.val, l) == ONE);
            if !justified {
                // Cannot happen for a correct justification; start from the full state again.
                for &(j, b) in state {
                    self.val[aig.latches[j].var as usize] = u8::from(b);
                }
                self.simulate_cone();
            }
            let mut kept = Vec::with_capacity(state.len());
            for &(j, b) in state {
                let var = aig.latches[j].var;
                let tried = self.in_cone[var as usize] && (self.needed[var as usize] || !justified);
                if tried && !self.try_x(var) {
                    kept.push((j, b));
                }
            }
            for &v in &self.cone {
                self.needed[v as usize] = false;
            }
            for &l in required {
                self.required[l.var() as usize] = false;
            }
            Some(kept)
        };
        for &v in &self.cone {
            self.in_cone[v as usize] = false;
        }
        result
    }

    /// Evaluate the gates of the cone in topological order.
    fn simulate_cone(&mut self) {
        for &v in &self.cone {
            if let Node::And(a, b) = self.aig.nodes[v as usize] {
                self.val[v as usize] = and3(lit_val(&self.val, a), lit_val(&self.val, b));
            }
        }
    }

    /// Mark in `needed` a set of variables whose values imply the required outputs: both
    /// fan-ins of a gate at 1, one fan-in at 0 of a gate at 0 (one already needed if any,
    /// else an input or gate before a latch).
    fn justify(&mut self, required: &[Lit]) {
        for &l in required {
            self.needed[l.var() as usize] = true;
        }
        for &v in self.cone.iter().rev() {
            if !self.needed[v as usize] {
                continue;
            }
            let Node::And(a, b) = self.aig.nodes[v as usize] else {
                continue;
            };
            if self.val[v as usize] == ONE {
                self.needed[a.var() as usize] = true;
                self.needed[b.var() as usize] = true;
                continue;
            }
            let zero_a = lit_val(&self.val, a) == ZERO;
            let zero_b = lit_val(&self.val, b) == ZERO;
            let (na, nb) = (self.needed[a.var() as usize], self.needed[b.var() as usize]);
            if (zero_a && na) || (zero_b && nb) {
                continue;
            }
            let is_latch = |l: Lit| matches!(self.aig.nodes[l.var() as usize], Node::Latch(_));
            let pick = match (zero_a, zero_b) {
                (true, true) if is_latch(a) && !is_latch(b) => b,
                (true, _) => a,
                (false, true) => b,
                // A gate at 0 has a fan-in at 0.
                (false, false) => continue,
            };
            self.needed[pick.var() as usize] = true;
        }
    }

    /// Mark the fan-in cone of the required literals (stopping at latches and inputs).
    fn mark_cone(&mut self, required: &[Lit]) {
        self.cone.clear();
        let mut stack: Vec<u32> = required.iter().map(|l| l.var()).collect();
        while let Some(v) = stack.pop() {
            if self.in_cone[v as usize] {
                continue;
            }
            self.in_cone[v as usize] = true;
            self.cone.push(v);
            if let Node::And(a, b) = self.aig.nodes[v as usize] {
                stack.push(a.var());
                stack.push(b.var());
            }
        }
    }

    /// Set `var` to X and propagate; keep the change when no required output became X, undo it
    /// otherwise. Whether it was kept.
    fn try_x(&mut self, var: u32) -> bool {
        self.trail.clear();
        let old = self.val[var as usize];
        if self.required[var as usize] {
            return false;
        }
        self.trail.push((var, old));
        self.val[var as usize] = X;
        self.enqueue_fanout(var);
        let mut ok = true;
        while let Some(Reverse(g)) = self.queue.pop() {
            self.queued[g as usize] = false;
            if !ok {
                continue;
            }
            let Node::And(a, b) = self.aig.nodes[g as usize] else {
                continue;
            };
            let new = and3(lit_val(&self.val, a), lit_val(&self.val, b));
            let cur = self.val[g as usize];
            if new == cur {
                continue;
            }
            if self.required[g as usize] {
                ok = false;
                continue;
            }
            self.trail.push((g, cur));
            self.val[g as usize] = new;
            self.enqueue_fanout(g);
        }
        if !ok {
            for &(v, old) in self.trail.iter().rev() {
                self.val[v as usize] = old;
            }
        }
        ok
    }

    fn enqueue_fanout(&mut self, var: u32) {
        for &g in &self.fanout[var as usize] {
            if self.in_cone[g as usize] && !self.queued[g as usize] {
                self.queued[g as usize] = true;
                self.queue.push(Reverse(g));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `bad = l0 & (l1 | l2)`: from the state 1, 1, 0 only l0 and l1 matter; from 1, 1, 1
    /// either of l1, l2 suffices: the justification of `l1 | l2 = !(!l1 & !l2)` picks the
    /// first fan-in at 0, `!l1`, so l2 goes to X at once and l0, l1 stay.
    #[test]
    fn lifts_to_the_latches_the_output_needs() {
        let mut aig = Aig::new();
        let l: Vec<Lit> = (0..3).map(|_| aig.latch(Some(false), None)).collect();
        let or = aig.or(l[1], l[2]);
        let bad = aig.and(l[0], or);
        let mut t = Ternary::new(&aig);
        let lifted = t.lift(&[(0, true), (1, true), (2, false)], &[], &[bad]);
        assert_eq!(lifted, Some(vec![(0, true), (1, true)]));
        let lifted = t.lift(&[(0, true), (1, true), (2, true)], &[], &[bad]);
        assert_eq!(lifted, Some(vec![(0, true), (1, true)]));
        // Not bad at all: no lifting.
        assert_eq!(
            t.lift(&[(0, false), (1, true), (2, true)], &[], &[bad]),
            None
        );
        // A negated requirement: `!bad` from 0, 1, 1 needs only l0.
        let lifted = t.lift(&[(0, false), (1, true), (2, true)], &[], &[!bad]);
        assert_eq!(lifted, Some(vec![(0, false)]));
    }

    /// Random circuits: every completion of a lifted cube gives the required outputs (checked by
    /// binary simulation of all completions).
    #[test]
    fn lifted_cubes_are_sound() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut rnd = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..200 {
            let mut aig = Aig::new();
            let n_latch = 6;
            let mut lits: Vec<Lit> = (0..n_latch).map(|_| aig.latch(None, None)).collect();
            lits.push(aig.input(None));
            for _ in 0..12 {
                let a = lits[(rnd() % lits.len() as u64) as usize].xor(rnd() % 2 == 0);
                let b = lits[(rnd() % lits.len() as u64) as usize].xor(rnd() % 2 == 0);
                let g = aig.and(a, b);
                lits.push(g);
            }
            let out = lits[lits.len() - 1];
            let state: Vec<(usize, bool)> = (0..n_latch).map(|j| (j, rnd() % 2 == 0)).collect();
            let ins = [rnd() % 2 == 0];
            let full: Vec<bool> = state.iter().map(|&(_, b)| b).collect();
            let v = aig.simulate(&ins, &full);
            let want = if crate::aig::lit_val(&v, out) {
                out
            } else {
                !out
            };
            let mut t = Ternary::new(&aig);
            let Some(lifted) = t.lift(&state, &ins, &[want]) else {
                panic!("the full state gives the output");
            };
            for m in 0u32..(1 << n_latch) {
                let latches: Vec<bool> = (0..n_latch)
                    .map(|j| match lifted.iter().find(|l| l.0 == j) {
                        Some(&(_, b)) => b,
                        None => m >> j & 1 == 1,
                    })
                    .collect();
                let v = aig.simulate(&ins, &latches);
                assert!(
                    crate::aig::lit_val(&v, want),
                    "completion {m:b} of {lifted:?}"
                );
            }
        }
    }
}
