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

pub mod check;
pub mod emit;
pub mod encode;
pub mod explain;
pub mod explicit;
pub mod extract;
pub mod families;
pub mod problem;
pub mod symbolic;

pub use encode::Formula;
pub use problem::{EventId, Kind, Problem};

use biodivine_lib_bdd::Bdd;

/// Which synthesis engine to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Fixpoint over the explicitly enumerated reachable product.
    Explicit,
    /// Fixpoint over BDDs (for large products).
    Symbolic,
}

impl std::str::FromStr for Engine {
    type Err = String;
    fn from_str(s: &str) -> Result<Engine, String> {
        match s {
            "explicit" => Ok(Engine::Explicit),
            "symbolic" | "bdd" => Ok(Engine::Symbolic),
            _ => Err(format!("unknown engine `{s}` (explicit, symbolic)")),
        }
    }
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
    /// One guard per controllable event, in event order.
    pub guards: Vec<Guard>,
}

/// What synthesis found.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// The maximally permissive controllable nonblocking supervisor.
    Supervisor(Supervisor),
    /// No supervisor exists; the text says why.
    Empty(String),
}

/// Synthesis results with figures.
#[derive(Clone, Debug)]
pub struct Synthesis {
    /// The engine used.
    pub engine: Engine,
    /// Supervisor or reason for its absence.
    pub outcome: Outcome,
    /// Product states examined: reachable ones (explicit) or all encoded ones (symbolic).
    pub product_states: f64,
}

/// Run synthesis. `Err` only when the explicit engine's state limit is exceeded.
pub fn synthesize(p: &Problem, engine: Engine) -> Result<Synthesis, String> {
    match engine {
        Engine::Explicit => {
            let x = explicit::run(p)?;
            let outcome = if x.size() == 0 {
                Outcome::Empty(explain::why_empty(p))
            } else {
                let enc = encode::Encoding::new(p);
                let mut guards = Vec::new();
                for e in 0..p.events.len() as EventId {
                    if !p.events[e as usize].controllable {
                        continue;
                    }
                    let mut on: Vec<&[u32]> = Vec::new();
                    let mut allowed = vec![false; x.states.len()];
                    for &(s, ev, t) in &x.edges {
                        if ev == e && x.kept[s as usize] && x.kept[t as usize] {
                            allowed[s as usize] = true;
                        }
                    }
                    let mut off: Vec<&[u32]> = Vec::new();
                    for (i, locs) in x.states.iter().enumerate() {
                        if !x.kept[i] || !p.enabled_by(Kind::Plant, locs, e) {
                            continue;
                        }
                        if allowed[i] {
                            on.push(locs);
                        } else {
                            off.push(locs);
                        }
                    }
                    let on = enc.set(on.into_iter());
                    let off = enc.set(off.into_iter());
                    guards.push(Guard {
                        event: e,
                        allow: enc.simplify(&on, &off),
                    });
                }
                Outcome::Supervisor(Supervisor {
                    states: x.size() as u128,
                    transitions: x.transitions() as u128,
                    guards,
                })
            };
            Ok(Synthesis {
                engine,
                outcome,
                product_states: x.product_states as f64,
            })
        }
        Engine::Symbolic => {
            let s = symbolic::run(p);
            let product_states = s.enc.valid().cardinality();
            if s.reach.is_false() {
                return Ok(Synthesis {
                    engine,
                    outcome: Outcome::Empty(explain::why_empty(p)),
                    product_states,
                });
            }
            let allowed = symbolic::allowed_sets(p, &s);
            let transitions: u128 = allowed.iter().map(count).sum();
            let mut guards = Vec::new();
            for (e, on) in allowed.iter().enumerate() {
                if !p.events[e].controllable {
                    continue;
                }
                let off = s.reach.and(&s.plant_en[e]).and_not(on);
                guards.push(Guard {
                    event: e as EventId,
                    allow: s.enc.simplify(on, &off),
                });
            }
            Ok(Synthesis {
                engine,
                outcome: Outcome::Supervisor(Supervisor {
                    states: count(&s.reach),
                    transitions,
                    guards,
                }),
                product_states,
            })
        }
    }
}

/// Exact number of valuations of a BDD over all its variables.
fn count(b: &Bdd) -> u128 {
    b.exact_cardinality()
        .to_string()
        .parse()
        .unwrap_or(u128::MAX)
}
