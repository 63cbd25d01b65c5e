//! The properties one run checks: the system's own (invariants, reachability, bounded response,
//! observers) and the built-in ones every model has.

use statecheck_ir::{ExprId, Prepared, Program, PropertyKind};

/// Names of the built-in properties, violated by run-time errors.
pub const BUILTINS: [&str; 3] = ["no_range_overflow", "no_division_by_zero", "no_bad_shift"];

/// What kind of property (as printed and in JSON).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PropKind {
    /// `invariant NAME: expr [assuming expr];`
    Invariant,
    /// `reachable NAME: expr;`
    Reachable,
    /// `respond NAME: trigger => response within N;`
    Respond,
    /// An observer chart's `error` state is never entered.
    Observer,
    /// A built-in property (no run-time error of a kind).
    Builtin,
    /// `ltl NAME: formula;`
    Ltl,
    /// `ctl NAME: formula;`
    Ctl,
    /// `nonblocking NAME: expr;`
    Nonblocking,
}

impl PropKind {
    /// The JSON and table word.
    pub fn as_str(self) -> &'static str {
        match self {
            PropKind::Invariant => "invariant",
            PropKind::Reachable => "reachable",
            PropKind::Respond => "respond",
            PropKind::Observer => "observer",
            PropKind::Builtin => "builtin",
            PropKind::Ltl => "ltl",
            PropKind::Ctl => "ctl",
            PropKind::Nonblocking => "nonblocking",
        }
    }
}

/// An expression of a property, and its compiled form.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Expr {
    pub id: ExprId,
    pub code: Prepared,
}

impl Expr {
    fn new(program: &Program, id: ExprId) -> Expr {
        Expr {
            id,
            code: program.prepare(id),
        }
    }
}

/// How a property is decided on one transition.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Check {
    /// Violated when `assuming` holds and `expr` does not.
    Invariant { expr: Expr, assuming: Option<Expr> },
    /// Reached when `expr` holds.
    Reachable { expr: Expr },
    /// Violated when `ok` does not hold (respond monitors, observers).
    Ok { ok: Expr },
    /// Violated by a run-time error whose built-in property has this name.
    Builtin(&'static str),
}

impl Check {
    /// The expressions it evaluates.
    fn exprs(self) -> Vec<ExprId> {
        match self {
            Check::Invariant { expr, assuming } => std::iter::once(expr)
                .chain(assuming)
                .map(|e| e.id)
                .collect(),
            Check::Reachable { expr } => vec![expr.id],
            Check::Ok { ok } => vec![ok.id],
            Check::Builtin(_) => Vec::new(),
        }
    }
}

/// A property to check.
#[derive(Clone, Debug)]
pub struct Spec {
    /// Its name.
    pub name: String,
    /// Its kind.
    pub kind: PropKind,
    pub(crate) check: Check,
    /// Decided by the state after the tick alone, so checked once per new state instead of on
    /// every transition (see [`mark_per_state`]).
    pub(crate) per_state: bool,
    /// Decided by the state after the tick and the tick's inputs (no per-tick temporaries), so
    /// the native successor generator's output is enough to check it (see [`mark_per_state`]).
    pub(crate) after_tick: bool,
}

/// Mark the properties that read only the state and the inputs ([`Spec::after_tick`]), and
/// those that can be checked once per newly found state instead of on every transition: those whose expressions read only persistent state slots (so their value
/// after a tick is a function of the successor state), unless the initial state decides them
/// (the initial state is stored before any tick, so a transition back to it would not be
/// checked again). `init_decides` tells whether the initial state decides a check.
///
/// Same verdicts and counterexamples: a violating transition leads to a violating state; the
/// first time that state is found, in generation order, is the first such transition.
pub(crate) fn mark_per_state(
    program: &Program,
    specs: &mut [Spec],
    mut init_decides: impl FnMut(Check) -> bool,
) {
    let state = crate::reads::state_slots(program);
    let state_and_inputs = state.start..crate::reads::input_slots(program).end;
    for s in specs {
        let exprs = s.check.exprs();
        s.after_tick = exprs
            .iter()
            .all(|&e| crate::reads::reads_only(program, e, state_and_inputs.clone()));
        s.per_state = !exprs.is_empty()
            && exprs
                .iter()
                .all(|&e| crate::reads::reads_only(program, e, state.clone()))
            && !init_decides(s.check);
    }
}

/// Every property of a program: its own in declaration order, then the built-ins.
pub fn all(program: &Program) -> Vec<Spec> {
    let e = |id: &ExprId| Expr::new(program, *id);
    let mut out: Vec<Spec> = program
        .properties
        .iter()
        .map(|p| {
            let (kind, check) = match &p.kind {
                PropertyKind::Invariant { expr, assuming } => (
                    PropKind::Invariant,
                    Check::Invariant {
                        expr: e(expr),
                        assuming: assuming.as_ref().map(e),
                    },
                ),
                PropertyKind::Reachable { expr } => {
                    (PropKind::Reachable, Check::Reachable { expr: e(expr) })
                }
                PropertyKind::Respond { ok, .. } => (PropKind::Respond, Check::Ok { ok: e(ok) }),
                PropertyKind::Observer { ok, .. } => (PropKind::Observer, Check::Ok { ok: e(ok) }),
            };
            Spec {
                name: p.name.clone(),
                kind,
                check,
                per_state: false,
                after_tick: false,
            }
        })
        .collect();
    out.extend(BUILTINS.iter().map(|b| Spec {
        name: (*b).to_string(),
        kind: PropKind::Builtin,
        check: Check::Builtin(b),
        per_state: false,
        after_tick: false,
    }));
    out
}

/// The properties named in `names` (all of them when `names` is empty), in declaration order.
/// Errs with a message naming the unknown property and the known ones.
pub fn select(program: &Program, names: &[String]) -> Result<Vec<Spec>, String> {
    let all = all(program);
    if names.is_empty() {
        return Ok(all);
    }
    if let Some(bad) = names.iter().find(|n| !all.iter().any(|s| &s.name == *n)) {
        let known: Vec<&str> = all.iter().map(|s| s.name.as_str()).collect();
        return Err(format!(
            "no property named `{bad}`; the properties are: {}",
            known.join(", ")
        ));
    }
    Ok(all
        .into_iter()
        .filter(|s| names.contains(&s.name))
        .collect())
}
