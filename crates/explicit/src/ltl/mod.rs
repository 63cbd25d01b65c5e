//! Temporal properties on the explicit engine (docs/properties.md, "Temporal properties").
//!
//! The position graph of the system is built once ([`graph`]), with a letter per position
//! over the atoms of every selected property and of the fairness constraints. An LTL
//! property is checked by translating its negation into a generalised Büchi automaton
//! ([`buchi`], GPVW) and searching the product for a fair accepting cycle ([`product`],
//! SCC-based, [`scc`]); a cycle is a counterexample lasso. CTL properties are evaluated by
//! fixpoints on the same graph ([`ctl`]), with fair `EG` under fairness.

/// The translation lives in the IR, shared with the SAT engines' monitors.
pub use statecheck_ir::temporal::buchi;
pub mod ctl;
pub mod graph;
pub mod product;
pub mod scc;

use crate::props::PropKind;
use crate::{Options, PropResult, Verdict};
use statecheck_ir::temporal::{TemporalFormula, Written};
use statecheck_ir::{ExprId, Program};

/// Product states at most, per property, before the verdict is `unknown`.
const MAX_PRODUCT: u64 = 50_000_000;

/// The names of `program`'s temporal properties.
pub fn names(program: &Program) -> Vec<&str> {
    program.temporal.iter().map(|t| t.name.as_str()).collect()
}

/// The built-in property decided on the position graph: no reachable state where the
/// `assume`s allow no input vector. Reported when the system has temporal properties, or when
/// named.
pub const DEADLOCK_FREE: &str = "deadlock_free";

/// Split selected property names into those this module decides (temporal ones and
/// [`DEADLOCK_FREE`]) and the others (unchanged order).
pub fn split(program: &Program, names: &[String]) -> (Vec<String>, Vec<String>) {
    names
        .iter()
        .cloned()
        .partition(|n| n == DEADLOCK_FREE || program.temporal.iter().any(|t| &t.name == n))
}

/// The kind word of a temporal property.
fn kind(w: Written) -> PropKind {
    match w {
        Written::Ltl => PropKind::Ltl,
        Written::Respond => PropKind::Respond,
        Written::Ctl => PropKind::Ctl,
        Written::Nonblocking => PropKind::Nonblocking,
    }
}

/// Statistics of a temporal check.
#[derive(Clone, Debug, Default)]
pub struct TemporalStats {
    /// States of the graph (including the initial one).
    pub states: u64,
    /// Positions (graph nodes).
    pub positions: u64,
    /// Transitions taken.
    pub transitions: u64,
    /// Bytes of the graph.
    pub graph_bytes: u64,
    /// Reachable states where the `assume`s allow no input (deadlocks).
    pub deadlocks: u64,
}

/// Check the temporal properties named in `selected` (all when `None`).
pub fn check(
    program: &Program,
    selected: Option<&[String]>,
    opts: &Options,
) -> (Vec<PropResult>, TemporalStats) {
    let start = std::time::Instant::now();
    let props: Vec<_> = program
        .temporal
        .iter()
        .filter(|t| selected.is_none_or(|s| s.contains(&t.name)))
        .collect();
    let mut stats = TemporalStats::default();
    let deadlock = match selected {
        None => !props.is_empty(),
        Some(s) => s.iter().any(|n| n == DEADLOCK_FREE),
    };
    if props.is_empty() && !deadlock {
        return (Vec::new(), stats);
    }
    let unknown = |name: &str, w: Written, why: String| PropResult {
        name: name.to_string(),
        kind: kind(w),
        verdict: Verdict::Unknown,
        depth: 0,
        counterexample: None,
        error: None,
        note: Some(why),
        loop_start: None,
    };
    // Atoms: each LTL automaton's, each CTL formula's, then the fairness constraints'.
    let mut atoms: Vec<ExprId> = Vec::new();
    let mut automata = Vec::new();
    for p in &props {
        match &p.formula {
            TemporalFormula::Ltl(f) => {
                let neg = f.clone().negate();
                automata.push(Some(buchi::translate(&neg, &mut atoms)));
            }
            TemporalFormula::Ctl(f) => {
                for a in f.atoms() {
                    if !atoms.contains(&a) {
                        atoms.push(a);
                    }
                }
                automata.push(None);
            }
        }
    }
    let mut fair = product::FairBits::default();
    let bit = |e: ExprId, atoms: &mut Vec<ExprId>| match atoms.iter().position(|&a| a == e) {
        Some(i) => i as u32,
        None => {
            atoms.push(e);
            (atoms.len() - 1) as u32
        }
    };
    for f in &program.fairness {
        let e = bit(f.expr, &mut atoms);
        match f.trigger {
            None => fair.justice.push(e),
            Some(t) => {
                let t = bit(t, &mut atoms);
                fair.compassion.push((t, e));
            }
        }
    }
    if atoms.len() > 64 {
        let why = "more than 64 distinct atoms in the temporal properties and fairness constraints"
            .to_string();
        return (
            props
                .iter()
                .map(|p| unknown(&p.name, p.written, why.clone()))
                .collect(),
            stats,
        );
    }
    // With a time limit, the graph gets three quarters of it: if it is not completed, the
    // rest goes to looking for lassos in what was built (`early_lassos`).
    let limits = graph::GraphLimits {
        max_states: opts.max_states,
        max_memory: opts.max_memory,
        deadline: opts.timeout.map(|t| start + t.mul_f64(0.75)),
        max_branching: (!opts.force).then_some(opts.max_branching),
    };
    let g = match graph::build_partial(program, &atoms, limits) {
        (g, None) => g,
        (g, Some(why)) => {
            let why = format!("the state graph was not completed: {why:?} limit");
            let early = early_lassos(program, &g, &props, &automata, &fair);
            return (
                props
                    .iter()
                    .zip(early)
                    .map(|(p, found)| {
                        found.unwrap_or_else(|| unknown(&p.name, p.written, why.clone()))
                    })
                    .collect(),
                stats,
            );
        }
    };
    stats.states = g.n_states() as u64;
    stats.positions = g.n_nodes() as u64;
    stats.transitions = g.transitions;
    stats.graph_bytes = g.bytes();
    stats.deadlocks = g.deadlocks.len() as u64;
    let max_product = opts.max_states.unwrap_or(MAX_PRODUCT).min(MAX_PRODUCT);
    let mut results: Vec<PropResult> = props
        .iter()
        .zip(automata)
        .map(|(p, aut)| match (&p.formula, aut) {
            (TemporalFormula::Ltl(_), Some(Ok(a))) => {
                match product::find_lasso(&g, &a, &fair, max_product) {
                    Ok(None) => PropResult {
                        name: p.name.clone(),
                        kind: kind(p.written),
                        verdict: Verdict::Proved,
                        depth: 0,
                        counterexample: None,
                        error: None,
                        note: None,
                        loop_start: None,
                    },
                    Ok(Some(l)) => violated(program, &p.name, p.written, &l),
                    Err(product::TooLarge) => unknown(
                        &p.name,
                        p.written,
                        format!("the product has more than {max_product} states"),
                    ),
                }
            }
            (TemporalFormula::Ltl(_), _) => unknown(
                &p.name,
                p.written,
                "the formula's automaton is too large".into(),
            ),
            (TemporalFormula::Ctl(f), _) => {
                ctl::verdict(program, &g, f, &atoms, &fair, &p.name, kind(p.written))
            }
        })
        .collect();
    if deadlock {
        results.push(deadlock_result(program, &g));
    }
    (results, stats)
}

/// The result of a property violated by lasso `l`.
fn violated(program: &Program, name: &str, w: Written, l: &product::Lasso) -> PropResult {
    PropResult {
        name: name.to_string(),
        kind: kind(w),
        verdict: Verdict::Violated,
        depth: l.inputs.len() as u64,
        counterexample: Some(
            l.inputs
                .iter()
                .map(|&i| graph::input_vector(program, i))
                .collect(),
        ),
        error: None,
        note: None,
        loop_start: Some(l.loop_start as u64),
    }
}

/// Product states per position of a partial graph at most, in [`early_lassos`]: the search
/// stays proportional to the graph built.
const EARLY_PRODUCT_PER_NODE: u64 = 4;

/// Lassos in a graph whose construction a limit stopped (`graph::build_partial`): every cycle
/// in it is one of the system, so a fair accepting one found is a counterexample — a
/// violation reported although the graph is incomplete (early accepting-cycle detection).
/// `None` per property where none is found (or the property is CTL).
fn early_lassos(
    program: &Program,
    g: &graph::Kripke,
    props: &[&statecheck_ir::temporal::TemporalProperty],
    automata: &[Option<Result<buchi::Buchi, buchi::TranslateError>>],
    fair: &product::FairBits,
) -> Vec<Option<PropResult>> {
    let bound = (g.n_nodes() as u64)
        .saturating_mul(EARLY_PRODUCT_PER_NODE)
        .min(MAX_PRODUCT);
    props
        .iter()
        .zip(automata)
        .map(|(p, aut)| match aut {
            Some(Ok(a)) if g.n_states() > 0 => match product::find_lasso(g, a, fair, bound) {
                Ok(Some(l)) => {
                    let mut r = violated(program, &p.name, p.written, &l);
                    r.note = Some(
                        "found before the state graph was complete (the lasso is real)".into(),
                    );
                    Some(r)
                }
                _ => None,
            },
            _ => None,
        })
        .collect()
}

/// `deadlock_free`: violated by the first deadlock found (breadth-first: a shortest
/// scenario, whose last tick enters the deadlocked state).
fn deadlock_result(program: &Program, g: &graph::Kripke) -> PropResult {
    let mut r = PropResult::unknown(DEADLOCK_FREE, PropKind::Builtin);
    match g.deadlocks.first() {
        None => r.verdict = Verdict::Proved,
        Some(&s) => {
            let path = g.path_to(s);
            r.verdict = Verdict::Violated;
            r.depth = path.len() as u64;
            r.counterexample = Some(
                path.iter()
                    .map(|&i| graph::input_vector(program, i))
                    .collect(),
            );
            r.note = Some("after the last tick the `assume`s allow no input vector".into());
        }
    }
    r
}
