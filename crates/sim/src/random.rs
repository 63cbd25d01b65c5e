//! Random inputs within their types and the system's `assume`s, from a seed.
//!
//! The distribution of a tick's inputs is the product of one distribution per input (uniform
//! over its range; a boolean or event present with probability ½ unless a rate is declared in
//! the model, `rate instance.input = P;`, or given by [`RandomInputs::set_rate`])
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
use statecheck_ir::{eval, ExprId, Machine, Program};

/// Draws per tick before a state-dependent `assume` is solved by enumeration.
pub const REJECTION_TRIES: usize = 64;

/// Most candidate vectors enumerated in one tick to solve a state-dependent `assume`.
pub const MAX_ENUMERATED: u128 = 1 << 16;

/// Draws per tick, when the candidates are too many to enumerate, before giving up.
pub const MAX_TRIES: usize = 10_000;

/// Random inputs for a fixed number of ticks of one program.
pub struct RandomInputs {
    rng: rand::rngs::StdRng,
    ticks: u64,
    /// Per input: the probability that it is 1, for a 0..1 input given a rate.
    rates: Vec<(usize, f64)>,
    solved: Option<Solved>,
    /// With [`RandomInputs::set_guided`]: what the run has covered.
    guide: Option<crate::guided::Guide>,
}

/// The `assume`s of one program, solved.
struct Solved {
    space: InputSpace,
    rates: Vec<Option<f64>>,
    /// With rates and a listing: the cumulative weights of the listed vectors.
    cumulative: Vec<f64>,
    /// Input-only conjuncts still to check per draw (when they could not be listed).
    input_checks: Vec<ExprId>,
    state_checks: Vec<ExprId>,
    mixed_checks: Vec<ExprId>,
    /// A copy of the slots: the state before the tick and a candidate's inputs.
    slots: Vec<i64>,
    input_slots: Vec<u32>,
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

impl RandomInputs {
    /// `ticks` ticks of random inputs of `program` from `seed` (the same seed gives the same
    /// inputs), with the rates the system declares (`rate instance.input = P;`).
    pub fn new(program: &Program, seed: u64, ticks: u64) -> Self {
        let rates: Vec<(usize, f64)> = program
            .inputs
            .iter()
            .enumerate()
            .filter_map(|(k, i)| i.rate.map(|r| (k, r)))
            .collect();
        RandomInputs {
            rng: rand::rngs::StdRng::seed_from_u64(seed),
            ticks,
            solved: Some(Solved::new(program, &rates)),
            rates,
            guide: None,
        }
    }

    /// Guide the inputs towards coverage (`crate::guided`): each tick, prefer a vector whose
    /// successor enters a state or fires a transition not covered yet.
    pub fn set_guided(&mut self, program: &Program) {
        self.guide = Some(crate::guided::Guide::new(program));
    }

    /// Make input `k` of `program` (in [`Program::inputs`] order, a boolean or event, or an
    /// integer in `0..1`) be 1 with probability `rate` instead of ½ or the declared rate.
    pub fn set_rate(&mut self, program: &Program, k: usize, rate: f64) -> Result<(), RateError> {
        let err = |message: String| RateError { input: k, message };
        let Some(inp) = program.inputs.get(k) else {
            return Err(err(format!("no input #{k}")));
        };
        if !(0.0..=1.0).contains(&rate) {
            return Err(err(format!(
                "the rate {rate} is not a probability (0 to 1)"
            )));
        }
        let s = &program.slots[inp.slot as usize];
        if (s.lo, s.hi) != (0, 1) {
            return Err(err(format!(
                "a rate applies to a boolean or an event, not to a value in {}..{}",
                s.lo, s.hi
            )));
        }
        self.rates.retain(|&(j, _)| j != k);
        self.rates.push((k, rate));
        self.solved = Some(Solved::new(program, &self.rates));
        Ok(())
    }
}

impl Solved {
    fn new(p: &Program, rates: &[(usize, f64)]) -> Solved {
        let mut space = InputSpace::new(p);
        if !space.input_assumes.is_empty() {
            space.solve_static(p);
        }
        let input_checks = if space.listed().is_some() {
            Vec::new()
        } else {
            space.input_assumes.clone()
        };
        let mut per_input = vec![None; p.inputs.len()];
        for &(k, r) in rates {
            per_input[k] = Some(r);
        }
        let mut cumulative = Vec::new();
        if let (Some((flat, n)), false) = (space.listed(), rates.is_empty()) {
            let w = p.inputs.len();
            let mut total = 0.0;
            cumulative.reserve(n);
            for v in 0..n {
                total += weight(&per_input, &flat[v * w..v * w + w]);
                cumulative.push(total);
            }
        }
        Solved {
            state_checks: space.state_assumes.clone(),
            mixed_checks: space.mixed_assumes.clone(),
            input_checks,
            space,
            rates: per_input,
            cumulative,
            slots: Vec::new(),
            input_slots: p.inputs.iter().map(|i| i.slot).collect(),
            candidates: Vec::new(),
            weights: Vec::new(),
        }
    }

    /// One draw from the proposal: a listed vector, or each input on its own.
    fn propose(&self, rng: &mut impl Rng, out: &mut [i64]) {
        if let Some((flat, n)) = self.space.listed() {
            if n == 0 {
                return;
            }
            let i = if self.cumulative.is_empty() {
                rng.random_range(0..n)
            } else {
                pick_weighted(rng, &self.cumulative)
            };
            let w = out.len();
            out.copy_from_slice(&flat[i * w..i * w + w]);
            return;
        }
        for (k, x) in out.iter_mut().enumerate() {
            *x = match self.rates[k] {
                Some(r) => i64::from(rng.random_bool(r)),
                None => {
                    let (lo, hi) = self.space.bounds(k);
                    rng.random_range(lo..=hi)
                }
            };
        }
    }

    fn holds(&self, p: &Program, e: ExprId) -> bool {
        matches!(eval(&p.nodes, &self.slots, e), Ok(v) if v != 0)
    }

    /// Whether the candidate in the input slots satisfies the conjuncts checked per draw.
    fn allowed(&self, p: &Program) -> bool {
        self.input_checks.iter().all(|&e| self.holds(p, e))
            && self.mixed_checks.iter().all(|&e| self.holds(p, e))
    }

    fn set_inputs(&mut self, v: &[i64]) {
        for (&s, &x) in self.input_slots.iter().zip(v) {
            self.slots[s as usize] = x;
        }
    }

    /// The first `assume` (by index) that the current slots violate.
    fn first_violated(&self, p: &Program) -> usize {
        p.assumes
            .iter()
            .position(|&a| !self.holds(p, a))
            .unwrap_or(0)
    }

    /// Every candidate tried, one drawn among the allowed; `false` when none is.
    fn enumerate(&mut self, p: &Program, rng: &mut impl Rng, inputs: &mut [i64]) -> bool {
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
            if self.allowed(p) {
                self.candidates.extend_from_slice(&v);
                self.weights.push(weight(&self.rates, &v));
            }
            if !listed {
                self.space.advance(&mut v);
            }
        }
        if self.weights.is_empty() {
            return false;
        }
        let mut total = 0.0;
        for x in &mut self.weights {
            total += *x;
            *x = total;
        }
        let i = pick_weighted(rng, &self.weights);
        inputs.copy_from_slice(&self.candidates[i * w..i * w + w]);
        true
    }

    /// The inputs of one tick from the state in `m`.
    fn draw(&mut self, m: &Machine, rng: &mut impl Rng, inputs: &mut [i64]) -> Result<(), NoInput> {
        let p = m.program();
        self.slots.clear();
        self.slots.extend_from_slice(m.slots());
        if self.space.listed().is_some_and(|(_, n)| n == 0)
            || !self.state_checks.iter().all(|&e| self.holds(p, e))
        {
            self.set_inputs(inputs);
            let assume = self.first_violated(p);
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
            self.propose(rng, inputs);
            if !checked {
                return Ok(());
            }
            self.set_inputs(inputs);
            if self.allowed(p) {
                return Ok(());
            }
        }
        if small {
            if self.enumerate(p, rng, inputs) {
                return Ok(());
            }
            let assume = self.first_violated(p);
            return Err(NoInput::Deadlock { assume });
        }
        let assume = self.first_violated(p);
        Err(NoInput::NotFound { assume })
    }
}

impl Solved {
    /// The candidates of a guided tick (`crate::guided`), flat, `first` (the ordinary draw)
    /// first: every allowed vector when there are few, else more draws and `first` with each
    /// 0..1 input flipped; all satisfy the `assume`s in the state of `m`.
    fn candidates(&mut self, m: &Machine, rng: &mut impl Rng, first: &[i64], out: &mut Vec<i64>) {
        let p = m.program();
        let w = first.len();
        out.clear();
        out.extend_from_slice(first);
        if let Some((_, n)) = self
            .space
            .listed()
            .filter(|&(_, n)| n <= crate::guided::MAX_LISTED)
        {
            for pos in 0..n {
                let v = self.space.vector(pos as u128);
                if v != first && self.admits(p, &v) {
                    out.extend_from_slice(&v);
                }
            }
            return;
        }
        let mut v = vec![0; w];
        if self.space.listed().is_none()
            && self.space.per_tick() <= crate::guided::MAX_LISTED as u128
        {
            self.space.first(&mut v);
            for _ in 0..self.space.per_tick() {
                let c = v.clone();
                if c != first && self.admits(p, &c) {
                    out.extend_from_slice(&c);
                }
                self.space.advance(&mut v);
            }
            return;
        }
        for _ in 0..crate::guided::EXTRA_DRAWS {
            if self.draw(m, rng, &mut v).is_ok() {
                out.extend_from_slice(&v);
            }
        }
        for k in 0..w {
            if self.space.bounds(k) != (0, 1) {
                continue;
            }
            v.copy_from_slice(first);
            v[k] = 1 - v[k];
            if self.admits(p, &v) {
                out.extend_from_slice(&v);
            }
        }
    }

    /// Whether every `assume` holds for inputs `v` in the state copied by the last draw.
    fn admits(&mut self, p: &Program, v: &[i64]) -> bool {
        self.set_inputs(v);
        p.assumes.iter().all(|&a| self.holds(p, a))
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

impl InputSource for RandomInputs {
    fn next(&mut self, tick: u64, machine: &Machine, inputs: &mut [i64]) -> Result<bool, NoInput> {
        if tick >= self.ticks {
            return Ok(false);
        }
        let solved = self
            .solved
            .get_or_insert_with(|| Solved::new(machine.program(), &self.rates));
        solved.draw(machine, &mut self.rng, inputs)?;
        if let Some(guide) = &mut self.guide {
            let w = inputs.len();
            let mut cands = std::mem::take(guide.candidates_mut());
            solved.candidates(machine, &mut self.rng, inputs, &mut cands);
            *guide.candidates_mut() = cands;
            let i = guide.choose(machine, w);
            if i > 0 {
                inputs.copy_from_slice(&guide.candidates_mut()[i * w..i * w + w]);
            }
        }
        Ok(true)
    }
}
