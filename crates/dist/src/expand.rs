//! Expanding one state: every input vector the `assume`s allow, one tick of the IR each
//! (`statecheck_ir::Machine`), the still-open properties checked on the transition by the
//! explicit engine's own reading of their goals ([`Spec::decided_by`]).

use statecheck_explicit::pack::Packer;
use statecheck_explicit::props::Spec;
use statecheck_ir::assume::InputSpace;
use statecheck_ir::{Machine, Prepared, Program};

/// A worker's expander (a machine and scratch buffers of its own).
pub(crate) struct Expander<'p> {
    packer: &'p Packer,
    space: &'p InputSpace,
    specs: &'p [Spec],
    m: Machine<'p>,
    /// Assumes evaluated on every transition (all of them when the vectors are not listed).
    per_tick: Vec<Prepared>,
    state_assumes: Vec<Prepared>,
    state: Vec<i64>,
    inp: Vec<i64>,
    succ: Vec<u64>,
}

impl<'p> Expander<'p> {
    /// An expander of `program`'s states.
    pub fn new(
        program: &'p Program,
        packer: &'p Packer,
        space: &'p InputSpace,
        specs: &'p [Spec],
    ) -> Self {
        let prep = |v: &[statecheck_ir::ExprId]| -> Vec<Prepared> {
            v.iter().map(|&a| program.prepare(a)).collect()
        };
        let mut per_tick = prep(&space.mixed_assumes);
        if space.listed().is_none() {
            per_tick.extend(prep(&space.input_assumes));
        }
        Expander {
            packer,
            space,
            specs,
            m: Machine::new(program),
            per_tick,
            state_assumes: prep(&space.state_assumes),
            state: vec![0; program.n_state],
            inp: vec![0; space.slots.len()],
            succ: vec![0; packer.words],
        }
    }

    /// Expand the packed state `src`: `open[i]` tells whether property `i` is still to be
    /// looked for (cleared when a transition decides it, which `found(i, input)` reports);
    /// `succ(state, input)` gets every successor other than `src` itself. Returns the number
    /// of transitions (input vectors the assumes allow).
    pub fn expand(
        &mut self,
        src: &[u64],
        open: &mut [bool],
        found: &mut impl FnMut(usize, u32),
        succ: &mut impl FnMut(&[u64], u32),
    ) -> u64 {
        self.packer.unpack_words(src, &mut self.state);
        if !self.state_assumes.is_empty() {
            self.m.load_state(&self.state);
            if !self.state_assumes.iter().all(|a| self.m.holds(*a)) {
                return 0;
            }
        }
        let n = self.space.slots.len();
        let mut transitions = 0;
        match self.space.listed() {
            Some((flat, count)) => {
                for idx in 0..count {
                    self.m.load(&self.state, &flat[idx * n..idx * n + n]);
                    transitions += self.tick(src, idx as u32, open, found, succ);
                }
            }
            None => {
                self.space.first(&mut self.inp);
                for idx in 0..self.space.count as u64 {
                    self.m.load(&self.state, &self.inp);
                    self.space.advance(&mut self.inp);
                    transitions += self.tick(src, idx as u32, open, found, succ);
                }
            }
        }
        transitions
    }

    /// The tick from the loaded state and inputs, if the per-tick assumes allow it: 1 when
    /// taken, else 0.
    #[inline]
    fn tick(
        &mut self,
        src: &[u64],
        input: u32,
        open: &mut [bool],
        found: &mut impl FnMut(usize, u32),
        succ: &mut impl FnMut(&[u64], u32),
    ) -> u64 {
        if !self.per_tick.iter().all(|a| self.m.holds(*a)) {
            return 0;
        }
        match self.m.step() {
            Err(e) => {
                let b = e.kind.builtin();
                for (i, s) in self.specs.iter().enumerate() {
                    if open[i] && s.builtin() == Some(b) {
                        open[i] = false;
                        found(i, input);
                    }
                }
            }
            Ok(()) => {
                for (i, s) in self.specs.iter().enumerate() {
                    if open[i] && s.builtin().is_none() && s.decided_by(&mut self.m) {
                        open[i] = false;
                        found(i, input);
                    }
                }
                self.packer.pack_words(self.m.state(), &mut self.succ);
                if self.succ != src {
                    succ(&self.succ, input);
                }
            }
        }
        1
    }
}
