//! The properties one run checks: the system's own (invariants, reachability, bounded response,
//! observers) and the built-in ones every model has.

use statecheck_ir::{ExprId, Goal, Prepared, Program};

use statecheck_ir::verdict::{self, Builtin, Source};
pub use statecheck_ir::verdict::{PropKind, BUILTINS};

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
    /// The property's goal ([`Goal`]) with its expressions compiled: violated when `when`
    /// holds and `holds` does not.
    Always { when: Option<Expr>, holds: Expr },
    /// Reached when `target` holds.
    Reach { target: Expr },
    /// Violated by a run-time error whose built-in property has this name.
    Builtin(Builtin),
}

impl Check {
    /// The expressions it evaluates.
    fn exprs(self) -> Vec<ExprId> {
        match self {
            Check::Always { when, holds } => {
                std::iter::once(holds).chain(when).map(|e| e.id).collect()
            }
            Check::Reach { target } => vec![target.id],
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

impl Spec {
    /// True when the machine, as a tick left it, decides this property (violates it, or for
    /// `reachable` witnesses it): the IR's reading of the goal, exactly as this engine checks
    /// it on a transition. Always false for a built-in property, which a run-time error of
    /// the tick decides instead ([`Spec::builtin`]). A hook for other explorers of the same
    /// transition system (the distributed engine).
    pub fn decided_by(&self, m: &mut statecheck_ir::Machine) -> bool {
        crate::expand::decides(m, self.check)
    }

    /// The built-in property this is, if it is one: decided by a tick's run-time error of
    /// that kind (`RuntimeErrorKind::builtin`).
    pub fn builtin(&self) -> Option<Builtin> {
        match self.check {
            Check::Builtin(b) => Some(b),
            _ => None,
        }
    }
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
    let state = statecheck_ir::assume::reads::state_slots(program);
    let state_and_inputs = state.start..statecheck_ir::assume::reads::input_slots(program).end;
    for s in specs {
        let exprs = s.check.exprs();
        s.after_tick = exprs.iter().all(|&e| {
            statecheck_ir::assume::reads::reads_only(program, e, state_and_inputs.clone())
        });
        s.per_state = !exprs.is_empty()
            && exprs
                .iter()
                .all(|&e| statecheck_ir::assume::reads::reads_only(program, e, state.clone()))
            && !init_decides(s.check);
    }
}

/// The checks of the given properties of a program.
fn specs(program: &Program, refs: Vec<verdict::PropertyRef>) -> Vec<Spec> {
    let e = |id: &ExprId| Expr::new(program, *id);
    refs.into_iter()
        .map(|r| {
            let check = match r.source {
                Source::Builtin(b) => Check::Builtin(b),
                Source::Own(i) => match &program.properties[i].goal {
                    Goal::Always { when, holds } => Check::Always {
                        when: when.as_ref().map(e),
                        holds: e(holds),
                    },
                    Goal::Reach { target } => Check::Reach { target: e(target) },
                },
            };
            Spec {
                name: r.name,
                kind: r.kind,
                check,
                per_state: false,
                after_tick: false,
            }
        })
        .collect()
}

/// Every property of a program: its own in declaration order, then the built-ins.
pub fn all(program: &Program) -> Vec<Spec> {
    specs(program, verdict::properties(program))
}

/// The properties named in `names` (all of them when `names` is empty), in declaration order.
pub fn select(program: &Program, names: &[String]) -> Result<Vec<Spec>, verdict::UnknownProperty> {
    Ok(specs(program, verdict::select(program, names)?))
}
