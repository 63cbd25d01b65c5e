//! The input vectors of one tick, enumerated in a fixed order so that an index identifies a
//! vector: mixed radix over [`Program::inputs`], the first input varying fastest.

use statecheck_ir::{ExprId, Machine, Node, Program, SlotId};

/// Most input vectors [`InputSpace::solve_static`] enumerates up front.
pub const MAX_STATIC_ENUMERATION: u128 = 1 << 20;

/// The space of input vectors of a program.
#[derive(Clone, Debug)]
pub struct InputSpace {
    /// Slot of each input.
    pub slots: Vec<SlotId>,
    lo: Vec<i64>,
    hi: Vec<i64>,
    /// Number of vectors (saturating at `u128::MAX`).
    pub count: u128,
    /// When every `assume` reads only inputs: the vectors they allow, as (index, values),
    /// computed once instead of in every state.
    pub allowed: Option<Vec<(u32, Vec<i64>)>>,
}

impl InputSpace {
    /// The input space of `program`, before `assume`s.
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
        InputSpace {
            slots,
            lo,
            hi,
            count,
            allowed: None,
        }
    }

    /// If there are `assume`s, they all read only input slots, and the space is small enough,
    /// enumerate the allowed vectors once (see [`InputSpace::allowed`]). Returns true when it did.
    pub fn solve_static(&mut self, program: &Program) -> bool {
        let lo = program.n_state as u32;
        let hi = lo + program.inputs.len() as u32;
        if program.assumes.is_empty()
            || self.count > MAX_STATIC_ENUMERATION
            || !program
                .assumes
                .iter()
                .all(|a| reads_only(program, *a, lo, hi))
        {
            return false;
        }
        let mut m = Machine::new(program);
        let mut v = self.lo.clone();
        let mut allowed = Vec::new();
        for idx in 0..self.count as u32 {
            for (k, &s) in self.slots.iter().enumerate() {
                m.set(s, v[k]);
            }
            if program
                .assumes
                .iter()
                .all(|a| matches!(m.eval(*a), Ok(x) if x != 0))
            {
                allowed.push((idx, v.clone()));
            }
            self.advance(&mut v);
        }
        self.allowed = Some(allowed);
        true
    }

    /// Input vectors per tick after the `assume`s, when known up front.
    pub fn effective(&self) -> Option<u128> {
        self.allowed.as_ref().map(|a| a.len() as u128)
    }

    /// The first vector (every input at its lowest value).
    pub fn first(&self, out: &mut [i64]) {
        out.copy_from_slice(&self.lo);
    }

    /// Advance `v` to the next vector in enumeration order (wrapping after the last).
    pub fn advance(&self, v: &mut [i64]) {
        for (k, x) in v.iter_mut().enumerate() {
            if *x < self.hi[k] {
                *x += 1;
                return;
            }
            *x = self.lo[k];
        }
    }

    /// The vector with index `idx`.
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

/// True when expression `e` reads no slot outside `lo..hi` (unknown node kinds count as
/// reading anything).
fn reads_only(p: &Program, e: ExprId, lo: u32, hi: u32) -> bool {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match p.nodes.get(e as usize) {
            Some(Node::Const(_)) => {}
            Some(Node::Slot(s)) => {
                if *s < lo || *s >= hi {
                    return false;
                }
            }
            Some(Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, _, _, _)) => stack.push(*a),
            Some(Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b)) => {
                stack.extend([*a, *b])
            }
            Some(Node::Ite(c, a, b)) => stack.extend([*c, *a, *b]),
            _ => return false,
        }
    }
    true
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
            allowed: None,
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
