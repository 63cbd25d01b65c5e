//! Lasso hunting: random runs that end in a loop, searched for a counterexample of an `ltl`
//! property (or unbounded `respond`) too deep for the exhaustive engines.
//!
//! A lasso needs a state that recurs. With the inputs held constant the closed system is
//! deterministic and finite, so from any state it enters a cycle within as many ticks as it
//! has states: each attempt draws a random **prefix** of piecewise-constant inputs (a vector
//! drawn as random simulation draws it, within the `assume`s, held for a random number of
//! ticks, then another), then holds one **tail** vector (by preference the quiet one: every
//! rated input, a fault, at its likely value, every event absent) until the state after a tick
//! recurs. One tail in eight is **periodic** instead: a period of 2 to 32 ticks in which a
//! window of ticks takes a second vector (a setpoint read differently in two ticks of a bus
//! round, say), repeated until the state after a tick recurs at the same place of the period
//! (the closed system fed a periodic input is deterministic and finite too); half the time the
//! period is the length of a loop closed before (2 to 32 ticks), as a schedule's round
//! is. The run is then
//! a lasso; each open property's formula is evaluated on it with the
//! IR's lasso semantics ([`statecheck_ir::temporal::holds_on_lasso`]), on fair lassos only
//! (every justice atom somewhere in the loop, every compassion trigger there answered). A
//! violating lasso is shortened ([`shrink`]: segments removed and halved while it still
//! violates the property) and confirmed by replaying its scenario ([`crate::lasso::run_lasso`])
//! before it is reported. Half the attempts start from a kept run ([`Corpus`]) that reached a
//! valuation of the atoms no run had reached before, and extend it.
//!
//! Why this finds the FAM's lassos: their violations are "a fault pattern, then calm for
//! ever", and a pattern is a few held segments (a stall, a failure held through two bus
//! rounds); the exhaustive engines must enumerate every input in every tick up to that depth,
//! the hunt draws whole segments. It never proves anything: it runs until every property it
//! hunts is decided, the deadline, or the stop flag.

use crate::lasso::run_lasso;
use crate::random::RandomInputs;
use crate::run::{InputSource, Options};
use crate::scenario::from_lasso;
use rand::{RngExt, SeedableRng};
use statecheck_ir::temporal::{holds_on_lasso, Ltl, TemporalFormula};
use statecheck_ir::{eval, ExprId, Machine, Program};
use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// Limits and seed of a hunt.
#[derive(Clone, Copy, Debug)]
pub struct HuntOptions<'a> {
    /// The seed of the random draws (the same seed gives the same attempts).
    pub seed: u64,
    /// Stop at this instant.
    pub deadline: Option<Instant>,
    /// Stop when this flag is set.
    pub stop: Option<&'a AtomicBool>,
    /// Most ticks of a prefix (each attempt draws its length up to this).
    pub max_prefix: usize,
    /// Most ticks of a tail before the attempt is given up (no state recurred).
    pub max_tail: usize,
    /// Most attempts (`None`: until the deadline or the stop flag).
    pub max_attempts: Option<u64>,
}

impl Default for HuntOptions<'_> {
    fn default() -> Self {
        HuntOptions {
            seed: 0,
            deadline: None,
            stop: None,
            max_prefix: DEFAULT_MAX_PREFIX,
            max_tail: DEFAULT_MAX_TAIL,
            max_attempts: None,
        }
    }
}

/// Default of [`HuntOptions::max_prefix`].
pub const DEFAULT_MAX_PREFIX: usize = 1024;

/// Default of [`HuntOptions::max_tail`].
pub const DEFAULT_MAX_TAIL: usize = 4096;

/// Most replays spent shortening one lasso.
const SHRINK_REPLAYS: usize = 400;

/// A lasso violating a property, confirmed by replaying its scenario.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// The property, an index into [`Program::temporal`].
    pub property: usize,
    /// The input vectors of its ticks, in [`Program::inputs`] order.
    pub inputs: Vec<Vec<i64>>,
    /// The first tick of the loop: after the last tick, the state after tick
    /// `loop_start - 1` recurs.
    pub loop_start: usize,
}

/// What a hunt did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HuntStats {
    /// Attempts (prefix and tail) made.
    pub attempts: u64,
    /// Attempts whose tail closed a loop.
    pub loops: u64,
    /// Ticks simulated.
    pub ticks: u64,
}

/// One attempt's inputs: the prefix's held segments and the tail's period (one vector: a
/// constant tail; more: tail tick `k` takes vector `k % period`).
#[derive(Clone, Debug)]
struct Plan {
    segments: Vec<(Vec<i64>, usize)>,
    tail: Vec<Vec<i64>>,
}

/// The atoms the hunted formulas and the fairness constraints read, evaluated once per tick.
struct Atoms {
    exprs: Vec<ExprId>,
    column: HashMap<ExprId, usize>,
}

impl Atoms {
    fn new(program: &Program, formulas: &[(usize, &Ltl)]) -> Atoms {
        let mut exprs: Vec<ExprId> = Vec::new();
        for (_, f) in formulas {
            exprs.extend(f.atoms());
        }
        for fair in &program.fairness {
            exprs.extend(fair.trigger);
            exprs.push(fair.expr);
        }
        exprs.sort_unstable();
        exprs.dedup();
        let column = exprs.iter().enumerate().map(|(i, &e)| (e, i)).collect();
        Atoms { exprs, column }
    }

    fn record(&self, program: &Program, slots: &[i64], out: &mut Vec<bool>) {
        out.extend(
            self.exprs
                .iter()
                .map(|&e| matches!(eval(&program.nodes, slots, e), Ok(v) if v != 0)),
        );
    }
}

/// A lasso run: its input vectors, the atoms at each position, and the loop.
#[derive(Clone)]
struct Closed {
    inputs: Vec<Vec<i64>>,
    values: Vec<bool>,
    loop_start: usize,
}

/// Hunt lassos violating the `ltl` properties `targets` (indices into [`Program::temporal`];
/// CTL ones are skipped). `is_open(t)` says whether target `t` is still wanted (a property
/// decided elsewhere is dropped); `found` receives each confirmed lasso, once per property.
/// Returns when no target is open, or at the deadline, the stop flag or the attempt limit.
pub fn hunt(
    program: &Program,
    targets: &[usize],
    opts: &HuntOptions,
    is_open: &dyn Fn(usize) -> bool,
    found: &mut dyn FnMut(Found),
) -> HuntStats {
    let formulas: Vec<(usize, &Ltl)> = targets
        .iter()
        .filter_map(|&t| match &program.temporal.get(t)?.formula {
            TemporalFormula::Ltl(f) => Some((t, f)),
            TemporalFormula::Ctl(_) => None,
        })
        .collect();
    let mut open: Vec<(usize, &Ltl)> = formulas.clone();
    let atoms = Atoms::new(program, &formulas);
    let mut rng = rand::rngs::StdRng::seed_from_u64(opts.seed);
    // Two input distributions, alternated: the model's rates (faults rare, as a random run
    // sees them) and every vector alike (a fault as likely as calm).
    let mut rated = RandomInputs::new(program, opts.seed, u64::MAX);
    let mut even = RandomInputs::new(program, opts.seed ^ 0x9e37_79b9_7f4a_7c15, u64::MAX);
    for (k, inp) in program.inputs.iter().enumerate() {
        if inp.rate.is_some() {
            // Cannot fail: a rate is declared only on an input it applies to.
            let _ = even.set_rate(program, k, 0.5);
        }
    }
    let mut stats = HuntStats::default();
    let mut corpus = Corpus::default();
    // Lengths (2..=32) of the loops closed so far, at most PERIODS of them: a closed system
    // with a schedule (a bus round) closes loops of the schedule's length, the period a
    // periodic tail most likely needs.
    let mut periods: Vec<usize> = Vec::new();
    let over = |stats: &HuntStats| {
        opts.stop.is_some_and(|s| s.load(Ordering::Relaxed))
            || opts.deadline.is_some_and(|d| Instant::now() >= d)
            || opts.max_attempts.is_some_and(|m| stats.attempts >= m)
    };
    while !over(&stats) {
        open.retain(|&(t, _)| is_open(t));
        if open.is_empty() {
            break;
        }
        stats.attempts += 1;
        let source: &mut RandomInputs = if stats.attempts % 2 == 0 {
            &mut rated
        } else {
            &mut even
        };
        // Half the attempts extend a run that reached a new valuation of the atoms.
        let base = if !corpus.entries.is_empty() && rng.random_bool(0.5) {
            let i = rng.random_range(0..corpus.entries.len());
            Some(corpus.entries[i].clone())
        } else {
            None
        };
        let Some(plan) = draw_plan(program, &mut rng, source, opts.max_prefix, base, &periods)
        else {
            continue;
        };
        let Some(closed) = play(
            program,
            &atoms,
            &plan,
            opts.max_tail,
            &mut stats,
            Some(&mut corpus),
        ) else {
            continue;
        };
        stats.loops += 1;
        let length = closed.inputs.len() - closed.loop_start;
        if (2..=32).contains(&length) {
            if periods.len() < PERIODS {
                periods.push(length);
            } else {
                periods[stats.loops as usize % PERIODS] = length;
            }
        }
        let violated: Vec<usize> = open
            .iter()
            .filter(|(_, f)| violates(program, &atoms, &closed, f))
            .map(|&(t, _)| t)
            .collect();
        for t in violated {
            let Some(&(_, f)) = open.iter().find(|&&(u, _)| u == t) else {
                continue;
            };
            let closed = shrink(program, &atoms, plan.clone(), closed.clone(), f);
            if confirmed(program, t, &closed) {
                open.retain(|&(u, _)| u != t);
                found(Found {
                    property: t,
                    inputs: closed.inputs,
                    loop_start: closed.loop_start,
                });
            }
        }
    }
    stats
}

/// Most loop lengths remembered as periods of periodic tails.
const PERIODS: usize = 64;

/// Most runs kept in a [`Corpus`].
const CORPUS_SIZE: usize = 512;

/// Beginnings of runs worth extending: each reached a valuation of the atoms (the hunted
/// formulas' and the fairness constraints') that no run had reached before, as coverage-guided
/// fuzzing keeps inputs that cover something new. A violation that needs nested conditions (a
/// stall, then a permanent failure mode while the stall flag is still set, then calm) is found
/// a step at a time: each step is a new valuation, kept and extended later.
#[derive(Default)]
struct Corpus {
    entries: Vec<Vec<(Vec<i64>, usize)>>,
    seen: HashSet<Vec<bool>>,
}

impl Corpus {
    /// Note the valuation `sig` after tick `tick` of `plan` (whose prefix has `prefix` ticks),
    /// keeping the run up to that tick when the valuation is new.
    fn note(&mut self, sig: &[bool], plan: &Plan, prefix: usize, tick: usize) {
        if self.seen.contains(sig) || self.seen.len() >= 1 << 16 {
            return;
        }
        self.seen.insert(sig.to_vec());
        let mut kept: Vec<(Vec<i64>, usize)> = Vec::new();
        let mut left = tick + 1;
        for (v, d) in &plan.segments {
            if left == 0 {
                break;
            }
            let d = (*d).min(left);
            kept.push((v.clone(), d));
            left -= d;
        }
        if left > 0 && tick >= prefix {
            // A periodic tail is kept tick by tick (at most one period: a kept run is a
            // beginning to extend, and the period's continuation is drawn again).
            if let [v] = plan.tail.as_slice() {
                kept.push((v.clone(), left));
            } else {
                for k in 0..left.min(plan.tail.len()) {
                    kept.push((plan.tail[k].clone(), 1));
                }
            }
        }
        if self.entries.len() < CORPUS_SIZE {
            self.entries.push(kept);
        } else {
            let i = self.seen.len() % CORPUS_SIZE;
            self.entries[i] = kept;
        }
    }
}

/// A random plan: segments of held vectors up to a random total length (after the segments of
/// `base`, when given), and a tail: one vector, or (one time in eight) a period of two, whose
/// length is half the time one of `periods`.
fn draw_plan(
    program: &Program,
    rng: &mut rand::rngs::StdRng,
    source: &mut RandomInputs,
    max_prefix: usize,
    base: Option<Vec<(Vec<i64>, usize)>>,
    periods: &[usize],
) -> Option<Plan> {
    // Log-uniform: short prefixes are tried most, long ones (a fault held through several
    // bus rounds of five FAMs) still often.
    let top = max_prefix.max(1).ilog2();
    let cap = (1usize << rng.random_range(0..=top)).min(max_prefix);
    let mut m = Machine::new(program);
    let mut v: Vec<i64> = program
        .inputs
        .iter()
        .map(|i| program.slots[i.slot as usize].init)
        .collect();
    let segments: Vec<(Vec<i64>, usize)> = base.unwrap_or_default();
    let mut t = 0;
    for (w, d) in &segments {
        for _ in 0..*d {
            if !step(program, &mut m, w) {
                return None;
            }
        }
        t += d;
        v.clone_from(w);
    }
    let mut segments = segments;
    let len = t + rng.random_range(0..=cap);
    // The draws depend on the state (state-dependent `assume`s): the prefix is run as drawn.
    while t < len {
        // A new vector, or (one time in four) the previous one again: holds add up, so a
        // vector is sometimes held far longer than one segment.
        if segments.is_empty() || rng.random_range(0..4) != 0 {
            source.next(t as u64, &m, &mut v).ok()?;
        }
        let scale = [1, 8, 32, 128, 512][rng.random_range(0..5)];
        let d = rng.random_range(1..=scale).min(len - t);
        let mut held = 0;
        while held < d && step(program, &mut m, &v) {
            held += 1;
        }
        if held == 0 {
            return None;
        }
        segments.push((v.clone(), held));
        t += held;
    }
    let last = segments.last().map(|(v, _)| v.clone()).unwrap_or(v);
    let one = match rng.random_range(0..4) {
        0 | 1 => quiet(program, rng, &last),
        2 => last,
        _ => {
            let mut w = last.clone();
            source.next(t as u64, &m, &mut w).ok()?;
            w
        }
    };
    if rng.random_range(0..8) != 0 {
        return Some(Plan {
            segments,
            tail: vec![one],
        });
    }
    // A periodic tail: `one`, except in a window of the period, which takes `other`: a fresh
    // draw, or (half the time) that draw made quiet, so that only setpoints differ from a
    // quiet `one` (faults stay off in the loop, as "faults stop occurring" asks).
    // Half the time the length of a loop closed before (module doc), else any.
    let period = if !periods.is_empty() && rng.random_bool(0.5) {
        periods[rng.random_range(0..periods.len())]
    } else {
        rng.random_range(2..=32usize)
    };
    let mut other = one.clone();
    source.next(t as u64, &m, &mut other).ok()?;
    if rng.random_bool(0.5) {
        other = quiet(program, rng, &other);
    }
    let start = rng.random_range(0..period);
    let width = rng.random_range(1..period);
    let tail = (0..period)
        .map(|k| {
            if (k + period - start) % period < width {
                other.clone()
            } else {
                one.clone()
            }
        })
        .collect();
    Some(Plan { segments, tail })
}

/// `last` with every rated input at its likely value, every event absent, and each other
/// input at its initial value or its value in `last` (a coin flip each): a fault without a
/// rate (an enumeration such as `fault: EnvFault = NONE`) is quiet at its initial value, a
/// setpoint is kept at its last.
fn quiet(program: &Program, rng: &mut rand::rngs::StdRng, last: &[i64]) -> Vec<i64> {
    program
        .inputs
        .iter()
        .zip(last)
        .map(|(inp, &x)| match inp.rate {
            Some(r) => i64::from(r > 0.5),
            None if inp.is_event => 0,
            None if rng.random_bool(0.5) => program.slots[inp.slot as usize].init,
            None => x,
        })
        .collect()
}

/// One tick of `m` with inputs `v`: false when an `assume` refuses them or the tick fails.
fn step(program: &Program, m: &mut Machine, v: &[i64]) -> bool {
    for (inp, &x) in program.inputs.iter().zip(v) {
        m.set(inp.slot, x);
    }
    if program
        .assumes
        .iter()
        .any(|&a| m.eval(a).map_or(true, |x| x == 0))
    {
        return false;
    }
    m.step().is_ok()
}

/// Run `plan`: the prefix, then the tail until the state after a tick recurs at the same place
/// of the tail's period. `None` when a tick is refused or fails, or no state recurs within
/// `max_tail` ticks.
fn play(
    program: &Program,
    atoms: &Atoms,
    plan: &Plan,
    max_tail: usize,
    stats: &mut HuntStats,
    mut corpus: Option<&mut Corpus>,
) -> Option<Closed> {
    let w = atoms.exprs.len();
    let prefix: usize = plan.segments.iter().map(|(_, d)| d).sum();
    let mut note = |values: &[bool], tick: usize| {
        if let Some(c) = corpus.as_deref_mut() {
            c.note(&values[tick * w..(tick + 1) * w], plan, prefix, tick);
        }
    };
    let mut m = Machine::new(program);
    let mut inputs: Vec<Vec<i64>> = Vec::new();
    let mut values: Vec<bool> = Vec::new();
    for (v, d) in &plan.segments {
        for _ in 0..*d {
            stats.ticks += 1;
            if !step(program, &mut m, v) {
                return None;
            }
            inputs.push(v.clone());
            atoms.record(program, m.slots(), &mut values);
            note(&values, inputs.len() - 1);
        }
    }
    let prefix = inputs.len();
    let period = plan.tail.len().max(1);
    // The state after tick `i`, with the place in the period of the next tail tick, for every
    // `i >= prefix - 1` (the loop must start within the tail, whose inputs repeat with the
    // period); after tick 0 at the earliest.
    let mut seen: HashMap<(Vec<i64>, usize), usize> = HashMap::new();
    if prefix > 0 {
        seen.insert((m.state().to_vec(), 0), prefix - 1);
    }
    for k in 0..max_tail {
        let v = plan.tail.get(k % period)?;
        stats.ticks += 1;
        if !step(program, &mut m, v) {
            return None;
        }
        let j = inputs.len();
        inputs.push(v.clone());
        atoms.record(program, m.slots(), &mut values);
        note(&values, j);
        let key = (m.state().to_vec(), (k + 1) % period);
        if let Some(&i) = seen.get(&key) {
            // State after tick j == state after tick i, and the next tail ticks take the same
            // vectors from tick i + 1 on: ticks i + 1 ..= j repeat for ever.
            return Some(Closed {
                inputs,
                values,
                loop_start: i + 1,
            });
        }
        seen.insert(key, j);
    }
    None
}

/// Whether the lasso is fair and violates `f`.
fn violates(program: &Program, atoms: &Atoms, c: &Closed, f: &Ltl) -> bool {
    let n = c.inputs.len();
    let k = c.loop_start;
    let w = atoms.exprs.len();
    let at = |e: ExprId, i: usize| {
        atoms
            .column
            .get(&e)
            .is_some_and(|&col| c.values[i * w + col])
    };
    let in_loop = |e: ExprId| (k..n).any(|i| at(e, i));
    let fair = program.fairness.iter().all(|fc| match fc.trigger {
        None => in_loop(fc.expr),
        Some(p) => !in_loop(p) || in_loop(fc.expr),
    });
    fair && !holds_on_lasso(f, &at, n, k)
}

/// Shorten a violating plan: remove segments, then halve them, keeping each change after
/// which the plan still closes a loop violating `f` (at most [`SHRINK_REPLAYS`] replays).
fn shrink(program: &Program, atoms: &Atoms, mut plan: Plan, mut best: Closed, f: &Ltl) -> Closed {
    let mut replays = 0;
    let mut scratch = HuntStats::default();
    let mut changed = true;
    while changed && replays < SHRINK_REPLAYS {
        changed = false;
        let mut i = 0;
        while i < plan.segments.len() && replays < SHRINK_REPLAYS {
            let mut tries: Vec<Plan> = Vec::new();
            let mut without = plan.clone();
            without.segments.remove(i);
            tries.push(without);
            let d = plan.segments[i].1;
            if d > 1 {
                let mut half = plan.clone();
                half.segments[i].1 = d / 2;
                tries.push(half);
            }
            let mut took = false;
            for p in tries {
                replays += 1;
                let tail = best.inputs.len() * 2 + 16;
                if let Some(c) = play(program, atoms, &p, tail, &mut scratch, None) {
                    if c.inputs.len() < best.inputs.len() && violates(program, atoms, &c, f) {
                        plan = p;
                        best = c;
                        took = true;
                        changed = true;
                        break;
                    }
                }
            }
            if !took {
                i += 1;
            }
        }
    }
    best
}

/// Whether the lasso's scenario, replayed by the simulator, is a lasso that violates
/// property `t`.
fn confirmed(program: &Program, t: usize, c: &Closed) -> bool {
    let sc = from_lasso(program, &c.inputs, c.loop_start);
    let run = run_lasso(program, &sc, Options::default());
    run.broken.is_none() && run.fair && run.violated.iter().any(|n| *n == program.temporal[t].name)
}
