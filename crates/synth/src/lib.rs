//! Supervisory controller synthesis (Ramadge–Wonham) for statecheck.
//!
//! A `system` of `plant chart`s and `requirement chart`s (flat event-level automata whose
//! events are `controllable` or `uncontrollable`, with `marked` states) plus state-based
//! requirements (`requirement never (…)`, `requirement e needs (…)`) is read by
//! [`extract::extract`] into a [`Problem`]. [`synthesize`] computes the maximally permissive,
//! controllable, nonblocking supervisor with the [`Engine::Explicit`] or
//! [`Engine::Symbolic`] (BDD) engine; the result is a set of simplified guards on the
//! controllable events ([`Supervisor::guards`]), which [`emit::emit`] turns into a `.sc`
//! system that the simulator runs and the checkers verify. [`check::check`] verifies any such
//! supervisor against the plant in the tick semantics; it shares no code with the fixpoints.
//! See `docs/synthesis.md`.

pub mod build;
pub mod check;
pub mod emit;
pub mod encode;
pub mod error;
pub mod explain;
pub mod explicit;
pub mod extract;
pub mod families;
pub mod guards;
pub mod limits;
pub mod order;
pub mod problem;
pub mod supremica;
pub mod symbolic;

pub use encode::Formula;
pub use error::{Error, ErrorKind, Limit, Partial};
pub use limits::{Budget, Limits};
pub use problem::{EventId, Kind, Problem};

use biodivine_lib_bdd::Bdd;

/// Which synthesis engine to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Fixpoint over the explicitly enumerated reachable product.
    Explicit,
    /// Fixpoint over BDDs (for large products).
    Symbolic,
    /// Choose: see [`AUTO_EXPLICIT_ALONE`] and [`synthesize_with`].
    Auto,
}

impl Engine {
    /// The engine's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Engine::Explicit => "explicit",
            Engine::Symbolic => "symbolic",
            Engine::Auto => "auto",
        }
    }
}

impl std::str::FromStr for Engine {
    type Err = Error;
    fn from_str(s: &str) -> Result<Engine, Error> {
        match s {
            "explicit" => Ok(Engine::Explicit),
            "symbolic" | "bdd" => Ok(Engine::Symbolic),
            "auto" => Ok(Engine::Auto),
            _ => Err(Error::new(ErrorKind::Engine(s.to_string()))),
        }
    }
}

/// `auto` runs the explicit engine alone when the Cartesian product of the automata has at
/// most this many states (it cannot lose much there); otherwise it races both engines on two
/// threads and takes the first answer, stopping the other.
pub const AUTO_EXPLICIT_ALONE: f64 = 1e5;

/// How to run [`synthesize_with`].
#[derive(Clone, Debug)]
pub struct Options {
    /// The engine.
    pub engine: Engine,
    /// Limits (state count, memory, time, stop flag).
    pub limits: Limits,
    /// Build the guards (needed to print or emit the supervisor; skipped otherwise).
    pub guards: bool,
    /// Threads the explicit engine explores on: 1, or 2 and more for its two-thread pipeline
    /// (the same result; docs/synthesis.md, "Engines"). In `auto`'s race the explicit engine
    /// has one thread, the symbolic engine the other.
    pub threads: usize,
}

/// A guard on one controllable event.
#[derive(Clone, Debug)]
pub struct Guard {
    /// The event.
    pub event: EventId,
    /// Where the supervisor allows it (only meaningful where the plant enables it, in states
    /// of the controlled behaviour).
    pub allow: Formula,
}

/// A nonempty supervisor.
#[derive(Clone, Debug)]
pub struct Supervisor {
    /// States of the controlled behaviour (reachable product states kept by the supervisor).
    pub states: u128,
    /// Its transitions.
    pub transitions: u128,
    /// One guard per controllable event, in event order; empty when guards were not asked
    /// for ([`Options::guards`]).
    pub guards: Vec<Guard>,
}

/// What synthesis found.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// The maximally permissive controllable nonblocking supervisor.
    Supervisor(Supervisor),
    /// No supervisor exists; the text says why, with a witness trace.
    Empty(String),
}

/// Synthesis results with figures.
#[derive(Clone, Debug)]
pub struct Synthesis {
    /// The engine that produced the answer (never [`Engine::Auto`]).
    pub engine: Engine,
    /// Supervisor or reason for its absence.
    pub outcome: Outcome,
    /// Reachable states of the product of plants and requirements (requirement-allowed
    /// moves; `never` states reached but not expanded); the same figure from both engines.
    pub product_states: f64,
    /// Fixpoint rounds (controllability and nonblocking) until stable.
    pub rounds: usize,
}

/// Run synthesis with guards and no limits.
pub fn synthesize(p: &Problem, engine: Engine) -> Result<Synthesis, Error> {
    synthesize_with(
        p,
        &Options {
            engine,
            limits: Limits::default(),
            guards: true,
            threads: 1,
        },
    )
}

/// Run synthesis. `Err` when a limit stops the engine (with the figures reached).
pub fn synthesize_with(p: &Problem, o: &Options) -> Result<Synthesis, Error> {
    match o.engine {
        Engine::Explicit => run_explicit(p, o),
        Engine::Symbolic => run_symbolic(p, o),
        Engine::Auto if p.product_size() <= AUTO_EXPLICIT_ALONE => run_explicit(p, o),
        Engine::Auto => race(p, o),
    }
}

/// Both engines on two threads; the first answer wins and the other is stopped. A limit
/// (other than the stop) hit by one engine stops the race only when the other fails too.
fn race(p: &Problem, o: &Options) -> Result<Synthesis, Error> {
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::{mpsc, Arc};
    let stop = Arc::new(AtomicBool::new(false));
    let outer = o.limits.stop.clone();
    let (tx, rx) = mpsc::channel();
    std::thread::scope(|scope| {
        for engine in [Engine::Symbolic, Engine::Explicit] {
            let tx = tx.clone();
            let mut o = o.clone();
            o.engine = engine;
            o.threads = 1;
            let mine = stop.clone();
            let outer = outer.clone();
            o.limits.stop = Some(mine.clone());
            // The caller's stop flag is relayed to both engines by the waiting loop below.
            scope.spawn(move || {
                let r = synthesize_with(p, &o);
                let _ = tx.send(r);
                drop(outer);
            });
        }
        drop(tx);
        let mut first_err = None;
        loop {
            match rx.recv_timeout(std::time::Duration::from_millis(20)) {
                Ok(Ok(s)) => {
                    stop.store(true, Ordering::Relaxed);
                    return Ok(s);
                }
                Ok(Err(e)) => {
                    if first_err.is_some() {
                        return Err(first_err.unwrap_or(e));
                    }
                    first_err = Some(e);
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {
                    if outer.as_ref().is_some_and(|s| s.load(Ordering::Relaxed)) {
                        stop.store(true, Ordering::Relaxed);
                    }
                }
                Err(mpsc::RecvTimeoutError::Disconnected) => {
                    return Err(first_err.unwrap_or_else(|| {
                        Error::supervisor("both engines ended without an answer")
                    }));
                }
            }
        }
    })
}

fn run_explicit(p: &Problem, o: &Options) -> Result<Synthesis, Error> {
    let budget = Budget::new(&o.limits);
    let x = explicit::run_on(p, &budget, o.threads)?;
    let outcome = if x.size() == 0 {
        Outcome::Empty(explain::why_empty(p))
    } else {
        let guards = if o.guards {
            budget.check("guards", x.product_states as f64, 0)?;
            guards::explicit_guards(p, &x, &encode::Encoding::new(p), &budget)?
        } else {
            Vec::new()
        };
        Outcome::Supervisor(Supervisor {
            states: x.size() as u128,
            transitions: x.transitions() as u128,
            guards,
        })
    };
    Ok(Synthesis {
        engine: Engine::Explicit,
        outcome,
        product_states: x.product_states as f64,
        rounds: x.rounds,
    })
}

fn run_symbolic(p: &Problem, o: &Options) -> Result<Synthesis, Error> {
    let budget = Budget::new(&o.limits);
    let s = symbolic::run(p, &budget)?;
    let product_states = s.product.cardinality();
    if s.reach.is_false() {
        return Ok(Synthesis {
            engine: Engine::Symbolic,
            outcome: Outcome::Empty(explain::why_empty(p)),
            product_states,
            rounds: s.rounds,
        });
    }
    let allowed = symbolic::allowed_sets(p, &s);
    let transitions: u128 = allowed.iter().map(count).sum();
    let mut guards = Vec::new();
    if o.guards {
        for (e, on) in allowed.iter().enumerate() {
            if !p.events[e].controllable {
                continue;
            }
            budget.check("guards", product_states, 0)?;
            let off = s.reach.and(&s.plant_en[e]).and_not(on);
            guards.push(Guard {
                event: e as EventId,
                allow: s.enc.simplify_until(on, &off, &budget, product_states)?,
            });
        }
    }
    Ok(Synthesis {
        engine: Engine::Symbolic,
        outcome: Outcome::Supervisor(Supervisor {
            states: count(&s.reach),
            transitions,
            guards,
        }),
        product_states,
        rounds: s.rounds,
    })
}

/// Exact number of valuations of a BDD over all its variables.
fn count(b: &Bdd) -> u128 {
    b.exact_cardinality()
        .to_string()
        .parse()
        .unwrap_or(u128::MAX)
}
