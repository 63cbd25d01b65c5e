//! The checked model: every name resolved, every expression typed, the state hierarchy as an
//! arena. This is what the IR lowering consumes; it still says *what* was written, not how a
//! step executes.

use crate::types::{EnumId, Type};
use statecheck_base::Span;
use statecheck_syntax::ast::HistoryKind;
pub use statecheck_syntax::ast::{BinOp, Control, UnOp, VarKind};

/// Index of a chart in [`Model::charts`].
pub type ChartId = u32;
/// Index of a state node in [`Chart::states`]; 0 is the chart's root.
pub type StateId = u32;
/// Index of a variable in [`Chart::vars`].
pub type VarId = u32;
/// Index of a transition in [`Chart::transitions`].
pub type TransId = u32;

/// A whole checked file.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Enum declarations.
    pub enums: Vec<EnumDef>,
    /// Constants with their values (kept for display and code generation).
    pub consts: Vec<ConstDef>,
    /// Charts (including observers declared inside systems, after the top-level ones).
    pub charts: Vec<Chart>,
    /// Systems, including implicit single-chart systems (see [`System::implicit`]).
    pub systems: Vec<System>,
    /// Length of one tick in milliseconds, if declared.
    pub tick_ms: Option<i64>,
    /// The continuous variables of every discretized chart, by the chart's name in
    /// [`Model::charts`] (a parameterised chart's copies each with their values:
    /// `Mover(20)`), for `statecheck analyse` (docs/hybrid.md).
    pub hybrid: Vec<crate::hybrid::ChartPlans>,
}

/// `enum Name { A, B }`
#[derive(Clone, Debug)]
pub struct EnumDef {
    /// The enum's name.
    pub name: String,
    /// Literal names in order (value = index).
    pub variants: Vec<String>,
}

/// A named constant.
#[derive(Clone, Debug)]
pub struct ConstDef {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: Type,
    /// Its value.
    pub value: i64,
}

/// What a chart is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartRole {
    /// An ordinary chart (controller or plant model).
    Normal,
    /// An assertion chart: its property is that its state `error` is never entered.
    Observer,
    /// `plant chart`: an automaton of a synthesis problem (`docs/synthesis.md`).
    Plant,
    /// `requirement chart`: an automaton a synthesized supervisor must enforce.
    Requirement,
}

impl ChartRole {
    /// The role a top-level chart declares (`plant chart`, `requirement chart`, or none).
    pub fn of(c: &statecheck_syntax::ast::Chart) -> ChartRole {
        match c.role.as_ref().map(|r| r.name.as_str()) {
            Some("plant") => ChartRole::Plant,
            Some("requirement") => ChartRole::Requirement,
            _ => ChartRole::Normal,
        }
    }
}

/// A checked chart.
#[derive(Clone, Debug)]
pub struct Chart {
    /// Its name.
    pub name: String,
    /// Where it was declared (its name).
    pub span: Span,
    /// Ordinary chart or observer.
    pub role: ChartRole,
    /// Variables and events.
    pub vars: Vec<Var>,
    /// State hierarchy; `states[0]` is the root (the chart itself, an OR or AND node).
    pub states: Vec<StateNode>,
    /// All transitions, each owned by one source state.
    pub transitions: Vec<Transition>,
    /// Properties declared in the chart (hold for every instance).
    pub properties: Vec<Property>,
}

/// A chart variable or event.
#[derive(Clone, Debug)]
pub struct Var {
    /// Its name.
    pub name: String,
    /// Input, output or local.
    pub kind: VarKind,
    /// True for events.
    pub is_event: bool,
    /// Its type (`Bool` for events).
    pub ty: Type,
    /// Initial value (for inputs: the value before a scenario sets one).
    pub init: i64,
    /// `controllable`/`uncontrollable` (events of plant and requirement charts).
    pub control: Option<Control>,
    /// Where it was declared.
    pub span: Span,
}

/// How a state node decomposes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NodeKind {
    /// A leaf.
    Simple,
    /// Exclusive children: exactly one is active while the node is.
    Or {
        /// Children in declaration order.
        children: Vec<StateId>,
        /// Index into `children` of the default child.
        initial: usize,
        /// History kind, if any.
        history: Option<HistoryKind>,
    },
    /// Parallel regions: all active while the node is; each region is itself an `Or` node.
    And {
        /// Regions in execution order.
        regions: Vec<StateId>,
    },
}

/// A state, a region, or the chart root.
#[derive(Clone, Debug)]
pub struct StateNode {
    /// Its name (`""` for the root).
    pub name: String,
    /// Dotted path from the root, e.g. `Go.Pause` (`""` for the root).
    pub path: String,
    /// True for a region of a parallel state.
    pub is_region: bool,
    /// The parent node (`None` for the root).
    pub parent: Option<StateId>,
    /// Decomposition.
    pub kind: NodeKind,
    /// Entry actions.
    pub entry: Vec<Stmt>,
    /// During actions.
    pub during: Vec<Stmt>,
    /// Exit actions.
    pub exit: Vec<Stmt>,
    /// Action of the default (`initial`) transition of an `Or` node.
    pub initial_action: Vec<Stmt>,
    /// Outgoing transitions in firing order (priority, then text order).
    pub transitions: Vec<TransId>,
    /// Written `marked state`: an accepting state for synthesis.
    pub marked: bool,
    /// Where it was declared (its name).
    pub span: Span,
}

/// A trigger of a transition.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Trigger {
    /// Guard-only.
    None,
    /// An event variable.
    Event(VarId),
    /// After this many ticks in the source state (at least 1).
    After(i64),
}

/// A transition's destination after choices are resolved.
#[derive(Clone, Debug)]
pub enum Dest {
    /// No target: an internal transition.
    Internal,
    /// A state.
    State(StateId),
    /// A choice: the first branch whose guard holds (and whose own destination is valid) is taken.
    Choice(Vec<Branch>),
}

/// One branch of a choice point.
#[derive(Clone, Debug)]
pub struct Branch {
    /// Its guard (`None` for `else`).
    pub guard: Option<Expr>,
    /// Its action.
    pub action: Vec<Stmt>,
    /// Where it leads.
    pub dest: Dest,
    /// Where it was written.
    pub span: Span,
}

/// A checked transition.
#[derive(Clone, Debug)]
pub struct Transition {
    /// The state that owns it.
    pub source: StateId,
    /// Its trigger.
    pub trigger: Trigger,
    /// Its guard.
    pub guard: Option<Expr>,
    /// Its action.
    pub action: Vec<Stmt>,
    /// Its destination.
    pub dest: Dest,
    /// Explicit priority if written.
    pub priority: Option<i64>,
    /// Where it was written.
    pub span: Span,
}

/// A checked statement.
#[derive(Clone, Debug)]
pub enum Stmt {
    /// `var = expr`; `checked` is false when the value's bounds already fit the variable.
    Assign {
        /// The variable.
        var: VarId,
        /// The value.
        value: Expr,
        /// Whether a run-time range check is needed.
        checked: bool,
        /// Where.
        span: Span,
    },
    /// `raise e`
    Raise {
        /// The event.
        event: VarId,
        /// Where.
        span: Span,
    },
    /// `if c { } else { }`
    If {
        /// Condition.
        cond: Expr,
        /// Then branch.
        then: Vec<Stmt>,
        /// Else branch.
        otherwise: Vec<Stmt>,
    },
}

/// A reference to a variable: of the enclosing chart instance, or of a named instance in a
/// system-level expression.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VarRef {
    /// Flat instance index in the system, or `None` for "this instance".
    pub instance: Option<u32>,
    /// The variable in that instance's chart.
    pub var: VarId,
}

/// A reference to a state of this or of a named instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StateRef {
    /// Flat instance index, or `None` for "this instance".
    pub instance: Option<u32>,
    /// The state in that instance's chart.
    pub state: StateId,
}

/// Built-in functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    /// `min(a, b)`
    Min,
    /// `max(a, b)`
    Max,
    /// `abs(a)`
    Abs,
}

/// A typed expression. Function calls are inlined by the checker: the IR never sees them.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What it computes.
    pub kind: ExprKind,
    /// Its type (integer bounds by interval arithmetic).
    pub ty: Type,
    /// Where it was written.
    pub span: Span,
}

/// The forms of a typed expression.
#[derive(Clone, Debug)]
pub enum ExprKind {
    /// A constant (integer, bool as 0/1, enum as index).
    Const(i64),
    /// A variable's current value (an event: 1 when present).
    Var(VarRef),
    /// `in(state)`.
    In(StateRef),
    /// A unary operation.
    Unary(UnOp, Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `if c then a else b`.
    If(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `min`, `max`, `abs`.
    Builtin(Builtin, Vec<Expr>),
    /// A value that must lie in `lo..=hi` (function parameters and results); a run-time
    /// error otherwise.
    Check(Box<Expr>, i64, i64, String),
    /// `let local = value in body`: an inlined function's argument (or `let`), evaluated once.
    Let(u32, Box<Expr>, Box<Expr>),
    /// The value bound by the enclosing [`ExprKind::Let`] with this id.
    Local(u32),
}

/// A checked property.
#[derive(Clone, Debug)]
pub struct Property {
    /// Its name.
    pub name: String,
    /// What it states.
    pub kind: PropertyKind,
    /// Where it was declared.
    pub span: Span,
}

/// The forms of a property.
#[derive(Clone, Debug)]
pub enum PropertyKind {
    /// Holds in every reachable state where `assuming` holds.
    Invariant {
        /// The invariant.
        expr: Expr,
        /// The restriction.
        assuming: Option<Expr>,
    },
    /// Some reachable state satisfies `expr`.
    Reachable {
        /// The target condition.
        expr: Expr,
    },
    /// Whenever `trigger` holds, `response` holds within `within` ticks.
    Respond {
        /// The trigger condition.
        trigger: Expr,
        /// The response condition.
        response: Expr,
        /// The bound in ticks.
        within: i64,
    },
    /// Whenever `trigger` holds, `response` holds then or later (`respond` without a bound).
    RespondEventually {
        /// The trigger condition.
        trigger: Expr,
        /// The response condition.
        response: Expr,
    },
    /// An LTL formula every run satisfies.
    Ltl(crate::formula::Formula),
    /// A CTL formula every initial state satisfies.
    Ctl(crate::formula::Formula),
    /// From every reachable state, a state where `expr` holds stays reachable.
    Nonblocking {
        /// The marked condition.
        expr: Expr,
    },
    /// A fairness constraint on the runs temporal properties speak of: `expr` holds infinitely
    /// often (justice), or, with a `trigger`, if `trigger` holds infinitely often (compassion).
    Fair {
        /// The compassion trigger.
        trigger: Option<Expr>,
        /// What must hold infinitely often.
        expr: Expr,
    },
}

/// One chart instance of a system (instance arrays are flattened: `fam[0]`, `fam[1]`, ...).
#[derive(Clone, Debug)]
pub struct Instance {
    /// Display name, e.g. `fam[2]`.
    pub name: String,
    /// The chart.
    pub chart: ChartId,
    /// Its index when it is an element of an instance array (`name[index]`).
    pub index: Option<u32>,
    /// Event renames (`instance p1: Phil { take -> take1; }`): the chart's event variable and
    /// its name in synthesis. Only synthesis reads them (events synchronise by name there);
    /// the tick semantics is unchanged.
    pub renames: Vec<EventRename>,
    /// Where it was declared.
    pub span: Span,
}

/// One checked entry of an instance's rename block.
#[derive(Clone, Debug)]
pub struct EventRename {
    /// The chart's event (a variable declared `controllable event` or `uncontrollable event`).
    pub var: VarId,
    /// Its name for this instance.
    pub name: String,
    /// Where the entry was written.
    pub span: Span,
}

/// `connect from -> to` after flattening: `to` (an input) reads `from`.
#[derive(Clone, Debug)]
pub struct Connection {
    /// Source instance and variable.
    pub from: (u32, VarId),
    /// Destination instance and input.
    pub to: (u32, VarId),
    /// Where it was written.
    pub span: Span,
}

/// `rate instance.input = P;` after flattening (one per instance of `instance[*].input`).
#[derive(Clone, Debug)]
pub struct InputRate {
    /// The instance.
    pub instance: u32,
    /// Its input (a boolean or an event, not driven by a connection).
    pub var: VarId,
    /// The probability of `true` (or presence) per tick, from 0 to 1.
    pub rate: f64,
    /// The declaration.
    pub span: Span,
}

/// A checked system: flat instances, connections, execution order, assumptions, properties.
#[derive(Clone, Debug)]
pub struct System {
    /// Its name.
    pub name: String,
    /// True when synthesised for a file's single chart (no `system` written).
    pub implicit: bool,
    /// Instances (observers last).
    pub instances: Vec<Instance>,
    /// Connections.
    pub connections: Vec<Connection>,
    /// Execution order: indices into `instances`, each exactly once (observers last).
    pub order: Vec<u32>,
    /// Constraints on free inputs, evaluated every tick.
    pub assumes: Vec<Expr>,
    /// `rate` declarations: how often random simulation makes a free boolean input true.
    pub rates: Vec<InputRate>,
    /// Properties (system-level, then each instance's chart properties).
    pub properties: Vec<Property>,
    /// State-based synthesis requirements (`docs/synthesis.md`).
    pub requirements: Vec<Requirement>,
    /// `system S interleaved { … }`: which unit each instance belongs to; `None` for the
    /// synchronous default.
    pub interleaved: Option<Interleaving>,
    /// Where it was declared.
    pub span: Span,
}

/// Interleaved composition (`docs/components.md`): in each tick only the unit the scheduler
/// input names steps.
#[derive(Clone, Debug)]
pub struct Interleaving {
    /// The scheduler instance; its only variable, `unit`, is the free input naming the unit.
    pub scheduler: u32,
    /// Each instance's unit (`None` for the scheduler and observers, which step every tick).
    pub unit: Vec<Option<u32>>,
    /// Each unit's name (`ctrl`, `storage`, `fam[0]`), in execution order.
    pub units: Vec<String>,
}

/// A checked state-based synthesis requirement.
#[derive(Clone, Debug)]
pub struct Requirement {
    /// What it requires.
    pub kind: RequirementKind,
    /// Where it was written.
    pub span: Span,
}

/// The kinds of [`Requirement`].
#[derive(Clone, Debug)]
pub enum RequirementKind {
    /// `requirement never (cond);`: no reachable state satisfies `cond`.
    Never(Expr),
    /// `requirement e needs (cond);`: event `e` may occur only where `cond` holds. Events
    /// synchronise by name across the system's automata, so the event stays a name.
    Needs {
        /// The event's name.
        event: String,
        /// Where the event was written.
        event_span: Span,
        /// The condition.
        cond: Expr,
    },
}

impl Model {
    /// Number of literals of an enum.
    pub fn enum_len(&self, e: EnumId) -> usize {
        self.enums.get(e as usize).map_or(1, |d| d.variants.len())
    }

    /// Inclusive value bounds of a type.
    pub fn bounds(&self, ty: Type) -> (i64, i64) {
        ty.bounds(|e| self.enum_len(e))
    }

    /// Render a value of a type for people: `true`, `42`, `NORMAL_RUN`.
    pub fn format_value(&self, ty: Type, v: i64) -> String {
        match ty {
            Type::Bool => (v != 0).to_string(),
            Type::Int { .. } => v.to_string(),
            Type::Enum(e) => self
                .enums
                .get(e as usize)
                .and_then(|d| d.variants.get(v as usize))
                .cloned()
                .unwrap_or_else(|| v.to_string()),
        }
    }

    /// Find a system by name.
    pub fn system(&self, name: &str) -> Option<&System> {
        self.systems.iter().find(|s| s.name == name)
    }
}

impl Chart {
    /// Find a variable by name.
    pub fn var(&self, name: &str) -> Option<VarId> {
        self.vars
            .iter()
            .position(|v| v.name == name)
            .map(|i| i as VarId)
    }

    /// Find a state by dotted path from the root (`""` is the root).
    pub fn state_by_path(&self, path: &str) -> Option<StateId> {
        self.states
            .iter()
            .position(|s| s.path == path)
            .map(|i| i as StateId)
    }

    /// The chain of nodes from the root down to `s`, inclusive.
    pub fn ancestry(&self, s: StateId) -> Vec<StateId> {
        let mut chain = vec![s];
        let mut cur = s;
        while let Some(p) = self.states[cur as usize].parent {
            chain.push(p);
            cur = p;
        }
        chain.reverse();
        chain
    }

    /// True for the top-level state `error` of an observer: entering it is the observer's
    /// property violated, so it is meant never to be entered (not dead design, not a
    /// coverage gap; docs/lints.md).
    pub fn is_observer_error(&self, s: StateId) -> bool {
        self.role == ChartRole::Observer
            && self
                .states
                .get(s as usize)
                .is_some_and(|n| n.parent == Some(0) && n.name == "error")
    }

    /// True when `a` is `d` or one of its ancestors.
    pub fn is_ancestor_or_self(&self, a: StateId, d: StateId) -> bool {
        let mut cur = Some(d);
        while let Some(c) = cur {
            if c == a {
                return true;
            }
            cur = self.states[c as usize].parent;
        }
        false
    }
}
