//! Random inputs within their types and the system's `assume`s, from a seed.

use crate::run::InputSource;
use rand::{RngExt, SeedableRng};
use statecheck_ir::{Machine, Program};

/// How many draws per tick before giving up on satisfying the `assume`s.
pub const MAX_TRIES: usize = 10_000;

/// Uniformly random inputs for a fixed number of ticks; events are present with probability ½.
pub struct RandomInputs {
    rng: rand::rngs::StdRng,
    ticks: u64,
}

impl RandomInputs {
    /// `ticks` ticks of random inputs from `seed` (the same seed gives the same inputs).
    pub fn new(seed: u64, ticks: u64) -> Self {
        RandomInputs {
            rng: rand::rngs::StdRng::seed_from_u64(seed),
            ticks,
        }
    }
}

impl InputSource for RandomInputs {
    fn next(&mut self, tick: u64, machine: &Machine, inputs: &mut [i64]) -> Result<bool, usize> {
        if tick >= self.ticks {
            return Ok(false);
        }
        let p: &Program = machine.program();
        let mut scratch = machine.clone();
        for _ in 0..MAX_TRIES {
            for (k, inp) in p.inputs.iter().enumerate() {
                let s = &p.slots[inp.slot as usize];
                inputs[k] = self.rng.random_range(s.lo..=s.hi);
                scratch.set(inp.slot, inputs[k]);
            }
            let violated = p
                .assumes
                .iter()
                .position(|a| scratch.eval(*a).map_or(true, |v| v == 0));
            if violated.is_none() {
                return Ok(true);
            }
        }
        let first = p
            .assumes
            .iter()
            .position(|a| scratch.eval(*a).map_or(true, |v| v == 0))
            .unwrap_or(0);
        Err(first)
    }
}
