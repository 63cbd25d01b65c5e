//! Running an engine on a program's properties, with answers in the explicit engine's terms
//! (verdicts, counterexamples as input vectors), so that both engines share one report.

use crate::aig::Aig;
use crate::blast::{blast, Blasted, SharedProblem};
use crate::engine::{Invariant, Limits, Outcome, Trace};
use crate::ic3::Ic3Frames;
use crate::scorr::{Reduction, SPURIOUS};
use statecheck_ir::verdict::{self, PropKind, PropResult, Verdict};
use statecheck_ir::{Machine, Program};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

/// A SAT-based engine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Bounded model checking.
    Bmc,
    /// k-induction.
    Kind,
    /// IC3/PDR.
    Ic3,
    /// IC3 on a localization abstraction refined by counterexamples ([`crate::localize`]).
    Cegar,
}

impl Engine {
    /// The name used on the command line and in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Engine::Bmc => "bmc",
            Engine::Kind => "kind",
            Engine::Ic3 => "ic3",
            Engine::Cegar => "cegar",
        }
    }

    /// Run on a one-property circuit.
    pub fn run(self, aig: &crate::aig::Aig, limits: &Limits) -> Outcome {
        crate::sat::with_limits(limits, || match self {
            Engine::Bmc => crate::bmc::bmc(aig, limits),
            Engine::Kind => crate::kind::kind(aig, limits),
            Engine::Ic3 => crate::ic3::ic3(aig, limits),
            Engine::Cegar => crate::localize::cegar(aig, limits),
        })
    }
}

/// How long IC3 and k-induction try the circuit as blasted before it is reduced by signal
/// correspondence ([`crate::scorr`]): most properties are decided well within it, and the
/// reduction costs seconds on a large circuit.
pub const QUICK: Duration = Duration::from_secs(1);

/// Reductions of a run's problems, computed at most once each and shared by the engines.
#[derive(Debug, Default)]
pub struct Reductions {
    /// One per problem, then one for the shared problem.
    slots: Vec<Mutex<Option<Option<Arc<Reduction>>>>>,
    /// The problem shared by the program's own properties, built on first use.
    shared: OnceLock<SharedProblem>,
    /// Clauses of the invariants IC3 proved on the shared problem's reduction (over its
    /// latches): facts of every reachable state, which later proofs start from.
    lemmas: Mutex<Invariant>,
    /// Per bad output of the shared problem's reduction: the frames of IC3's last attempt on
    /// it that a limit stopped, from which its next attempt resumes.
    ic3_frames: Mutex<HashMap<usize, Ic3Frames>>,
    /// Per property: its retimed problem and what localization has refined on it
    /// ([`crate::localize::cegar_reducing`]), kept between attempts.
    retimed: Mutex<HashMap<usize, Retimed>>,
}

/// A property's retimed problem (with the [`Blasted::aig`] latch of each of its latches,
/// `None` for the added `stepped` latch) and localization's progress on it.
type Retimed = (Arc<(Aig, Vec<Option<usize>>)>, crate::localize::Progress);

/// The most lemma clauses kept for later proofs (beyond it, new invariants are not added:
/// every frame of every later IC3 run carries them).
const MAX_LEMMAS: usize = 4000;

impl Reductions {
    /// Room for `n` problems (and the shared one).
    pub fn new(n: usize) -> Reductions {
        Reductions {
            slots: (0..=n).map(|_| Mutex::new(None)).collect(),
            shared: OnceLock::new(),
            lemmas: Mutex::new(Vec::new()),
            ic3_frames: Mutex::new(HashMap::new()),
            retimed: Mutex::new(HashMap::new()),
        }
    }

    /// Localization on property `prop`'s retimed problem ([`Blasted::retimed_problem`]),
    /// resumed from its last attempt; `None` when the property has no retimed form. The
    /// answer is read on the original problem: a counterexample loses the retimed problem's
    /// last frame; a proof is believed only when its invariant checks on the retimed problem,
    /// and comes with a certificate of the original problem when [`original_invariant`]
    /// finds one.
    fn cegar_retimed(
        &self,
        bl: &Blasted,
        prop: usize,
        limits: &Limits,
    ) -> Option<(Outcome, Option<(Aig, Invariant)>)> {
        let taken = self
            .retimed
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .remove(&prop);
        let (problem, mut progress) = match taken {
            Some(x) => x,
            None => (Arc::new(bl.retimed_problem(prop)?), Default::default()),
        };
        let (aig, origin) = &*problem;
        let (out, _) = crate::sat::with_limits(limits, || {
            crate::localize::cegar_reducing(aig, limits, &mut progress)
        });
        let mut cert = None;
        let out = match out {
            Outcome::Reached(t) => Outcome::Reached(crate::blast::retimed_trace(t)),
            Outcome::Proved(Some(inv)) => match crate::cert::check(aig, &inv) {
                Ok(()) => {
                    cert = original_invariant(bl, prop, &inv, origin);
                    Outcome::Proved(None)
                }
                Err(e) => {
                    Outcome::unknown(format!("the localization invariant does not check: {e}"))
                }
            },
            // The retimed problem's frames are one more than the original's.
            Outcome::Unknown { why, cleared } => {
                Outcome::unknown_after(why, cleared.saturating_sub(1))
            }
            out => out,
        };
        if matches!(out, Outcome::Unknown { .. }) {
            self.retimed
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .insert(prop, (problem, progress));
        }
        Some((out, cert))
    }

    /// Whether problem `i`'s reduction is computed (and useful): then the engines go to it
    /// at once, without a quick attempt on the circuit as blasted.
    fn ready(&self, i: usize) -> bool {
        self.slots.get(i).is_some_and(|slot| {
            slot.try_lock()
                .is_ok_and(|g| g.as_ref().is_some_and(Option::is_some))
        })
    }

    /// Whether the shared problem's reduction is computed.
    fn shared_ready(&self) -> bool {
        self.slots
            .len()
            .checked_sub(1)
            .is_some_and(|l| self.ready(l))
    }

    /// The lemmas for the next proof on the shared reduction.
    fn lemmas(&self) -> Invariant {
        self.lemmas
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// The frames IC3 left on the shared reduction's bad output `k` (empty if none).
    fn take_frames(&self, k: usize) -> Ic3Frames {
        let mut g = self.ic3_frames.lock().unwrap_or_else(|e| e.into_inner());
        g.remove(&k).unwrap_or_default()
    }

    /// Keep `frames` for IC3's next attempt on the shared reduction's bad output `k`.
    fn keep_frames(&self, k: usize, frames: Ic3Frames) {
        if frames.depth() > 0 {
            let mut g = self.ic3_frames.lock().unwrap_or_else(|e| e.into_inner());
            g.insert(k, frames);
        }
    }

    /// Keep the clauses of `inv` (an invariant proved on the shared reduction, which ends with
    /// the lemmas it was given) for later proofs: the clauses not yet
    /// kept, while they fit under [`MAX_LEMMAS`].
    fn learn(&self, inv: &Invariant) {
        let mut l = self.lemmas.lock().unwrap_or_else(|e| e.into_inner());
        let known: std::collections::HashSet<&Vec<(usize, bool)>> = l.iter().collect();
        let add: Vec<Vec<(usize, bool)>> =
            inv.iter().filter(|c| !known.contains(c)).cloned().collect();
        if l.len() + add.len() <= MAX_LEMMAS {
            l.extend(add);
        }
    }

    /// The reduction of problem `i` (circuit `aig`), computed on first use under the run's
    /// limits; `None` when it was stopped (it is tried again next time) or removes nothing.
    pub fn get(&self, i: usize, aig: &Aig, limits: &Limits) -> Option<Arc<Reduction>> {
        let slot = self.slots.get(i)?;
        // A poisoned lock only means another engine's thread panicked: the data is intact.
        let mut g = slot.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(r) = g.as_ref() {
            return r.clone();
        }
        let run = limits.for_run();
        match crate::sat::with_limits(&run, || crate::scorr::reduce(aig, &run)) {
            Ok(r) => {
                let useful = r.stats.merged > 0 || r.stats.latches.1 < r.stats.latches.0;
                let r = useful.then(|| Arc::new(r));
                *g = Some(r.clone());
                r
            }
            Err(_) => None,
        }
    }

    /// The problem shared by `bl`'s own properties.
    fn shared(&self, bl: &Blasted) -> &SharedProblem {
        self.shared.get_or_init(|| bl.shared_problem())
    }

    /// The reduction of the shared problem, narrowed to its bad output `k`.
    fn get_shared(&self, bl: &Blasted, k: usize, limits: &Limits) -> Option<Arc<Reduction>> {
        let last = self.slots.len().checked_sub(1)?;
        let red = self.get(last, &self.shared(bl).aig, limits)?;
        Some(Arc::new(red.with_bad(k)))
    }
}

/// Run IC3 or k-induction on problem `i`: first on the circuit as blasted for [`QUICK`], then
/// on its reduction by signal correspondence (when the first attempt did not decide), falling
/// back to the blasted circuit if a counterexample of the reduced one does not replay.
/// BMC always runs on the blasted circuit (its counterexamples are found frame by frame, and
/// the reduction would only delay them).
pub fn run_reduced(
    engine: Engine,
    aig: &Aig,
    i: usize,
    reductions: &Reductions,
    limits: &Limits,
) -> Outcome {
    let ready = reductions.ready(i);
    run_with(engine, aig, limits, ready, None, || {
        reductions.get(i, aig, limits)
    })
}

/// [`run_reduced`], with the reduction of `aig` from `reduction`: tried at once when it is
/// `ready` (computed by an earlier attempt: the quick attempt on the circuit as blasted
/// would only repeat what that attempt did), and, with `lemmas` (a store and the shared
/// problem's bad output `k`), with IC3 on it given the store's clauses and adding its own
/// invariant to them, and resuming from the frames of its last attempt on `k`.
fn run_with(
    engine: Engine,
    aig: &Aig,
    limits: &Limits,
    ready: bool,
    lemmas: Option<(&Reductions, usize)>,
    reduction: impl FnOnce() -> Option<Arc<Reduction>>,
) -> Outcome {
    if engine == Engine::Bmc {
        return engine.run(aig, limits);
    }
    // Localization waits for the reduction: on the circuit as blasted a bad output reads
    // most latches (`crate::localize`), so its quick attempt would be IC3's again.
    if !ready && engine != Engine::Cegar {
        let quick = engine.run(aig, &limits.attempt_until(Instant::now() + QUICK));
        if !matches!(quick, Outcome::Unknown { .. }) || limits.expired().is_some() {
            return quick;
        }
    }
    // The reduction is computed once for all properties and attempts (to the run's end, not
    // this attempt's): the attempt's budget counts from when it is there, or the attempt
    // that pays for it would end as soon as it starts.
    let asked = Instant::now();
    let red = reduction();
    let waited = asked.elapsed();
    let limits = &match limits.attempt_deadline {
        Some(d) if waited > Duration::ZERO => Limits {
            attempt_deadline: Some(limits.deadline.map_or(d + waited, |r| r.min(d + waited))),
            ..limits.clone()
        },
        _ => limits.clone(),
    };
    let Some(red) = red else {
        return engine.run(aig, limits);
    };
    let out = match (engine, lemmas) {
        (Engine::Ic3, Some((store, k))) => {
            let given = store.lemmas();
            let mut frames = store.take_frames(k);
            let out = crate::sat::with_limits(limits, || {
                crate::ic3::ic3_resume(&red.aig, limits, &given, &mut frames)
            });
            store.keep_frames(k, frames);
            if let Outcome::Proved(Some(inv)) = &out {
                store.learn(inv);
            }
            out
        }
        (Engine::Cegar, Some((store, _))) => {
            let given = store.lemmas();
            let (out, _) = crate::sat::with_limits(limits, || {
                crate::localize::cegar_with_lemmas(&red.aig, limits, &given)
            });
            if let Outcome::Proved(Some(inv)) = &out {
                store.learn(inv);
            }
            out
        }
        _ => engine.run(&red.aig, limits),
    };
    match red.lift(aig, out) {
        Outcome::Unknown { why, .. } if why == SPURIOUS => engine.run(aig, limits),
        out => out,
    }
}

/// Decide property `prop` of `bl` with `engine`: an own property on the shared problem (whose
/// one reduction serves them all), a built-in on its own problem. An invariant is returned
/// over the latches of [`Blasted::problem`] (what `--check-certificate` and `export aiger`
/// number), and only when it checks there.
fn run_property(
    bl: &Blasted,
    prop: usize,
    engine: Engine,
    limits: &Limits,
    reductions: &Reductions,
) -> (Outcome, Option<(Aig, Invariant)>) {
    let shared = reductions.shared(bl);
    let Some(k) = shared.bad_index.get(prop).copied().flatten() else {
        let aig = bl.problem(prop);
        if engine == Engine::Cegar {
            // A built-in's bad output is the step's error, which has no form on the state:
            // localization would keep most of the circuit, and waiting for the whole
            // circuit's reduction here would hold up the own properties (minutes on master +
            // 3..5 FAMs). IC3 on the circuit as blasted, within the attempt's budget; IC3
            // and k-induction take the reduced one.
            return match engine_ic3_blasted(&aig, limits) {
                Outcome::Proved(Some(inv)) => (Outcome::Proved(None), Some((aig, inv))),
                out => (out, None),
            };
        }
        return match run_reduced(engine, &aig, prop, reductions, limits) {
            Outcome::Proved(Some(inv)) => (Outcome::Proved(None), Some((aig, inv))),
            out => (out, None),
        };
    };
    if engine == Engine::Cegar {
        if let Some(answer) = reductions.cegar_retimed(bl, prop, limits) {
            return answer;
        }
    }
    let aig = shared.with_bad(k);
    let ready = reductions.shared_ready();
    match run_with(engine, &aig, limits, ready, Some((reductions, k)), || {
        reductions.get_shared(bl, k, limits)
    }) {
        Outcome::Proved(Some(inv)) => {
            let (own, kept) = bl.problem_with_latches(prop);

            let inv = renumber(&inv, &shared.latch_origin, &kept);
            let cert = crate::cert::check(&own, &inv).is_ok().then_some((own, inv));
            (Outcome::Proved(None), cert)
        }
        out => (out, None),
    }
}

/// IC3 on a circuit as blasted (no reduction).
fn engine_ic3_blasted(aig: &Aig, limits: &Limits) -> Outcome {
    Engine::Ic3.run(aig, limits)
}

/// A certificate of property `prop`'s original problem ([`Blasted::problem`]) from `inv`, an
/// inductive invariant of its retimed problem (latches numbered by `origin`, `None` for
/// `stepped`), when there is one: `inv` with `stepped` true. Its consecution and safety on
/// the original problem follow from the retimed problem's consecution (a tick from a state of
/// it reaches one with `stepped` true, which is not bad); it holds initially when the reset
/// state, read as a state after a tick, satisfies it. The result is checked; `None` if it
/// fails.
fn original_invariant(
    bl: &Blasted,
    prop: usize,
    inv: &Invariant,
    origin: &[Option<usize>],
) -> Option<(Aig, Invariant)> {
    let stepped = origin.iter().position(Option::is_none);
    let after_a_tick: Invariant = inv
        .iter()
        .filter(|c| !c.iter().any(|&(j, v)| Some(j) == stepped && v))
        .map(|c| {
            c.iter()
                .copied()
                .filter(|&(j, _)| Some(j) != stepped)
                .collect()
        })
        .collect();
    let from: Vec<usize> = origin.iter().map(|o| o.unwrap_or(usize::MAX)).collect();
    let (own, kept) = bl.problem_with_latches(prop);
    let inv = renumber(&after_a_tick, &from, &kept);
    crate::cert::check(&own, &inv).is_ok().then_some((own, inv))
}

/// An invariant over latches numbered by `from` (index in a base circuit of each latch) over
/// latches numbered by `to`, without the clauses that mention a latch `to` lacks (facts about
/// other properties' latches; the caller checks that the rest is still an invariant).
fn renumber(inv: &Invariant, from: &[usize], to: &[usize]) -> Invariant {
    let mut base_to = std::collections::HashMap::with_capacity(to.len());
    for (j, &b) in to.iter().enumerate() {
        base_to.insert(b, j);
    }
    inv.iter()
        .filter_map(|c| {
            c.iter()
                .map(|&(j, v)| Some((*base_to.get(from.get(j)?)?, v)))
                .collect()
        })
        .collect()
}

/// The answer for one property.
#[derive(Clone, Debug)]
pub struct SymResult {
    /// The verdict, in the explicit engine's terms.
    pub result: PropResult,
    /// The inductive invariant of a proof by IC3, with the circuit it is about.
    pub invariant: Option<(crate::aig::Aig, Invariant)>,
    /// Time spent on this property.
    pub time: Duration,
    /// Why the verdict is `unknown`, if it is.
    pub reason: Option<String>,
}

/// The circuit of each selected property (`Err`: an unknown property name).
pub fn problems(
    p: &Program,
    names: &[String],
) -> Result<(Blasted, Vec<(usize, PropKind)>), verdict::UnknownProperty> {
    let specs = verdict::select(p, names)?;
    let bl = blast(p);
    // By name through a map: a linear search per property was quadratic, seconds for 10^4
    // properties before any engine started (and so past `--timeout`).
    let by_name: std::collections::BTreeMap<&str, usize> = bl
        .props
        .iter()
        .enumerate()
        .rev()
        .map(|(i, x)| (x.name.as_str(), i))
        .collect();
    let idx = specs
        .iter()
        .map(|s| (by_name.get(s.name.as_str()).copied().unwrap_or(0), s.kind))
        .collect();
    Ok((bl, idx))
}

/// Decide property `prop` (index into `bl.props`) of `p` with `engine` (IC3 and k-induction
/// through [`run_reduced`], with `reductions` indexed like `bl.props`).
pub fn decide(
    p: &Program,
    bl: &Blasted,
    prop: usize,
    kind: PropKind,
    engine: Engine,
    limits: &Limits,
    reductions: &Reductions,
) -> SymResult {
    let start = Instant::now();
    let (out, invariant) = run_property(bl, prop, engine, limits, reductions);
    sym_result(p, bl, prop, kind, out, invariant, start)
}

/// BMC on several own properties of `bl` at once (`props`: index into `bl.props` and kind;
/// built-ins are skipped, each has its own constraint): one unrolling of the shared problem
/// ([`crate::bmc::bmc_many`]), so the witnesses of all of them cost the deepest one's
/// unrolling. `open(n)` says whether `props[n]` is still wanted (asked before every query),
/// `stop_of(n)` gives the flag that abandons a running query on it, `cleared(n, k)` is told
/// each time no trace of at most `k` ticks decides it, and `found(n, result)` gets each
/// shortest counterexample or witness as it is found.
#[allow(clippy::too_many_arguments)] // reason: the program, its circuit, the selection, limits and four callbacks are all needed; a struct for one call site would only rename them
pub fn bmc_shared(
    p: &Program,
    bl: &Blasted,
    reductions: &Reductions,
    props: &[(usize, PropKind)],
    limits: &Limits,
    open: &dyn Fn(usize) -> bool,
    stop_of: &dyn Fn(usize) -> Option<Arc<std::sync::atomic::AtomicBool>>,
    cleared: &dyn Fn(usize, usize),
    found: &mut dyn FnMut(usize, SymResult),
) -> crate::bmc::ManyEnd {
    let start = Instant::now();
    let shared = reductions.shared(bl);
    // Bad output j of the circuit below watches props[which[j]].
    let mut which = Vec::new();
    let mut g = shared.aig.clone();
    g.bad.clear();
    g.bad_names.clear();
    for (n, &(prop, _)) in props.iter().enumerate() {
        if let Some(k) = shared.bad_index.get(prop).copied().flatten() {
            which.push(n);
            g.bad.push(shared.aig.bad[k]);
            g.bad_names
                .push(shared.aig.bad_names.get(k).cloned().flatten());
        }
    }
    crate::sat::with_limits(limits, || {
        crate::bmc::bmc_many(
            &g,
            limits,
            &|j| open(which[j]),
            &|j| stop_of(which[j]),
            &|j, k| cleared(which[j], k),
            &mut |j, t| {
                let n = which[j];
                let (prop, kind) = props[n];
                let r = sym_result(p, bl, prop, kind, Outcome::Reached(t), None, start);
                found(n, r);
            },
        )
    })
}

/// The answer `out` of an engine for property `prop`, in the explicit engine's terms.
fn sym_result(
    p: &Program,
    bl: &Blasted,
    prop: usize,
    kind: PropKind,
    out: Outcome,
    invariant: Option<(Aig, Invariant)>,
    start: Instant,
) -> SymResult {
    let sig = &bl.props[prop];
    let reach = sig.reachable;
    let mut r = PropResult {
        name: sig.name.clone(),
        kind,
        verdict: Verdict::Unknown,
        depth: 0,
        counterexample: None,
        error: None,
        note: None,
        loop_start: None,
    };
    let mut reason = None;
    match out {
        Outcome::Reached(t) => {
            let vectors = input_vectors(bl, &t);
            r.verdict = if reach {
                Verdict::Reachable
            } else {
                Verdict::Violated
            };
            r.depth = vectors.len() as u64;
            r.error = replay_error(p, &vectors);
            r.counterexample = Some(vectors);
        }
        Outcome::Proved(_) => {
            r.verdict = if reach {
                Verdict::Unreachable
            } else {
                Verdict::Proved
            };
        }
        Outcome::Bounded(k) => {
            r.verdict = Verdict::Bounded;
            r.depth = k as u64;
        }
        Outcome::Unknown { why, cleared } => {
            r.depth = cleared as u64;
            reason = Some(why);
        }
    }
    SymResult {
        result: r,
        invariant,
        time: start.elapsed(),
        reason,
    }
}

/// The input vectors (in `Program::inputs` order) of a trace of one of `bl`'s problems (they
/// keep every input, in order).
pub fn input_vectors(bl: &Blasted, t: &Trace) -> Vec<Vec<i64>> {
    let aig = &bl.aig;
    t.inputs
        .iter()
        .map(|frame| {
            bl.inputs
                .iter()
                .map(|enc| {
                    let bits: Vec<bool> = enc
                        .bits
                        .iter()
                        .map(|b| frame[aig.nodes[b.var() as usize].input_index()])
                        .collect();
                    enc.decode(&bits)
                })
                .collect()
        })
        .collect()
}

/// The run-time error the last tick of `vectors` ends with, if any.
fn replay_error(p: &Program, vectors: &[Vec<i64>]) -> Option<statecheck_ir::RuntimeError> {
    let mut m = Machine::new(p);
    for v in vectors {
        for (k, inp) in p.inputs.iter().enumerate() {
            m.set(inp.slot, v[k]);
        }
        if let Err(e) = m.step() {
            return Some(e);
        }
    }
    None
}
