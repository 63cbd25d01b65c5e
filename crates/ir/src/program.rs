//! The IR: a closed system's tick as a small imperative program over a flat vector of bounded
//! integer slots.
//!
//! Every consumer (simulator, checkers, code generators) reads this and nothing else to know
//! what a tick does. Slots `0..n_state` are the persistent state (what a checker stores);
//! `n_state..n_state+n_inputs` are the free inputs of the tick; the rest are temporaries that
//! live within one tick.

use statecheck_base::Span;
use statecheck_model::{StateId, TransId, VarId};
use statecheck_syntax::ast::{BinOp, UnOp};

/// Index of a slot.
pub type SlotId = u32;
/// Index of an expression node in [`Program::nodes`].
pub type ExprId = u32;
/// Index of a procedure in [`Program::procs`].
pub type ProcId = u32;
/// Index of a run-time check site in [`Program::sites`].
pub type SiteId = u32;
/// Index of a coverage item in [`Program::covers`].
pub type CoverId = u32;

/// What a slot holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SlotRole {
    /// A chart variable (outputs, locals, and inputs fed by a connection alias their source).
    Var {
        /// Instance index.
        instance: u32,
        /// Variable.
        var: VarId,
    },
    /// A free input of the system (set by the environment every tick).
    Input {
        /// Instance index.
        instance: u32,
        /// Variable.
        var: VarId,
    },
    /// The active child of an exclusive node (index into its children).
    Region {
        /// Instance index.
        instance: u32,
        /// The OR node.
        node: StateId,
    },
    /// Whether an OR node with history has ever been entered (history resumes only then).
    Visited {
        /// Instance index.
        instance: u32,
        /// The OR node.
        node: StateId,
    },
    /// Ticks since the state was entered, saturating at its largest `after` delay.
    Timer {
        /// Instance index.
        instance: u32,
        /// The state.
        state: StateId,
    },
    /// A local event raised in this tick, present in the next one.
    Pending {
        /// Instance index.
        instance: u32,
        /// The event.
        var: VarId,
    },
    /// A local event present in this tick (temporary).
    Present {
        /// Instance index.
        instance: u32,
        /// The event.
        var: VarId,
    },
    /// Set when a transition left a parallel state, so its later regions are skipped (temporary).
    Abort {
        /// Instance index.
        instance: u32,
        /// The parallel state.
        state: StateId,
    },
    /// False until the initialisation tick has run.
    Started,
    /// Ticks an unanswered `respond` trigger has waited.
    Monitor {
        /// Property index in [`Program::properties`].
        property: u32,
    },
}

/// A slot with its bounds.
#[derive(Clone, Debug)]
pub struct Slot {
    /// Display name, e.g. `fam.actualPos` or `fam.$move`.
    pub name: String,
    /// What it holds.
    pub role: SlotRole,
    /// Smallest value.
    pub lo: i64,
    /// Largest value.
    pub hi: i64,
    /// Value before the first tick.
    pub init: i64,
    /// How values are shown to people.
    pub display: ValueKind,
}

/// How a slot's values are displayed and parsed in scenarios and traces.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ValueKind {
    /// `true` / `false`.
    Bool,
    /// A decimal integer.
    Int,
    /// An enum literal, by index.
    Enum(Vec<String>),
}

impl ValueKind {
    /// Render a value.
    pub fn format(&self, v: i64) -> String {
        match self {
            ValueKind::Bool => (v != 0).to_string(),
            ValueKind::Int => v.to_string(),
            ValueKind::Enum(names) => names
                .get(v as usize)
                .cloned()
                .unwrap_or_else(|| v.to_string()),
        }
    }

    /// Parse a value written in a scenario (`true`, `42`, `-3`, `0x1F`, an enum literal).
    pub fn parse(&self, text: &str) -> Option<i64> {
        match self {
            ValueKind::Bool => match text {
                "true" | "1" => Some(1),
                "false" | "0" => Some(0),
                _ => None,
            },
            ValueKind::Int => parse_int(text),
            ValueKind::Enum(names) => {
                let bare = text.rsplit('.').next().unwrap_or(text);
                names.iter().position(|n| n == bare).map(|i| i as i64)
            }
        }
    }
}

/// An integer in decimal, `0x` hex or `0b` binary with an optional `-` and `_` separators.
/// The magnitude is read unsigned so that every `i64`, `-9223372036854775808` included, reads
/// back what [`ValueKind::format`] wrote.
fn parse_int(text: &str) -> Option<i64> {
    let (neg, digits) = match text.strip_prefix('-') {
        Some(d) => (true, d),
        None => (false, text),
    };
    let digits = digits.replace('_', "");
    let mag = if let Some(h) = digits
        .strip_prefix("0x")
        .or_else(|| digits.strip_prefix("0X"))
    {
        u64::from_str_radix(h, 16).ok()?
    } else if let Some(b) = digits.strip_prefix("0b") {
        u64::from_str_radix(b, 2).ok()?
    } else {
        digits.parse::<u64>().ok()?
    };
    let v = if neg { -(mag as i128) } else { mag as i128 };
    i64::try_from(v).ok()
}

impl Slot {
    /// Bits needed to store `value - lo` for every value in range.
    pub fn width(&self) -> u32 {
        let span = self.hi.wrapping_sub(self.lo) as u64;
        64 - span.leading_zeros()
    }
}

/// An expression node; children are earlier nodes.
#[derive(Clone, Debug)]
pub enum Node {
    /// A constant.
    Const(i64),
    /// A slot's current value.
    Slot(SlotId),
    /// A unary operation.
    Unary(UnOp, ExprId),
    /// A binary operation; `&&`/`||` short-circuit; the site reports `/`, `%`, shifts and overflow.
    Binary(BinOp, ExprId, ExprId, SiteId),
    /// `if c then a else b`.
    Ite(ExprId, ExprId, ExprId),
    /// `min(a, b)`.
    Min(ExprId, ExprId),
    /// `max(a, b)`.
    Max(ExprId, ExprId),
    /// `abs(a)`.
    Abs(ExprId, SiteId),
    /// The value must lie in `lo..=hi`, else a run-time error at the site.
    Check(ExprId, i64, i64, SiteId),
    /// Evaluate the value into local `l`, then the body (an inlined function argument).
    Let(u32, ExprId, ExprId),
    /// The value of local `l`, bound by the enclosing `Let`.
    Local(u32),
}

/// A statement.
#[derive(Clone, Debug)]
pub enum Stmt {
    /// `slot = expr`, with a range check against the slot's bounds when `site` is given.
    Assign {
        /// Destination.
        slot: SlotId,
        /// Value.
        expr: ExprId,
        /// Range-check site, if the value may leave the slot's range.
        site: Option<SiteId>,
    },
    /// Conditional.
    If {
        /// Condition (non-zero is true).
        cond: ExprId,
        /// When true.
        then: Vec<Stmt>,
        /// When false.
        otherwise: Vec<Stmt>,
    },
    /// Run `cases[slot]`.
    Switch {
        /// The selector (a region slot).
        slot: SlotId,
        /// One block per value `0..`.
        cases: Vec<Vec<Stmt>>,
    },
    /// Run a procedure (procedures never recurse: the state hierarchy is a tree).
    Call(ProcId),
    /// Count a coverage item (a state entered, a transition or branch taken).
    Cover(CoverId),
}

/// A named block of statements shared by several callers (entry and exit of a state).
#[derive(Clone, Debug)]
pub struct Proc {
    /// For generated code and debugging, e.g. `exit_fam_move_running`.
    pub name: String,
    /// The statements.
    pub body: Vec<Stmt>,
}

/// Where a run-time error can occur.
#[derive(Clone, Debug)]
pub struct Site {
    /// The source span.
    pub span: Span,
    /// Instance index, if inside a chart.
    pub instance: Option<u32>,
    /// Path of the state whose action or transition it is (`""` for the chart level).
    pub state: String,
    /// What is checked, e.g. ``assignment to `actualPos` ``.
    pub what: String,
}

/// What a coverage item counts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CoverKind {
    /// Entries of a state.
    State(StateId),
    /// Firings of a transition.
    Transition(TransId),
    /// Firings through branch `index` (depth-first numbering) of a transition's choice.
    Branch(TransId, u32),
}

/// A coverage item.
#[derive(Clone, Debug)]
pub struct Cover {
    /// Instance index.
    pub instance: u32,
    /// What it counts.
    pub kind: CoverKind,
    /// Human-readable label, e.g. `Go.GoLeft` or `Stop -> Go.GoLeft`.
    pub label: String,
    /// Where it was written.
    pub span: Span,
    /// True when the item is meant never to be covered: an observer's `error` state
    /// (`Chart::is_observer_error`) and a transition whose every target is one. Reports of
    /// dead design and of coverage leave such items out.
    pub expected_unreached: bool,
}

/// Per-instance layout: which slot holds what.
#[derive(Clone, Debug)]
pub struct InstanceLayout {
    /// Display name, e.g. `fam[1]`.
    pub name: String,
    /// The chart in the model.
    pub chart: u32,
    /// Slot of each variable (connected inputs share their source's slot).
    pub var_slots: Vec<SlotId>,
    /// Region slot of each OR node (`None` for simple and parallel states).
    pub region_slots: Vec<Option<SlotId>>,
    /// `in(state)` expression of each state node.
    pub active: Vec<ExprId>,
    /// True for observer instances.
    pub observer: bool,
}

/// A free input of the system.
#[derive(Clone, Debug)]
pub struct Input {
    /// Its slot.
    pub slot: SlotId,
    /// `instance.variable`.
    pub name: String,
    /// True for events (present or absent each tick, never held).
    pub is_event: bool,
    /// The instance.
    pub instance: u32,
    /// The variable.
    pub var: VarId,
    /// The probability that random simulation makes it 1 in a tick, when the system declares
    /// one (`rate instance.input = P;`); random simulation draws ½ otherwise.
    pub rate: Option<f64>,
}

/// Property kinds in the IR.
#[derive(Clone, Debug)]
pub enum PropertyKind {
    /// `expr` holds in every reachable state where `assuming` holds.
    Invariant {
        /// The invariant.
        expr: ExprId,
        /// The restriction, if any.
        assuming: Option<ExprId>,
    },
    /// Some reachable state satisfies `expr`.
    Reachable {
        /// Target condition.
        expr: ExprId,
    },
    /// Bounded response, monitored by a slot; `ok` is false once the bound is exceeded.
    Respond {
        /// The monitor's slot.
        monitor: SlotId,
        /// The bound.
        within: i64,
        /// `monitor <= within`.
        ok: ExprId,
    },
    /// The observer instance's `error` state is never entered; `ok` is `!in(error)`.
    Observer {
        /// The observer instance.
        instance: u32,
        /// `!in(error)`.
        ok: ExprId,
    },
}

/// What every state after a tick must satisfy for a property: compiled from the property by
/// the lowering, so that every consumer (simulator, engines, code generators) reads a property
/// the same way and none re-decides what an invariant, a `respond` or an observer means.
///
/// Each expression is read as a truth value: non-zero is true, and an expression whose
/// evaluation fails reads as **false** ([`crate::Machine::holds`]). An invariant whose
/// expression fails is therefore violated, and a target whose expression fails is not reached.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Goal {
    /// Violated by a state where `when` holds (every state, without one) and `holds` does not:
    /// invariants (`when` is their `assuming`), bounded response (its monitor within the
    /// bound) and observers (not in `error`).
    Always {
        /// The restriction, if any.
        when: Option<ExprId>,
        /// What must hold.
        holds: ExprId,
    },
    /// Witnessed by a state where `target` holds (`reachable`).
    Reach {
        /// The target.
        target: ExprId,
    },
}

impl Goal {
    /// True when a state decides the goal: it violates an `Always` or witnesses a `Reach`.
    /// `holds` reads one expression on that state (evaluation failure reads as false).
    #[inline]
    pub fn decided_by(self, mut holds: impl FnMut(ExprId) -> bool) -> bool {
        match self {
            // `holds` first: it usually holds, and then `when` need not be read (both are
            // pure, so the order does not change the answer).
            Goal::Always { when, holds: h } => !holds(h) && when.is_none_or(holds),
            Goal::Reach { target } => holds(target),
        }
    }

    /// True for a reachability goal (decided by a witness, not a violation).
    pub fn is_reach(self) -> bool {
        matches!(self, Goal::Reach { .. })
    }

    /// The expressions the goal reads: `holds` then `when`, or the target.
    pub fn exprs(self) -> impl Iterator<Item = ExprId> {
        let (a, b) = match self {
            Goal::Always { when, holds } => (holds, when),
            Goal::Reach { target } => (target, None),
        };
        std::iter::once(a).chain(b)
    }
}

/// A property of the system.
#[derive(Clone, Debug)]
pub struct Property {
    /// Its name (a contract).
    pub name: String,
    /// What it states, as written (for reports).
    pub kind: PropertyKind,
    /// What it asks of every state after a tick: the form every consumer reads.
    pub goal: Goal,
    /// Where it was declared.
    pub span: Span,
}

/// A lowered system: everything needed to run, check or generate code for it.
#[derive(Clone, Debug)]
pub struct Program {
    /// System name.
    pub name: String,
    /// All slots: state, then inputs, then temporaries.
    pub slots: Vec<Slot>,
    /// Number of persistent state slots (they come first).
    pub n_state: usize,
    /// Free inputs, in slot order (they follow the state slots).
    pub inputs: Vec<Input>,
    /// Expression arena.
    pub nodes: Vec<Node>,
    /// Shared procedures.
    pub procs: Vec<Proc>,
    /// One tick of the whole system.
    pub step: Vec<Stmt>,
    /// Run-time check sites.
    pub sites: Vec<Site>,
    /// Coverage items.
    pub covers: Vec<Cover>,
    /// Instances in declaration order.
    pub instances: Vec<InstanceLayout>,
    /// Execution order (indices into `instances`).
    pub order: Vec<u32>,
    /// Constraints on the inputs of each tick (over inputs and the state before the tick).
    pub assumes: Vec<ExprId>,
    /// Properties, checked on the state after each tick.
    pub properties: Vec<Property>,
    /// Temporal properties (`ltl`, `ctl`, unbounded `respond`, `nonblocking`), decided on
    /// runs rather than states (`crate::temporal`).
    pub temporal: Vec<crate::temporal::TemporalProperty>,
    /// Fairness constraints on the runs of the temporal properties.
    pub fairness: Vec<crate::temporal::Fairness>,
    /// The `Started` slot.
    pub started: SlotId,
    /// Number of expression locals (see [`Node::Let`]).
    pub n_locals: usize,
    /// The declared length of one tick in milliseconds (`tick 100 ms;`), `None` when the model
    /// declares none (then nothing shows a time; see [`crate::time`]).
    pub tick_ms: Option<i64>,
    /// What the interpreter derives from the program once (its register code, `crate::vm`).
    pub(crate) run_cache: RunCache,
}

/// What the interpreter derives from a program once, on first use, and shares between all the
/// machines that run it (the register code of `crate::vm`). Opaque here, so that the IR's data
/// does not depend on how it is run; a cloned program starts with an empty cache.
#[derive(Default)]
pub(crate) struct RunCache(std::sync::OnceLock<Box<dyn std::any::Any + Send + Sync>>);

impl RunCache {
    /// The cached value, computed by `init` on first use; `None` if a value of another type
    /// was cached (one type is ever stored: `vm::Code`).
    pub(crate) fn get_or_init<T: std::any::Any + Send + Sync>(
        &self,
        init: impl FnOnce() -> T,
    ) -> Option<&T> {
        self.0.get_or_init(|| Box::new(init())).downcast_ref()
    }
}

impl Clone for RunCache {
    fn clone(&self) -> Self {
        RunCache::default()
    }
}

impl std::fmt::Debug for RunCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let state = if self.0.get().is_some() {
            "built"
        } else {
            "empty"
        };
        write!(f, "RunCache({state})")
    }
}

impl Program {
    /// The slots of the persistent state.
    pub fn state_slots(&self) -> &[Slot] {
        &self.slots[..self.n_state]
    }

    /// Total bits of a packed state vector.
    pub fn state_bits(&self) -> u32 {
        self.state_slots().iter().map(Slot::width).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::ValueKind;

    #[test]
    fn scenario_integers_round_trip_over_the_full_i64_range() {
        // IC3 once wrote `-9223372036854775808` (i64::MIN) that the reader then rejected.
        for v in [i64::MIN, i64::MIN + 1, -1, 0, 1, i64::MAX] {
            assert_eq!(ValueKind::Int.parse(&ValueKind::Int.format(v)), Some(v));
        }
        assert_eq!(ValueKind::Int.parse("-0x8000000000000000"), Some(i64::MIN));
        // One past either end has no value.
        assert_eq!(ValueKind::Int.parse("9223372036854775808"), None);
        assert_eq!(ValueKind::Int.parse("-9223372036854775809"), None);
    }
}
