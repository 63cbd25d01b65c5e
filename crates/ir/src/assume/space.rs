//! The input vectors of one tick, enumerated in a fixed order so that a position identifies a
//! vector, and the `assume`s that restrict them.
//!
//! The raw space is mixed radix over [`Program::inputs`], the first input varying fastest.
//! Every `assume` is split into its `&&` conjuncts, and each conjunct is classified by what it
//! reads: inputs only (solved once, up front: the allowed vectors are listed, see
//! the pruned enumeration of the parent module), state only (evaluated once per state), or both (evaluated on every
//! transition). When the vectors are listed, a transition's input position is its index in
//! the list; otherwise it is the raw mixed-radix index.

use super::enumerate::{allowed, Budget};
use super::reads::{conjuncts, input_slots, reads_only, state_slots};
use crate::{ExprId, Program, SlotId};

/// Most vectors [`InputSpace::solve_static`] lists up front.
pub const MAX_STATIC_ENUMERATION: u128 = 1 << 20;

/// Most values (vectors × inputs) a listing may hold: 32 MiB.
const MAX_LISTED_VALUES: usize = 1 << 22;

/// Most partial assignments the enumeration visits before giving up.
const MAX_ENUMERATION_NODES: u64 = 1 << 23;

/// The space of input vectors of a program.
#[derive(Clone, Debug)]
pub struct InputSpace {
    /// Slot of each input.
    pub slots: Vec<SlotId>,
    lo: Vec<i64>,
    hi: Vec<i64>,
    /// Number of vectors before `assume`s (saturating at `u128::MAX`).
    pub count: u128,
    /// `assume` conjuncts that read only inputs: solved up front when the vectors are listed,
    /// otherwise evaluated on every transition.
    pub input_assumes: Vec<ExprId>,
    /// `assume` conjuncts that read only the state: evaluated once per state (a state where one
    /// fails has no successor).
    pub state_assumes: Vec<ExprId>,
    /// `assume` conjuncts that read the state and the inputs: evaluated on every transition.
    pub mixed_assumes: Vec<ExprId>,
    /// The vectors of a tick, listed up front: flat, `slots.len()` values each.
    listed: Option<Vec<i64>>,
    /// How many vectors are listed.
    n_listed: usize,
    /// True when the input-only assumes allow too many vectors to list.
    pub too_many: bool,
}

impl InputSpace {
    /// The input space of `program`, its assumes classified, nothing listed yet.
    pub fn new(program: &Program) -> InputSpace {
        let mut count: u128 = 1;
        let mut slots = Vec::new();
        let mut lo = Vec::new();
        let mut hi = Vec::new();
        for inp in &program.inputs {
            let s = &program.slots[inp.slot as usize];
            let size = (s.hi as i128 - s.lo as i128 + 1).max(1) as u128;
            count = count.saturating_mul(size);
            slots.push(inp.slot);
            lo.push(s.lo);
            hi.push(s.hi);
        }
        let mut parts = Vec::new();
        for &a in &program.assumes {
            conjuncts(program, a, &mut parts);
        }
        let (mut input_assumes, mut state_assumes, mut mixed_assumes) =
            (Vec::new(), Vec::new(), Vec::new());
        for c in parts {
            if reads_only(program, c, input_slots(program)) {
                input_assumes.push(c);
            } else if reads_only(program, c, state_slots(program)) {
                state_assumes.push(c);
            } else {
                mixed_assumes.push(c);
            }
        }
        InputSpace {
            slots,
            lo,
            hi,
            count,
            input_assumes,
            state_assumes,
            mixed_assumes,
            listed: None,
            n_listed: 0,
            too_many: false,
        }
    }

    /// List the vectors of a tick up front: those the input-only assumes allow, or, without
    /// such assumes, all of them when they are few. Returns true when it did.
    pub fn solve_static(&mut self, program: &Program) -> bool {
        let n = self.slots.len().max(1);
        if self.input_assumes.is_empty() {
            let small = self.count <= MAX_STATIC_ENUMERATION
                && (self.count as usize).saturating_mul(n) <= MAX_LISTED_VALUES;
            if !small {
                return false;
            }
            let mut flat = Vec::with_capacity(self.count as usize * self.slots.len());
            let mut v = self.lo.clone();
            for _ in 0..self.count {
                flat.extend_from_slice(&v);
                self.advance(&mut v);
            }
            self.listed = Some(flat);
            self.n_listed = self.count as usize;
            return true;
        }
        let bounds: Vec<(i64, i64)> = self
            .lo
            .iter()
            .copied()
            .zip(self.hi.iter().copied())
            .collect();
        let budget = Budget {
            vectors: MAX_STATIC_ENUMERATION as usize,
            values: MAX_LISTED_VALUES,
            nodes: MAX_ENUMERATION_NODES,
        };
        match allowed(program, &self.slots, &bounds, &self.input_assumes, budget) {
            Some((flat, n_listed)) => {
                self.listed = Some(flat);
                self.n_listed = n_listed;
                // Solved: no longer evaluated per transition.
                true
            }
            None => {
                self.too_many = true;
                false
            }
        }
    }

    /// Input vectors per tick allowed by the input-only assumes, when there are some and they
    /// were solved up front.
    pub fn effective(&self) -> Option<u128> {
        (!self.input_assumes.is_empty() && self.listed.is_some()).then_some(self.n_listed as u128)
    }

    /// The listed vectors, flat (`slots.len()` values each), and how many there are.
    pub fn listed(&self) -> Option<(&[i64], usize)> {
        self.listed.as_deref().map(|l| (l, self.n_listed))
    }

    /// Input vectors per tick the engine will enumerate: the listed ones, or the raw space.
    pub fn per_tick(&self) -> u128 {
        if self.listed.is_some() {
            self.n_listed as u128
        } else {
            self.count
        }
    }

    /// The declared bounds of input `k` (in [`Program::inputs`] order).
    pub fn bounds(&self, k: usize) -> (i64, i64) {
        (self.lo[k], self.hi[k])
    }

    /// The first vector (every input at its lowest value).
    pub fn first(&self, out: &mut [i64]) {
        out.copy_from_slice(&self.lo);
    }

    /// Advance `v` to the next vector in raw enumeration order (wrapping after the last).
    pub fn advance(&self, v: &mut [i64]) {
        for (k, x) in v.iter_mut().enumerate() {
            if *x < self.hi[k] {
                *x += 1;
                return;
            }
            *x = self.lo[k];
        }
    }

    /// The vector at position `pos` of the enumeration (of the listing when there is one).
    pub fn vector(&self, pos: u128) -> Vec<i64> {
        let n = self.slots.len();
        match &self.listed {
            Some(flat) => {
                let i = usize::try_from(pos).unwrap_or(usize::MAX);
                flat.get(i.saturating_mul(n)..i.saturating_mul(n).saturating_add(n))
                    .map_or_else(|| self.lo.clone(), <[i64]>::to_vec)
            }
            None => self.decode(pos),
        }
    }

    /// The vector with raw index `idx`.
    pub fn decode(&self, mut idx: u128) -> Vec<i64> {
        self.lo
            .iter()
            .zip(&self.hi)
            .map(|(&lo, &hi)| {
                let size = (hi as i128 - lo as i128 + 1) as u128;
                let d = idx % size;
                idx /= size;
                lo + d as i64
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decode_matches_advance() {
        let sp = InputSpace {
            slots: vec![0, 1, 2],
            lo: vec![0, -1, 3],
            hi: vec![1, 1, 4],
            count: 12,
            input_assumes: Vec::new(),
            state_assumes: Vec::new(),
            mixed_assumes: Vec::new(),
            listed: None,
            n_listed: 0,
            too_many: false,
        };
        let mut v = vec![0; 3];
        sp.first(&mut v);
        for idx in 0..12u128 {
            assert_eq!(sp.decode(idx), v, "index {idx}");
            sp.advance(&mut v);
        }
        assert_eq!(v, vec![0, -1, 3]);
    }
}
