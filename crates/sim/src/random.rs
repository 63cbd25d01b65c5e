//! Random inputs within their types and the system's `assume`s, from a seed.
//!
//! The distribution of a tick's inputs is the product of one distribution per input (uniform
//! over its range; a boolean or event present with probability ½ unless a rate is given)
//! conditioned on the `assume`s holding. The `assume`s are solved the way the explicit engine
//! solves them ([`statecheck_ir::assume`]), by the same code:
//!
//! - conjuncts that read only inputs are solved up front: the allowed vectors are listed by the
//!   pruned enumeration and each tick draws one of them (uniformly, or weighted by the rates).
//!   When too many are allowed to list, vectors are drawn input by input and rejected until
//!   one satisfies them;
//! - conjuncts that read only the state are evaluated once per tick: when one fails, no input
//!   is allowed at all and the run ends in a deadlock;
//! - conjuncts that read the state and the inputs are handled by rejection sampling
//!   ([`REJECTION_TRIES`] draws); when that fails and the candidates are few
//!   ([`MAX_ENUMERATED`]), every candidate is tried and one is drawn among those allowed, so
//!   that "none is allowed" is a proven deadlock. Rejection followed by enumeration still draws
//!   from the conditioned distribution: both steps sample it exactly.

use crate::run::{InputSource, NoInput};
use rand::{Rng, RngExt, SeedableRng};
use statecheck_ir::assume::InputSpace;
use statecheck_ir::{Machine, Prepared, Program};

/// Draws per tick before a state-dependent `assume` is solved by enumeration.
pub const REJECTION_TRIES: usize = 64;

/// Most candidate vectors enumerated in one tick to solve a state-dependent `assume`.
pub const MAX_ENUMERATED: u128 = 1 << 16;

/// Draws per tick, when the candidates are too many to enumerate, before giving up.
pub const MAX_TRIES: usize = 10_000;

/// Random inputs for a fixed number of ticks.
pub struct RandomInputs<'p> {
    p: &'p Program,
    rng: rand::rngs::StdRng,
    ticks: u64,
    space: InputSpace,
    /// Per input: the probability that it is 1, for a 0..1 input given a rate.
    rates: Vec<Option<f64>>,
    /// With rates and a listing: the cumulative weights of the listed vectors.
    cumulative: Vec<f64>,
    /// Input-only conjuncts still to check per draw (when they could not be listed).
    input_checks: Vec<Prepared>,
    state_checks: Vec<Prepared>,
    mixed_checks: Vec<Prepared>,
    scratch: Machine<'p>,
    candidates: Vec<i64>,
    weights: Vec<f64>,
}

/// A rate that cannot be applied.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RateError {
    /// Index of the input in [`Program::inputs`].
    pub input: usize,
    /// What is wrong.
    pub message: String,
}

impl<'p> RandomInputs<'p> {
    /// `ticks` ticks of random inputs of `program` from `seed` (the same seed gives the same
    /// inputs).
    pub fn new(program: &'p Program, seed: u64, ticks: u64) -> Self {
        let mut space = InputSpace::new(program);
        if !space.input_assumes.is_empty() {
            space.solve_static(program);
        }
        let scratch = Machine::new(program);
        let prep = |es: &[u32]| es.iter().map(|&e| program.prepare(e)).collect::<Vec<_>>();
        let input_checks = if space.listed().is_some() {
            Vec::new()
        } else {
            prep(&space.input_assumes)
        };
        let state_checks = prep(&space.state_assumes);
        let mixed_checks = prep(&space.mixed_assumes);
        RandomInputs {
            p: program,
            rng: rand::rngs::StdRng::seed_from_u64(seed),
            ticks,
            rates: vec![None; program.inputs.len()],
            cumulative: Vec::new(),
            input_checks,
            state_checks,
            mixed_checks,
            scratch,
            candidates: Vec::new(),
            weights: Vec::new(),
            space,
        }
    }

    /// Make input `k` (in [`Program::inputs`] order, a boolean or event, or an integer in
    /// `0..1`) be 1 with probability `rate` instead of ½.
    pub fn set_rate(&mut self, k: usize, rate: f64) -> Result<(), RateError> {
        let err = |message: String| RateError { input: k, message };
        if k >= self.rates.len() {
            return Err(err(format!("no input #{k}")));
        }
        if !(0.0..=1.0).contains(&rate) {
            return Err(err(format!(
                "the rate {rate} is not a probability (0 to 1)"
            )));
        }
        if self.space.bounds(k) != (0, 1) {
            let (lo, hi) = self.space.bounds(k);
            return Err(err(format!(
                "a rate applies to a boolean or an event, not to a value in {lo}..{hi}"
            )));
        }
        self.rates[k] = Some(rate);
        self.cumulative.clear();
        if let Some((flat, n)) = self.space.listed() {
            let w = self.rates.len();
            let mut total = 0.0;
            self.cumulative.reserve(n);
            for v in 0..n {
                total += weight(&self.rates, &flat[v * w..v * w + w]);
                self.cumulative.push(total);
            }
        }
        Ok(())
    }

    /// One draw from the proposal: a listed vector, or each input on its own.
    fn propose(&mut self, out: &mut [i64]) {
        if let Some((flat, n)) = self.space.listed() {
            if n == 0 {
                return;
            }
            let i = if self.cumulative.is_empty() {
                self.rng.random_range(0..n)
            } else {
                pick_weighted(&mut self.rng, &self.cumulative)
            };
            let w = out.len();
            out.copy_from_slice(&flat[i * w..i * w + w]);
            return;
        }
        for (k, x) in out.iter_mut().enumerate() {
            *x = match self.rates[k] {
                Some(r) => i64::from(self.rng.random_bool(r)),
                None => {
                    let (lo, hi) = self.space.bounds(k);
                    self.rng.random_range(lo..=hi)
                }
            };
        }
    }

    /// Whether the candidate in the scratch machine's input slots satisfies the conjuncts that
    /// are checked per draw.
    fn allowed(&mut self) -> bool {
        let m = &mut self.scratch;
        self.input_checks.iter().all(|&e| m.holds(e))
            && self.mixed_checks.iter().all(|&e| m.holds(e))
    }

    fn set_inputs(&mut self, v: &[i64]) {
        for (inp, &x) in self.p.inputs.iter().zip(v) {
            self.scratch.set(inp.slot, x);
        }
    }

    /// The first `assume` (by index) that the scratch machine violates.
    fn first_violated(&mut self) -> usize {
        let m = &mut self.scratch;
        self.p
            .assumes
            .iter()
            .position(|&a| m.eval(a).map_or(true, |v| v == 0))
            .unwrap_or(0)
    }

    /// Every candidate tried, one drawn among the allowed; `false` when none is.
    fn enumerate(&mut self, inputs: &mut [i64]) -> bool {
        let w = inputs.len();
        let n = self.space.per_tick();
        self.candidates.clear();
        self.weights.clear();
        let mut v = vec![0; w];
        self.space.first(&mut v);
        let listed = self.space.listed().is_some();
        for pos in 0..n {
            if listed {
                v = self.space.vector(pos);
            }
            self.set_inputs(&v);
            if self.allowed() {
                self.candidates.extend_from_slice(&v);
                self.weights.push(weight(&self.rates, &v));
            }
            if !listed {
                self.space.advance(&mut v);
            }
        }
        let found = self.weights.len();
        if found == 0 {
            return false;
        }
        let mut total = 0.0;
        for x in &mut self.weights {
            total += *x;
            *x = total;
        }
        let i = pick_weighted(&mut self.rng, &self.weights);
        inputs.copy_from_slice(&self.candidates[i * w..i * w + w]);
        true
    }
}

/// The weight of a vector under the rates: the product of each rated input's probability of
/// its value (unrated inputs contribute the same factor to every vector).
fn weight(rates: &[Option<f64>], v: &[i64]) -> f64 {
    rates
        .iter()
        .zip(v)
        .map(|(r, &x)| match r {
            Some(r) if x != 0 => *r,
            Some(r) => 1.0 - r,
            None => 1.0,
        })
        .product()
}

/// An index drawn with probability proportional to the increments of `cumulative`.
fn pick_weighted(rng: &mut impl Rng, cumulative: &[f64]) -> usize {
    let total = cumulative.last().copied().unwrap_or(0.0);
    if total <= 0.0 {
        return rng.random_range(0..cumulative.len().max(1));
    }
    let x = rng.random_range(0.0..total);
    cumulative
        .partition_point(|&c| c <= x)
        .min(cumulative.len() - 1)
}

impl InputSource for RandomInputs<'_> {
    fn next(&mut self, tick: u64, machine: &Machine, inputs: &mut [i64]) -> Result<bool, NoInput> {
        if tick >= self.ticks {
            return Ok(false);
        }
        self.scratch.load_state(machine.state());
        if self.space.listed().is_some_and(|(_, n)| n == 0) {
            self.set_inputs(inputs);
            let assume = self.first_violated();
            return Err(NoInput::Deadlock { assume });
        }
        let state_ok = {
            let m = &mut self.scratch;
            self.state_checks.iter().all(|&e| m.holds(e))
        };
        if !state_ok {
            self.set_inputs(inputs);
            let assume = self.first_violated();
            return Err(NoInput::Deadlock { assume });
        }
        let checked = !self.input_checks.is_empty() || !self.mixed_checks.is_empty();
        let small = self.space.per_tick() <= MAX_ENUMERATED;
        let tries = if !checked {
            1
        } else if small {
            REJECTION_TRIES
        } else {
            MAX_TRIES
        };
        for _ in 0..tries {
            self.propose(inputs);
            if !checked {
                return Ok(true);
            }
            self.set_inputs(inputs);
            if self.allowed() {
                return Ok(true);
            }
        }
        if small {
            if self.enumerate(inputs) {
                return Ok(true);
            }
            let assume = self.first_violated();
            return Err(NoInput::Deadlock { assume });
        }
        let assume = self.first_violated();
        Err(NoInput::NotFound { assume })
    }
}
