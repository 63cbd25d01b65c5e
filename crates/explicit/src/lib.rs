//! Explicit-state model checking on the IR.
//!
//! [`verify`] explores the closed system of a [`Program`] breadth-first from its initial state
//! (every slot at its `init`, before tick 0): the successors of a state are one tick of the IR
//! for every input vector within the inputs' ranges that satisfies the `assume`s. Visited states
//! are stored bit-packed ([`pack`]) in a sharded open-addressing set ([`table`]); layers are
//! expanded in parallel. Every property of the run is checked on every transition, in one
//! exploration; the first violation found of each is a shortest one. Counterexamples are
//! returned as the input vectors of each tick, ready for `statecheck_sim::scenario`.
//!
//! Properties that read only the state are checked once per newly found state (while it is
//! inserted), the others on every transition; `assume` conjuncts are solved up front (inputs
//! only), per state (state only) or per transition ([`InputSpace`]).
//!
//! Successors come from the IR's register code, or from the same program compiled to machine
//! code by a [`SuccessorCompiler`] that the caller plugs in ([`Options::compiler`], [`Backend`];
//! the `statecheck-native` crate provides one): the interpreter stays the reference that the
//! native code is compared against during the run.
//!
//! To keep the visited set small (no parent pointers), a counterexample is rebuilt after the
//! exploration by a second search, with parent links, up to the depth of the deepest violation,
//! within what is left of the time budget.

pub mod bitstate;
mod collapse;
mod error;
mod expand;
pub mod ltl;
mod native;
pub mod pack;
pub mod props;
mod reduce;
mod search;
pub mod successors;
mod symmetry;
pub mod table;
mod trace;

pub use error::{Error, ErrorKind};
pub use props::{PropKind, BUILTINS};
pub use statecheck_ir::assume::InputSpace;
pub use statecheck_ir::verdict::{PropResult, Verdict};
pub use successors::{CompiledSuccessors, SuccessorCompiler};

use expand::Expander;
use pack::{Key, Packer};
use search::{search, End, Limits};
use statecheck_ir::Program;
use std::time::Duration;

/// Above this many input vectors per tick, [`verify`] refuses unless [`Options::force`].
pub const DEFAULT_MAX_BRANCHING: u128 = 1_000_000;

/// Options of a run.
#[derive(Clone, Debug)]
pub struct Options {
    /// Properties to report (all when empty); the built-ins may be named too.
    pub properties: Vec<String>,
    /// Explore at most this many ticks.
    pub depth: Option<u64>,
    /// Stop with `unknown` when the estimated memory exceeds this many bytes.
    pub max_memory: Option<u64>,
    /// Stop with `unknown` after this many states.
    pub max_states: Option<u64>,
    /// Stop with `unknown` after this long.
    pub timeout: Option<Duration>,
    /// Worker threads (0: one per core).
    pub threads: usize,
    /// Explore even when the branching factor exceeds `max_branching`.
    pub force: bool,
    /// The branching factor above which the run is refused without `force`.
    pub max_branching: u128,
    /// How successors are computed.
    pub backend: Backend,
    /// With native successors, expand one state in this many (by position in its layer) with
    /// the interpreter too and compare; 0 never does (for tests of the native path alone).
    pub native_sample: u32,
    /// What builds native successor generators; without one, the interpreter computes every
    /// successor.
    pub compiler: Option<std::sync::Arc<dyn SuccessorCompiler>>,
    /// Step one input vector per combination of the inputs a tick can read from the state
    /// (`statecheck_ir::assume::InputReads`), not every vector: the same states, verdicts,
    /// counterexamples and transition counts, fewer ticks run (on by default).
    pub reduce_inputs: bool,
    /// Raised by another thread to end the run early (Ctrl-C, another engine answered): the
    /// search checks it between blocks and ends with [`Limit::Stopped`]; counterexamples
    /// already found are still rebuilt.
    pub stop: Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    /// Symmetry reduction (`verify --symmetry`): the interchangeable array elements found by
    /// `statecheck_ir::symmetry::detect`; the safety search then stores one state per orbit
    /// (state counts are orbits), with the interpreter's successors, and maps counterexamples
    /// back to concrete runs. Temporal properties are checked without it.
    pub symmetry: Option<std::sync::Arc<statecheck_ir::symmetry::Symmetry>>,
    /// Collapse compression of the visited set (docs/verification.md): states of more than
    /// 128 bits stored as the numbers of their halves' distinct values — the same states and
    /// results in less memory, at some cost in time.
    pub collapse: Collapse,
    /// Bitstate hashing (`verify --bitstate SIZE`, [`bitstate`]): a fixed bit array instead of
    /// the exact visited set, as SPIN's supertrace. Violations found are real; a search that
    /// runs out of states proves nothing (its other verdicts are `unknown`, with the expected
    /// omissions in [`Stats::bitstate`]). Collapse compression is then off.
    pub bitstate: Option<bitstate::Bitstate>,
}

/// When the explicit engine compresses its visited set ([`Options::collapse`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Collapse {
    /// Never (`verify --no-collapse`).
    Off,
    /// Once the plain set holds two fifths of the memory limit (the default): a search that
    /// fits stays as fast as without it, one that would not fit goes on compressed.
    #[default]
    Auto,
    /// From the start (`verify --collapse`).
    On,
}

/// How the explicit engine computes successors.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Backend {
    /// The interpreter; on a search still running after [`AUTO_NATIVE_AFTER`], the native
    /// generator is compiled in the background and used from the next block on.
    #[default]
    Auto,
    /// Always the IR's register-code interpreter.
    Interpreter,
    /// The native generator from the start (compiled before the search; the interpreter when
    /// no C compiler works, with a note).
    Native,
}

impl Backend {
    /// The option word: `auto`, `interpreter`, `native`.
    pub fn as_str(self) -> &'static str {
        match self {
            Backend::Auto => "auto",
            Backend::Interpreter => "interpreter",
            Backend::Native => "native",
        }
    }
}

/// With [`Backend::Auto`], a search still running after this long compiles the native
/// generator (smaller runs never pay for the compiler).
pub const AUTO_NATIVE_AFTER: Duration = Duration::from_millis(300);

impl Default for Options {
    fn default() -> Self {
        Options {
            properties: Vec::new(),
            depth: None,
            max_memory: None,
            max_states: None,
            timeout: None,
            threads: 0,
            force: false,
            max_branching: DEFAULT_MAX_BRANCHING,
            backend: Backend::Auto,
            native_sample: 64,
            compiler: None,
            reduce_inputs: true,
            stop: None,
            symmetry: None,
            collapse: Collapse::Auto,
            bitstate: None,
        }
    }
}

/// A limit that ended a run early.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Limit {
    /// The memory estimate exceeded this many bytes.
    Memory(u64),
    /// More states than this.
    States(u64),
    /// The run took longer than this.
    Time(Duration),
    /// The caller raised [`Options::stop`].
    Stopped,
    /// Too many input vectors per tick.
    Branching {
        /// Input vectors per tick.
        branching: u128,
        /// The threshold.
        max: u128,
    },
}

impl Limit {
    /// A short machine-readable name: `memory`, `states`, `time`, `branching`.
    pub fn name(&self) -> &'static str {
        match self {
            Limit::Memory(_) => "memory",
            Limit::States(_) => "states",
            Limit::Time(_) => "time",
            Limit::Stopped => "stopped",
            Limit::Branching { .. } => "branching",
        }
    }

    /// A sentence saying what was hit.
    pub fn describe(&self) -> String {
        match self {
            Limit::Memory(m) => format!("memory limit of {} reached", human_bytes(*m)),
            Limit::States(n) => format!("state limit of {n} reached"),
            Limit::Time(t) => format!("time limit of {:.1} s reached", t.as_secs_f64()),
            Limit::Stopped => "stopped on request".to_string(),
            Limit::Branching { branching, max } => format!(
                "branching factor {branching} exceeds {max} input vectors per tick; not explored (constrain the inputs with `assume`, or use --engine ic3)"
            ),
        }
    }
}

/// Format a byte count with a binary unit.
pub fn human_bytes(b: u64) -> String {
    const UNITS: [&str; 5] = ["B", "KiB", "MiB", "GiB", "TiB"];
    let mut v = b as f64;
    let mut u = 0;
    while v >= 1024.0 && u + 1 < UNITS.len() {
        v /= 1024.0;
        u += 1;
    }
    if u == 0 {
        format!("{b} B")
    } else {
        format!("{v:.1} {}", UNITS[u])
    }
}

/// Statistics of a run.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Distinct states stored (including the initial, pre-tick-0 state).
    pub states: u64,
    /// Transitions taken (input vectors satisfying the assumes, from every explored state).
    pub transitions: u64,
    /// Deepest layer reached, in ticks.
    pub depth: u64,
    /// Wall time of the exploration (without counterexample reconstruction).
    pub time: Duration,
    /// Wall time of counterexample reconstruction.
    pub cex_time: Duration,
    /// Largest memory estimate of the exploration.
    pub peak_memory_bytes: u64,
    /// Bytes of the visited set.
    pub table_bytes: u64,
    /// Input vectors per tick before `assume`s (saturating).
    pub branching: u128,
    /// Input vectors per tick allowed by the `assume` conjuncts that read only inputs (solved
    /// once, up front), when there are some; the others are evaluated per state or per
    /// transition.
    pub branching_after_assumes: Option<u128>,
    /// Worker threads.
    pub threads: usize,
    /// Bits of a packed state vector.
    pub state_bits: u32,
    /// True when every reachable state was explored.
    pub complete: bool,
    /// The limit that stopped the run, if any.
    pub limit: Option<Limit>,
    /// True when the run stopped because every property was decided.
    pub all_decided: bool,
    /// Coverage items never hit (indices into `Program::covers`), after a complete run.
    pub dead: Option<Vec<u32>>,
    /// What computed the successors: `interpreter`, or `native` when the native generator was
    /// used (from the start, or from some block on).
    pub backend: &'static str,
    /// Time to generate, compile (or find in the cache) and load the native generator.
    pub native_build_time: Option<Duration>,
    /// Why the native generator was not used, or was abandoned, when it was asked for.
    pub native_note: Option<String>,
    /// True when the search stored one state per orbit of interchangeable array elements
    /// ([`Options::symmetry`]): `states` then counts orbits.
    pub symmetry: bool,
    /// Why symmetry reduction was asked for but not used.
    pub symmetry_note: Option<String>,
    /// Under collapse compression ([`Options::collapse`]): the distinct values of the low and
    /// the high half of the state vector (each stored once). `None` without it, or when a
    /// state fits in 128 bits (then it is stored as it is).
    pub collapse_leaves: Option<Vec<u64>>,
    /// Under collapse compression: the states stored when it began (1: from the start; more
    /// when [`Collapse::Auto`] switched to it on the way).
    pub collapse_from: Option<u64>,
    /// Under bitstate hashing ([`Options::bitstate`]): the array's statistics. `complete` is
    /// then false even when the search ran out of states.
    pub bitstate: Option<bitstate::BitstateStats>,
}

impl Stats {
    /// States per second of exploration.
    pub fn states_per_s(&self) -> f64 {
        self.states as f64 / self.time.as_secs_f64().max(1e-9)
    }

    /// Bytes of the visited set per stored state.
    pub fn bytes_per_state(&self) -> f64 {
        self.table_bytes as f64 / (self.states.max(1)) as f64
    }
}

/// The outcome of [`verify`].
#[derive(Clone, Debug)]
pub struct Report {
    /// One result per checked property, the system's in declaration order, then built-ins.
    pub results: Vec<PropResult>,
    /// Statistics.
    pub stats: Stats,
}

/// Progress of a running exploration, reported after every block of states.
#[derive(Clone, Debug)]
pub struct Progress {
    /// The layer being expanded.
    pub depth: u64,
    /// States stored.
    pub states: u64,
    /// Transitions taken.
    pub transitions: u64,
    /// States in the layer being expanded.
    pub frontier: u64,
    /// Memory estimate.
    pub memory_bytes: u64,
    /// Time since the start.
    pub elapsed: Duration,
}

/// Verify `program`'s properties. Errs only on a bad option (an unknown property name, a
/// thread pool that cannot start).
pub fn verify(
    program: &Program,
    opts: &Options,
    progress: Option<&(dyn Fn(&Progress) + Sync)>,
) -> Result<Report, Error> {
    let (temporal, safety) = ltl::split(program, &opts.properties);
    let mut report = verify_safety(
        program,
        &Options {
            properties: safety.clone(),
            ..opts.clone()
        },
        progress,
        safety.is_empty() && !temporal.is_empty(),
    )?;
    if opts.properties.is_empty() || !temporal.is_empty() {
        let sel = (!opts.properties.is_empty()).then_some(temporal.as_slice());
        let (results, _) = ltl::check(program, sel, opts);
        report.results.extend(results);
    }
    Ok(report)
}

/// The safety part of [`verify`]: every non-temporal property selected (none when `none`).
fn verify_safety(
    program: &Program,
    opts: &Options,
    progress: Option<&(dyn Fn(&Progress) + Sync)>,
    none: bool,
) -> Result<Report, Error> {
    let start = std::time::Instant::now();
    let mut specs = if none {
        Vec::new()
    } else {
        props::select(program, &opts.properties)?
    };
    let mut init = statecheck_ir::Machine::new(program);
    props::mark_per_state(program, &mut specs, |c| expand::decides(&mut init, c));
    let mut space = InputSpace::new(program);
    space.solve_static(program);
    let packer = Packer::new(program);
    let threads = if opts.threads == 0 {
        std::thread::available_parallelism().map_or(1, usize::from)
    } else {
        opts.threads
    };
    let mut stats = Stats {
        branching: space.count,
        branching_after_assumes: space.effective(),
        threads,
        state_bits: packer.bits,
        ..Stats::default()
    };
    let branching = space.per_tick();
    let too_wide =
        branching > u128::from(u32::MAX) || (branching > opts.max_branching && !opts.force);
    if too_wide {
        let limit = Limit::Branching {
            branching,
            max: if opts.force {
                u128::from(u32::MAX)
            } else {
                opts.max_branching
            },
        };
        let results = specs
            .iter()
            .map(|s| PropResult {
                name: s.name.clone(),
                kind: s.kind,
                verdict: Verdict::Unknown,
                depth: 0,
                counterexample: None,
                error: None,
                note: None,
                loop_start: None,
            })
            .collect();
        stats.limit = Some(limit);
        return Ok(Report { results, stats });
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Error {
            kind: ErrorKind::Threads {
                threads,
                reason: e.to_string(),
            },
        })?;
    let canon = match opts
        .symmetry
        .as_deref()
        .map(|s| symmetry::Canon::new(program, s, &specs))
    {
        Some(Ok(c)) => c,
        Some(Err(why)) => {
            stats.symmetry_note = Some(why);
            None
        }
        None => None,
    };
    let canon = match canon {
        Some(c) => match c.validate(program, space.per_tick(), |i| space.vector(i), 8, 64) {
            Ok(()) => Some(c),
            Err(why) => {
                stats.symmetry_note = Some(format!("symmetry reduction off: {why}"));
                None
            }
        },
        None => None,
    };
    stats.symmetry = canon.is_some();
    // The native generator packs states itself, without the canonical form.
    let native = if canon.is_some() {
        None
    } else {
        prepare_native(program, &packer, &space, opts, &mut stats)
    };
    let started = std::sync::atomic::AtomicBool::new(opts.backend != Backend::Auto);
    // With `auto`, a search that is still running compiles the native generator.
    let watch = |pr: &Progress| {
        if let Some(n) = native.as_ref() {
            if pr.elapsed >= AUTO_NATIVE_AFTER
                && !started.swap(true, std::sync::atomic::Ordering::Relaxed)
            {
                if let Some(c) = opts.compiler.as_deref() {
                    n.build_in_background(native::Pending::new(c, program, &packer));
                }
            }
        }
        if let Some(f) = progress {
            f(pr);
        }
    };
    let reducer = opts
        .reduce_inputs
        .then(|| reduce::Reducer::new(per_transition_reads(&space, &specs)));
    let exp = Expander {
        program,
        packer: &packer,
        space: &space,
        specs: &specs,
        coverage: true,
        native: native.as_ref(),
        reduce: reducer.as_ref(),
        sym: canon.as_ref(),
    };
    let explore = |exp: &Expander, stats: Stats| {
        pool.install(|| {
            if packer.bits <= 31 {
                run::<u32>(exp, opts, start, stats, Some(&watch))
            } else if packer.bits <= 64 {
                run::<u64>(exp, opts, start, stats, Some(&watch))
            } else if packer.bits <= 127 {
                run::<u128>(exp, opts, start, stats, Some(&watch))
            } else if packer.bits < 192 {
                run::<[u64; 3]>(exp, opts, start, stats, Some(&watch))
            } else if packer.bits < 256 {
                run::<[u64; 4]>(exp, opts, start, stats, Some(&watch))
            } else if packer.bits < 384 {
                run::<[u64; 6]>(exp, opts, start, stats, Some(&watch))
            } else if packer.bits < 512 {
                run::<[u64; 8]>(exp, opts, start, stats, Some(&watch))
            } else {
                run::<Box<[u64]>>(exp, opts, start, stats, Some(&watch))
            }
        })
    };
    let mut report = explore(&exp, stats.clone());
    let Some(n) = native.as_ref() else {
        report.stats.backend = "interpreter";
        return Ok(report);
    };
    report.stats.backend = if n.ready().is_some() {
        "native"
    } else {
        "interpreter"
    };
    report.stats.native_build_time = n.ready().map(|g| g.build_time);
    if let Some(why) = n.failure() {
        report.stats.native_note = Some(why.to_string());
    }
    if let Some(what) = n.disagreement() {
        // A bug of the code generator or of this engine: the interpreter is the reference.
        let note = format!(
            "the native code disagreed with the interpreter ({what}); the run was repeated with the interpreter — please report this"
        );
        let exp = Expander {
            native: None,
            ..exp
        };
        report = explore(&exp, stats);
        report.stats.backend = "interpreter";
        report.stats.native_note = Some(note);
    }
    Ok(report)
}

/// What is evaluated on every transition besides the tick: the properties not checked per
/// state, and the assumes not solved up front (their inputs count as read in every state).
fn per_transition_reads(space: &InputSpace, specs: &[props::Spec]) -> Vec<statecheck_ir::ExprId> {
    let mut extra: Vec<_> = specs
        .iter()
        .filter(|s| !s.per_state)
        .flat_map(|s| s.check.exprs())
        .collect();
    extra.extend(&space.mixed_assumes);
    if space.listed().is_none() {
        extra.extend(&space.input_assumes);
    }
    extra
}

/// The native generator of a run, if `opts` asks for one: built now for [`Backend::Native`],
/// later (if the search runs long enough) for [`Backend::Auto`].
fn prepare_native(
    program: &Program,
    packer: &Packer,
    space: &InputSpace,
    opts: &Options,
    stats: &mut Stats,
) -> Option<native::NativeRun> {
    if opts.backend == Backend::Interpreter {
        return None;
    }
    let Some(compiler) = opts.compiler.as_deref() else {
        if opts.backend == Backend::Native {
            stats.native_note = Some("no native code generator was given".into());
        }
        return None;
    };
    let run = native::NativeRun::new(space, opts.native_sample);
    if opts.backend == Backend::Native {
        match &run {
            Some(n) => n.build_now(native::Pending::new(compiler, program, packer)),
            None => {
                stats.native_note = Some("too many input vectors to list for native code".into())
            }
        }
    }
    run
}

/// Under symmetry reduction: the canonical paths made concrete, and each family of element
/// properties answered together (a member decided makes every member decided, each with the
/// run that decides it).
fn symmetry_results<K: Key>(
    p: &Program,
    c: &symmetry::Canon,
    specs: &[props::Spec],
    found: &mut [Option<(u64, expand::Found<K>)>],
    traces: &mut [Result<Vec<Vec<i64>>, String>],
) {
    for path in traces.iter_mut().flatten() {
        *path = c.concretize(p, path);
    }
    for (g, fam) in &c.families {
        let Some(&j) = fam.iter().find(|&&q| found[q].is_some()) else {
            continue;
        };
        let (Some(first), first_tr) = (found[j].clone(), traces[j].clone()) else {
            continue;
        };
        for (k, &q) in fam.iter().enumerate() {
            // A member found itself keeps its own (shortest) run, else the first member's.
            let tr = match &found[q] {
                Some(_) => traces[q].clone(),
                None => first_tr.clone(),
            };
            let run = match &tr {
                Ok(run) => c.member_run(p, run, (*g, fam), k, specs).ok_or_else(|| {
                    "counterexample not rebuilt: no exchange of elements replays it (internal error)"
                        .to_string()
                }),
                Err(why) => Err(why.clone()),
            };
            if found[q].is_none() {
                let (layer, f) = first.clone();
                found[q] = Some((layer, expand::Found { prop: q, ..f }));
            }
            traces[q] = run;
        }
    }
}

/// Explore, then rebuild the counterexamples; `--timeout` counts from `start` and bounds both.
fn run<K: Key>(
    exp: &Expander,
    opts: &Options,
    start: std::time::Instant,
    mut stats: Stats,
    progress: Option<&(dyn Fn(&Progress) + Sync)>,
) -> Report {
    let limits = Limits {
        depth: opts.depth,
        max_memory: opts.max_memory,
        max_states: opts.max_states,
        timeout: opts.timeout,
        stop: opts.stop.clone(),
        collapse: opts.collapse,
        bitstate: opts.bitstate,
    };
    let s = search::<K>(exp, limits, None, progress);
    stats.collapse_leaves = s.collapse_leaves.clone();
    stats.collapse_from = s.collapse_from;
    stats.states = s.states;
    stats.transitions = s.transitions;
    stats.depth = s.depth;
    stats.time = s.elapsed;
    stats.peak_memory_bytes = s.peak_bytes;
    stats.table_bytes = s.table_bytes;
    // Under bitstate hashing, running out of states is not exhausting them (omissions).
    stats.complete = s.end == End::Complete && s.bitstate.is_none();
    stats.bitstate = s.bitstate.clone();
    stats.all_decided = s.end == End::AllDecided;
    if let End::Limit(l) = &s.end {
        stats.limit = Some(l.clone());
    }
    if stats.complete {
        stats.dead = s.covered.as_ref().map(|c| {
            c.iter()
                .enumerate()
                .filter(|(_, hit)| !**hit)
                .map(|(i, _)| i as u32)
                .collect()
        });
    }
    let cex_start = std::time::Instant::now();
    // What is left of the time budget bounds the reconstruction too.
    let budget = opts.timeout.map(|t| t.saturating_sub(start.elapsed()));
    let mut traces = trace::rebuild::<K>(exp, &s.found, opts.max_memory, budget);
    let mut found = s.found;
    if let Some(c) = exp.sym {
        symmetry_results(exp.program, c, exp.specs, &mut found, &mut traces);
    }
    stats.cex_time = cex_start.elapsed();
    let results = exp
        .specs
        .iter()
        .zip(found)
        .zip(traces)
        .map(|((spec, found), tr)| {
            let reach = spec.kind == PropKind::Reachable;
            match found {
                Some((layer, f)) => {
                    let (counterexample, note) = match tr {
                        Ok(c) => (Some(c), None),
                        Err(why) => (None, Some(why)),
                    };
                    // After a bitstate search the rebuilt run may be shorter than the layer
                    // the violation was found from (`trace::rebuild`).
                    let depth = counterexample
                        .as_ref()
                        .map_or(layer + 1, |c| c.len() as u64);
                    PropResult {
                        name: spec.name.clone(),
                        kind: spec.kind,
                        verdict: if reach {
                            Verdict::Reachable
                        } else {
                            Verdict::Violated
                        },
                        depth,
                        counterexample,
                        error: f.error,
                        note,
                        loop_start: None,
                    }
                }
                None => {
                    let verdict = match &s.end {
                        End::Complete | End::Depth if s.bitstate.is_some() => Verdict::Unknown,
                        End::Complete => {
                            if reach {
                                Verdict::Unreachable
                            } else {
                                Verdict::Proved
                            }
                        }
                        End::Depth => Verdict::Bounded,
                        End::AllDecided | End::Limit(_) => Verdict::Unknown,
                    };
                    let note = s.bitstate.as_ref().filter(|_| verdict == Verdict::Unknown).map(|b| {
                        format!(
                            "bitstate search: not refuted in {} states to depth {}; not a proof ({} states omitted)",
                            s.states, s.depth, bitstate::about(b.expected_omitted)
                        )
                    });
                    PropResult {
                        name: spec.name.clone(),
                        kind: spec.kind,
                        verdict,
                        depth: s.depth,
                        counterexample: None,
                        error: None,
                        note,
                        loop_start: None,
                    }
                }
            }
        })
        .collect();
    Report { results, stats }
}
