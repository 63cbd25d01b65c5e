//! The synthesis problem: event-level automata synchronised on shared event names.
//!
//! This is the Ramadge–Wonham view of a `system` whose instances are `plant` and
//! `requirement` charts (see `docs/synthesis.md`): every automaton is deterministic, an event
//! occurs in a product state when every automaton whose alphabet contains it can take it, and
//! the automata that have it move together.

/// Index of an event in [`Problem::events`].
pub type EventId = u32;

/// No transition (in [`Automaton::next`]).
pub const NONE: u32 = u32::MAX;

/// An event of the product alphabet.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Event {
    /// Its name (shared by every automaton that declares it).
    pub name: String,
    /// True if a supervisor may disable it.
    pub controllable: bool,
}

/// Whether an automaton models the plant or a requirement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Physical behaviour: what can happen.
    Plant,
    /// Specification: what may happen.
    Requirement,
}

/// One deterministic automaton (an instance of a `plant chart` or `requirement chart`).
#[derive(Clone, Debug)]
pub struct Automaton {
    /// The instance name.
    pub name: String,
    /// The chart it instantiates.
    pub chart: String,
    /// Plant or requirement.
    pub kind: Kind,
    /// Location (state) names.
    pub locs: Vec<String>,
    /// Marked (accepting) locations; a chart that marks no state has every state marked.
    pub marked: Vec<bool>,
    /// The initial location.
    pub initial: u32,
    /// The events of its alphabet, ascending.
    pub alphabet: Vec<EventId>,
    /// `next[loc * events + e]`: the successor, or [`NONE`] (indexed by global event id).
    pub next: Vec<u32>,
    /// Number of events of the problem (the row width of `next`).
    pub n_events: usize,
}

impl Automaton {
    /// Successor of `loc` on `e`, if `e` is in the alphabet and enabled there.
    #[inline]
    pub fn step(&self, loc: u32, e: EventId) -> Option<u32> {
        let n = self.next[loc as usize * self.n_events + e as usize];
        (n != NONE).then_some(n)
    }

    /// True if `e` is in the alphabet.
    pub fn has(&self, e: EventId) -> bool {
        self.alphabet.binary_search(&e).is_ok()
    }

    /// All transitions `(from, event, to)`, ordered by source then event.
    pub fn transitions(&self) -> impl Iterator<Item = (u32, EventId, u32)> + '_ {
        (0..self.locs.len() as u32).flat_map(move |l| {
            self.alphabet
                .iter()
                .filter_map(move |&e| self.step(l, e).map(|t| (l, e, t)))
        })
    }
}

/// A predicate over automaton locations (state-based requirements).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Pred {
    /// A constant.
    Const(bool),
    /// `in(aut.loc)`.
    At(u32, u32),
    /// Negation.
    Not(Box<Pred>),
    /// Conjunction.
    And(Box<Pred>, Box<Pred>),
    /// Disjunction.
    Or(Box<Pred>, Box<Pred>),
}

impl Pred {
    /// Evaluate on a location vector.
    pub fn eval(&self, locs: &[u32]) -> bool {
        match self {
            Pred::Const(b) => *b,
            Pred::At(a, l) => locs[*a as usize] == *l,
            Pred::Not(p) => !p.eval(locs),
            Pred::And(a, b) => a.eval(locs) && b.eval(locs),
            Pred::Or(a, b) => a.eval(locs) || b.eval(locs),
        }
    }

    /// Render in `.sc` syntax, with `at(aut, loc)` giving each atom's text.
    pub fn render(&self, at: &dyn Fn(u32, u32) -> String) -> String {
        match self {
            Pred::Const(b) => b.to_string(),
            Pred::At(a, l) => at(*a, *l),
            Pred::Not(p) => format!("!({})", p.render(at)),
            Pred::And(a, b) => format!("({} && {})", a.render(at), b.render(at)),
            Pred::Or(a, b) => format!("({} || {})", a.render(at), b.render(at)),
        }
    }
}

/// `requirement e needs (cond);`
#[derive(Clone, Debug)]
pub struct Needs {
    /// The event.
    pub event: EventId,
    /// Where it may occur.
    pub cond: Pred,
}

/// A whole synthesis problem.
#[derive(Clone, Debug)]
pub struct Problem {
    /// The system's name.
    pub name: String,
    /// The product alphabet, in order of first declaration.
    pub events: Vec<Event>,
    /// Plants and requirement automata in instance order.
    pub automata: Vec<Automaton>,
    /// `requirement never (cond);` conditions.
    pub never: Vec<Pred>,
    /// `requirement e needs (cond);` conditions.
    pub needs: Vec<Needs>,
}

impl Problem {
    /// The initial location vector.
    pub fn initial(&self) -> Vec<u32> {
        self.automata.iter().map(|a| a.initial).collect()
    }

    /// True if every automaton is in a marked location.
    pub fn is_marked(&self, locs: &[u32]) -> bool {
        self.automata
            .iter()
            .zip(locs)
            .all(|(a, &l)| a.marked[l as usize])
    }

    /// True if some `never` condition holds.
    pub fn is_forbidden(&self, locs: &[u32]) -> bool {
        self.never.iter().any(|p| p.eval(locs))
    }

    /// True if every automaton of `kind` with `e` in its alphabet can take it.
    pub fn enabled_by(&self, kind: Kind, locs: &[u32], e: EventId) -> bool {
        self.automata
            .iter()
            .zip(locs)
            .filter(|(a, _)| a.kind == kind)
            .all(|(a, &l)| !a.has(e) || a.step(l, e).is_some())
    }

    /// True if the requirements (automata and `needs`) allow `e` in `locs`.
    pub fn allowed(&self, locs: &[u32], e: EventId) -> bool {
        self.enabled_by(Kind::Requirement, locs, e)
            && self.needs.iter().all(|n| n.event != e || n.cond.eval(locs))
    }

    /// The successor of `locs` on `e` (every automaton with `e` must be able to take it).
    pub fn successor(&self, locs: &[u32], e: EventId) -> Option<Vec<u32>> {
        let mut out = locs.to_vec();
        for (i, a) in self.automata.iter().enumerate() {
            if a.has(e) {
                out[i] = a.step(locs[i], e)?;
            }
        }
        Some(out)
    }

    /// Number of product states (the product of the automata's sizes), as a float.
    pub fn product_size(&self) -> f64 {
        self.automata.iter().map(|a| a.locs.len() as f64).product()
    }

    /// A location vector as text: `m1.Idle, m2.Working, …`.
    pub fn describe(&self, locs: &[u32]) -> String {
        self.automata
            .iter()
            .zip(locs)
            .map(|(a, &l)| format!("{}.{}", a.name, a.locs[l as usize]))
            .collect::<Vec<_>>()
            .join(", ")
    }
}
