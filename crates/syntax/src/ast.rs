//! The abstract syntax tree of a `.sc` file, exactly as written, with spans.
//!
//! Nothing here is resolved: names are identifiers, types are as spelled. The `model` crate
//! resolves and checks them. Every node that a diagnostic may point at carries a [`Span`].

use statecheck_base::Span;

pub use crate::formula::{Formula, Quant, TempBin, TempOp};
pub use hybrid::{HybridElem, Speed, SpeedExpr, SpeedNumber};

mod hybrid;
pub mod visit_mut;

/// An identifier with its span.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ident {
    /// The name as written.
    pub name: String,
    /// Where it was written.
    pub span: Span,
}

/// A whole source file: a list of top-level items in textual order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct File {
    /// Items in textual order.
    pub items: Vec<Item>,
}

/// A top-level declaration.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// `const NAME[: type] = expr;`
    Const(ConstDecl),
    /// `enum Name { A, B }`
    Enum(EnumDecl),
    /// `fn name(p: T, ...) -> T { let x = e; ... return e; }` or `fn f(..) -> T = e;`
    Fn(FnDecl),
    /// `chart Name { ... }`
    Chart(Chart),
    /// `system Name { ... }`
    System(System),
    /// `tick 100 ms;` — the duration of one tick, enabling `after(3 s)`.
    Tick(TickDecl),
    /// `import "path.sc";` or `import "path.sc" { A, B };` — resolved before checking
    /// (`statecheck_model::imports`); the checker itself ignores it.
    Import(ImportDecl),
    /// `interface Name { input x: T; output event e; … }` (`docs/components.md`).
    Interface(InterfaceDecl),
    /// `component Name [implements I] { ports; instances; connections; … }`: a composite
    /// component, flattened into its instances before checking (`docs/components.md`).
    Component(Component),
}

/// `component Name[(params)] [implements I, …] { port; … instance …; connect …; … }`: a
/// composite component with a declared interface (its ports) built from instances.
#[derive(Clone, Debug, PartialEq)]
pub struct Component {
    /// The component's name.
    pub name: Ident,
    /// Compile-time parameters, `component Storage(n: int) { … }`, like a chart's; empty
    /// without a parameter list. Instances give arguments (`docs/components.md`).
    pub params: Vec<ChartParam>,
    /// The interfaces it declares it implements.
    pub implements: Vec<Ident>,
    /// Its ports: `input`/`output` variables and events (no initial values).
    pub ports: Vec<VarDecl>,
    /// Its contents, as a system body: instances, connections, `order`, assumptions, rates
    /// and properties (`body.name` is the component's name).
    pub body: System,
    /// The whole declaration.
    pub span: Span,
}

/// `interface Name { member; … }`: the ports a chart that implements it must declare.
#[derive(Clone, Debug, PartialEq)]
pub struct InterfaceDecl {
    /// The interface's name.
    pub name: Ident,
    /// Its ports: `input`/`output` variables and events (initial values are not allowed).
    pub members: Vec<VarDecl>,
    /// The whole declaration.
    pub span: Span,
}

/// `import "path.sc" [ '{' IDENT { ',' IDENT } '}' ] ';'`
#[derive(Clone, Debug, PartialEq)]
pub struct ImportDecl {
    /// The path as written, without the quotes.
    pub path: String,
    /// Where the quoted path is.
    pub path_span: Span,
    /// The names brought in explicitly, if a list was given.
    pub names: Option<Vec<Ident>>,
    /// The whole declaration.
    pub span: Span,
}

/// `const NAME[: type] = expr;`
#[derive(Clone, Debug, PartialEq)]
pub struct ConstDecl {
    /// The constant's name.
    pub name: Ident,
    /// Declared type, if given (`int`, `bool`, an enum, or a bounded int).
    pub ty: Option<TypeExpr>,
    /// Its value; must be a constant expression.
    pub value: Expr,
    /// The whole declaration.
    pub span: Span,
}

/// `enum Name { A, B, C }`
#[derive(Clone, Debug, PartialEq)]
pub struct EnumDecl {
    /// The enum's name.
    pub name: Ident,
    /// Its literals in order; the first has value 0.
    pub variants: Vec<Ident>,
    /// The whole declaration.
    pub span: Span,
}

/// A pure function; its body is a list of `let` bindings and a final `return`.
#[derive(Clone, Debug, PartialEq)]
pub struct FnDecl {
    /// The function's name.
    pub name: Ident,
    /// Parameters in order.
    pub params: Vec<Param>,
    /// Return type.
    pub ret: TypeExpr,
    /// `let name = expr;` bindings, in order.
    pub lets: Vec<(Ident, Expr)>,
    /// The returned expression.
    pub body: Expr,
    /// The whole declaration.
    pub span: Span,
}

/// A function parameter `name: type`.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// Parameter name.
    pub name: Ident,
    /// Parameter type.
    pub ty: TypeExpr,
}

/// `tick 100 ms;`
#[derive(Clone, Debug, PartialEq)]
pub struct TickDecl {
    /// The length of one tick.
    pub duration: Duration,
    /// The whole declaration.
    pub span: Span,
}

/// A literal duration such as `3 s` or `250 ms`.
#[derive(Clone, Debug, PartialEq)]
pub struct Duration {
    /// The number as written (must be a constant expression).
    pub amount: Box<Expr>,
    /// The unit.
    pub unit: TimeUnit,
    /// Where.
    pub span: Span,
}

/// Units of a [`Duration`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeUnit {
    /// Milliseconds.
    Ms,
    /// Seconds.
    S,
    /// Minutes.
    Min,
}

/// A type as written.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeExpr {
    /// `bool`
    Bool(Span),
    /// `int` without bounds (only for constants and function-local arithmetic).
    Int(Span),
    /// `int[lo..hi]`, bounds inclusive and constant.
    Range {
        /// Lower bound.
        lo: Box<Expr>,
        /// Upper bound (inclusive).
        hi: Box<Expr>,
        /// Whole type.
        span: Span,
    },
    /// An enum's name.
    Named(Ident),
}

impl TypeExpr {
    /// Where the type was written.
    pub fn span(&self) -> Span {
        match self {
            TypeExpr::Bool(s) | TypeExpr::Int(s) => *s,
            TypeExpr::Range { span, .. } => *span,
            TypeExpr::Named(i) => i.span,
        }
    }
}

/// A chart: a reusable statechart type with an interface, local variables and a state hierarchy.
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    /// The chart's name.
    pub name: Ident,
    /// `plant`/`requirement`/`observer` and similar role keywords before `chart` (later issues).
    pub role: Option<Ident>,
    /// Compile-time parameters, `chart Sensor(lo: int, hi: int = 5) { … }`; empty for a chart
    /// without a parameter list. Instances give arguments; the model substitutes them.
    pub params: Vec<ChartParam>,
    /// `implements A, B`: the interfaces the chart declares it conforms to.
    pub implements: Vec<Ident>,
    /// Variable and event declarations in textual order.
    pub vars: Vec<VarDecl>,
    /// The chart's top level, which is a state body without a name.
    pub body: StateBody,
    /// Properties stated inside the chart; they hold for every instance.
    pub properties: Vec<Property>,
    /// The whole chart.
    pub span: Span,
}

/// A chart parameter `name: type [= default]`: a constant fixed by each instance.
#[derive(Clone, Debug, PartialEq)]
pub struct ChartParam {
    /// The parameter's name.
    pub name: Ident,
    /// Its type: `int`, `int[lo..hi]`, `bool` or an enum.
    pub ty: TypeExpr,
    /// The value used when an instance gives no argument for it.
    pub default: Option<Expr>,
    /// The whole declaration.
    pub span: Span,
}

/// Who may write a variable and who sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarKind {
    /// Written by the environment or a connection; read-only inside the chart.
    Input,
    /// Written by the chart; visible to connections and properties.
    Output,
    /// Written and read only by the chart.
    Local,
}

/// `input x: T [= init];`, `output event e;`, `local n: T = 0;` ...
#[derive(Clone, Debug, PartialEq)]
pub struct VarDecl {
    /// Input, output or local.
    pub kind: VarKind,
    /// True for `event` declarations (present or absent in each tick).
    pub is_event: bool,
    /// The name.
    pub name: Ident,
    /// `input rm[N]: T;`: an array of `N` variables `rm[0]` … `rm[N-1]` (a constant length,
    /// expanded before checking, `docs/language.md` §5); `None` for a scalar.
    pub len: Option<Expr>,
    /// The type (absent for events).
    pub ty: Option<TypeExpr>,
    /// Initial value; for inputs, the value used before any scenario sets one.
    pub init: Option<Expr>,
    /// `controllable event e;` / `uncontrollable event u;` (synthesis, `docs/synthesis.md`):
    /// an input event with a controllability; `None` for every other declaration.
    pub control: Option<Control>,
    /// The whole declaration.
    pub span: Span,
}

/// Whether a supervisor may disable an event (`docs/synthesis.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Control {
    /// `controllable event e;`: the supervisor may disable it.
    Controllable,
    /// `uncontrollable event u;`: the supervisor can never disable it.
    Uncontrollable,
}

/// The inside of a state (or of a chart, or of a region): actions, children, transitions.
///
/// A body with `states` is an exclusive (OR) composite; a body with `regions` is a parallel
/// (AND) composite; a body with neither is a simple state. Having both is a checker error.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StateBody {
    /// `entry { ... }` blocks (normally at most one).
    pub entry: Vec<Block>,
    /// `during { ... }` blocks.
    pub during: Vec<Block>,
    /// `exit { ... }` blocks.
    pub exit: Vec<Block>,
    /// `initial NAME [/ { actions }];` declarations (the checker demands exactly one for OR states).
    pub initial: Vec<Initial>,
    /// `history shallow;` / `history deep;`
    pub history: Vec<History>,
    /// Child states in textual order.
    pub states: Vec<State>,
    /// Parallel regions in textual (= execution) order.
    pub regions: Vec<Region>,
    /// Named junctions (choice points) declared here.
    pub junctions: Vec<Junction>,
    /// Outgoing transitions of this state, in textual order.
    pub transitions: Vec<Transition>,
    /// Continuous-variable elements (`continuous`, `grid`, `sensor` at chart level, `der` in
    /// states; `docs/hybrid.md`), in textual order. The checker discretizes them away.
    pub hybrid: Vec<HybridElem>,
}

/// `initial NAME [/ { actions }];`
#[derive(Clone, Debug, PartialEq)]
pub struct Initial {
    /// The default child.
    pub target: Ident,
    /// Actions of the default transition.
    pub action: Option<Block>,
    /// Whole declaration.
    pub span: Span,
}

/// History kinds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HistoryKind {
    /// Re-enter the most recently active child; its own default entry below.
    Shallow,
    /// Re-enter the most recently active configuration of the whole subtree.
    Deep,
}

/// `history shallow;` or `history deep;`
#[derive(Clone, Debug, PartialEq)]
pub struct History {
    /// Which kind.
    pub kind: HistoryKind,
    /// Where.
    pub span: Span,
}

/// `state NAME { body }`
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// The state's name.
    pub name: Ident,
    /// Written `marked state NAME …`: an accepting state for synthesis.
    pub marked: bool,
    /// Its inside.
    pub body: StateBody,
    /// Whole state.
    pub span: Span,
}

/// `region NAME { body }` inside a parallel state (or `parallel { ... }` at chart level).
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    /// The region's name (a path component of `in(...)`).
    pub name: Ident,
    /// Its inside; an exclusive composite.
    pub body: StateBody,
    /// Whole region.
    pub span: Span,
}

/// `junction NAME { branches }`: a named choice point that several transitions may target.
#[derive(Clone, Debug, PartialEq)]
pub struct Junction {
    /// The junction's name.
    pub name: Ident,
    /// Its branches in priority order.
    pub branches: Vec<Branch>,
    /// Whole junction.
    pub span: Span,
}

/// One outgoing branch of a choice: `[guard] / { action } -> target;` or `else -> target;`.
#[derive(Clone, Debug, PartialEq)]
pub struct Branch {
    /// The guard; `None` for `else`.
    pub guard: Option<Expr>,
    /// Action run when the branch is taken.
    pub action: Option<Block>,
    /// Where the branch leads.
    pub target: Target,
    /// Whole branch.
    pub span: Span,
}

/// `on TRIGGER [GUARD] / { ACTION } -> TARGET priority N;` (each part optional).
#[derive(Clone, Debug, PartialEq)]
pub struct Transition {
    /// The trigger; `None` for guard-only (change) triggers.
    pub trigger: Option<Trigger>,
    /// The guard.
    pub guard: Option<Expr>,
    /// The transition action.
    pub action: Option<Block>,
    /// The target; `None` makes an internal transition (no exit, no entry).
    pub target: Option<Target>,
    /// Explicit priority (1 is highest), if given.
    pub priority: Option<(i64, Span)>,
    /// Whole transition.
    pub span: Span,
}

/// What makes a transition enabled, besides its guard.
#[derive(Clone, Debug, PartialEq)]
pub enum Trigger {
    /// An input or local event.
    Event(Ident),
    /// `after(n)` ticks, or `after(3 s)` with a declared tick length.
    After {
        /// The delay: a constant tick count, or a duration.
        delay: Delay,
        /// Whole trigger.
        span: Span,
    },
}

/// The delay of an `after` trigger.
#[derive(Clone, Debug, PartialEq)]
pub enum Delay {
    /// A constant expression in ticks.
    Ticks(Expr),
    /// A duration, converted with the file's `tick` declaration.
    Time(Duration),
}

/// Where a transition or branch leads.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    /// A state or junction by (possibly dotted) path, resolved relative to the source.
    Path(Path),
    /// An inline choice: `-> choice { [c1] -> A; else -> B; }`.
    Choice {
        /// Branches in priority order.
        branches: Vec<Branch>,
        /// Whole choice.
        span: Span,
    },
}

/// A dotted path of names, e.g. `move.running` or `fam[0].move.running`.
#[derive(Clone, Debug, PartialEq)]
pub struct Path {
    /// The components in order.
    pub segments: Vec<PathSegment>,
    /// Whole path.
    pub span: Span,
}

/// One component of a [`Path`]: a name with an optional index (`fam[2]`).
#[derive(Clone, Debug, PartialEq)]
pub struct PathSegment {
    /// The name.
    pub name: Ident,
    /// `[index]` if present; `[*]` is `Some(Index::All)`.
    pub index: Option<Index>,
}

/// An index in a path segment.
#[derive(Clone, Debug, PartialEq)]
pub enum Index {
    /// A constant index expression.
    At(Box<Expr>),
    /// `[*]`: every element (only in `connect` fan-out).
    All(Span),
}

/// `{ stmt; stmt; }`
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Block {
    /// Statements in order.
    pub stmts: Vec<Stmt>,
    /// Whole block including braces.
    pub span: Span,
}

/// A statement in an action.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `x = e;` (also `x += e;` / `x -= e;`, desugared by the parser into `x = x + e`).
    Assign {
        /// The variable written.
        target: Ident,
        /// `rm[k] = e;`: the element of an array variable written (a compile-time constant,
        /// expanded before checking); `None` for a scalar.
        index: Option<Box<Expr>>,
        /// The value.
        value: Expr,
        /// Whole statement.
        span: Span,
    },
    /// `raise e;`
    Raise {
        /// The event.
        event: Ident,
        /// Whole statement.
        span: Span,
    },
    /// `if c { ... } else if d { ... } else { ... }`
    If {
        /// The condition.
        cond: Expr,
        /// Statements when true.
        then: Block,
        /// Statements when false (an `else if` is a block holding one `If`).
        otherwise: Option<Block>,
        /// Whole statement.
        span: Span,
    },
    /// `for k in lo..hi { … }`: a compile-time loop, unrolled before checking with `k` bound
    /// to `lo`, …, `hi - 1` (`docs/language.md` §8).
    For {
        /// The loop variable.
        var: Ident,
        /// The first value (a constant expression).
        lo: Box<Expr>,
        /// One past the last value (a constant expression).
        hi: Box<Expr>,
        /// The body, repeated once per value.
        body: Block,
        /// Whole statement.
        span: Span,
    },
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnOp {
    /// `-x`
    Neg,
    /// `!b`
    Not,
    /// `~x` (bitwise complement)
    BitNot,
}

/// Binary operators, loosest to tightest: `||`, `&&`, comparisons, `|`, `^`, `&`, shifts,
/// `+ -`, `* / %`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// `||`
    Or,
    /// `&&`
    And,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `|`
    BitOr,
    /// `^`
    BitXor,
    /// `&`
    BitAnd,
    /// `<<`
    Shl,
    /// `>>`
    Shr,
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/` (truncates toward zero)
    Div,
    /// `%` (remainder with the sign of the dividend)
    Rem,
}

/// An expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An integer literal (decimal, `0x..` hex or `0b..` binary).
    Int(i64, Span),
    /// `true` / `false`.
    Bool(bool, Span),
    /// A name or dotted path: variable, constant, enum literal (`RED` or `Color.RED`), or an
    /// instance-qualified variable in system properties (`fam[0].stall`).
    Path(Path),
    /// `in(path)`: true while the state at `path` is active.
    In(Path, Span),
    /// A call to `min`, `max`, `abs` or a declared function.
    Call {
        /// Function name.
        func: Ident,
        /// Arguments.
        args: Vec<Expr>,
        /// Whole call.
        span: Span,
    },
    /// A unary operation.
    Unary(UnOp, Box<Expr>, Span),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>, Span),
    /// `if c then a else b`
    If(Box<Expr>, Box<Expr>, Box<Expr>, Span),
    /// Placeholder produced by error recovery; the checker ignores it silently.
    Error(Span),
}

impl Expr {
    /// Where the expression was written.
    pub fn span(&self) -> Span {
        match self {
            Expr::Int(_, s) | Expr::Bool(_, s) | Expr::In(_, s) | Expr::Error(s) => *s,
            Expr::Path(p) => p.span,
            Expr::Call { span, .. }
            | Expr::Unary(_, _, span)
            | Expr::Binary(_, _, _, span)
            | Expr::If(_, _, _, span) => *span,
        }
    }
}

/// `system Name { instances, connections, order, assumes, properties, observers }`
#[derive(Clone, Debug, PartialEq)]
pub struct System {
    /// The system's name.
    pub name: Ident,
    /// `instance name: Chart;` / `instance name[N]: Chart;`
    pub instances: Vec<Instance>,
    /// `connect a.x -> b.y;`
    pub connections: Vec<Connection>,
    /// `order a, b, c;` (at most one; default: instance declaration order)
    pub order: Vec<OrderDecl>,
    /// `assume expr;` constraints on the free inputs of every tick.
    pub assumes: Vec<Assume>,
    /// `rate instance.input = 0.01;` how often random simulation makes an input true.
    pub rates: Vec<Rate>,
    /// Properties (issue 3).
    pub properties: Vec<Property>,
    /// Observer (assertion) charts declared inline: `observer Name { ...chart body... }`.
    pub observers: Vec<Chart>,
    /// State-based synthesis requirements: `requirement never (…);`, `requirement e needs (…);`.
    pub requirements: Vec<StateRequirement>,
    /// `configuration NAME { inst = Chart(args); … }`: named choices of charts and arguments.
    pub configurations: Vec<Configuration>,
    /// `system NAME interleaved { … }`: one top-level instance steps per tick, chosen by the
    /// implicit scheduler input `sched.unit` (`docs/components.md`); false for the
    /// synchronous default (and for a component's body).
    pub interleaved: bool,
    /// Whole system.
    pub span: Span,
}

/// `configuration NAME { binding … }` inside a system (`docs/components.md`).
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    /// The configuration's name.
    pub name: Ident,
    /// The instances it binds, in order.
    pub bindings: Vec<Binding>,
    /// Whole declaration.
    pub span: Span,
}

/// `inst = Chart(args);` in a configuration: the chart (and arguments) an instance gets.
#[derive(Clone, Debug, PartialEq)]
pub struct Binding {
    /// The instance (or slot) bound.
    pub instance: Ident,
    /// The chart it gets.
    pub chart: Ident,
    /// The chart's arguments.
    pub args: Vec<Arg>,
    /// Whole binding.
    pub span: Span,
}

/// A state-based requirement for supervisor synthesis (`docs/synthesis.md`).
#[derive(Clone, Debug, PartialEq)]
pub struct StateRequirement {
    /// What it demands.
    pub kind: RequirementKind,
    /// Whole declaration.
    pub span: Span,
}

/// The kinds of [`StateRequirement`].
#[derive(Clone, Debug, PartialEq)]
pub enum RequirementKind {
    /// `requirement never (cond);`: no reachable state satisfies `cond`.
    Never(Expr),
    /// `requirement e needs (cond);`: event `e` may occur only where `cond` holds.
    Needs {
        /// The event.
        event: Ident,
        /// The condition on the state before the event.
        cond: Expr,
    },
}

/// `instance name: Chart;` or `instance name[N]: Chart;`
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    /// Instance name.
    pub name: Ident,
    /// Array length, if an instance array.
    pub count: Option<Expr>,
    /// The chart it instantiates.
    pub chart: Ident,
    /// The arguments of a parameterised chart, `: Sensor(0, hi = 5)`, in order.
    pub args: Vec<Arg>,
    /// Event renames of a synthesis instance, `: Phil { take -> take1; }`, in order
    /// (docs/synthesis.md, "Event renaming").
    pub renames: Vec<Rename>,
    /// Whole declaration.
    pub span: Span,
}

/// `event -> name;` in an instance's rename block: the chart's event `event` is known as
/// `name` in synthesis (where events synchronise by name).
#[derive(Clone, Debug, PartialEq)]
pub struct Rename {
    /// The chart's event.
    pub event: Ident,
    /// Its name for this instance.
    pub to: Ident,
    /// The whole entry.
    pub span: Span,
}

/// One argument of an instance: positional (`5`) or named (`hi = 5`).
#[derive(Clone, Debug, PartialEq)]
pub struct Arg {
    /// The parameter's name for a named argument.
    pub name: Option<Ident>,
    /// The value; must be a constant expression.
    pub value: Expr,
    /// The whole argument.
    pub span: Span,
}

/// `connect from -> to;` — `to` (an input) reads `from` (an output) from then on.
#[derive(Clone, Debug, PartialEq)]
pub struct Connection {
    /// Source: `instance.output`.
    pub from: Path,
    /// Destination: `instance.input` (may use `[*]` to fan out).
    pub to: Path,
    /// Whole declaration.
    pub span: Span,
}

/// `order a, b, c;`
#[derive(Clone, Debug, PartialEq)]
pub struct OrderDecl {
    /// Instance names (arrays run element 0 first).
    pub instances: Vec<Ident>,
    /// Whole declaration.
    pub span: Span,
}

/// `assume expr;`
#[derive(Clone, Debug, PartialEq)]
pub struct Assume {
    /// The constraint, over free inputs and state.
    pub expr: Expr,
    /// Whole declaration.
    pub span: Span,
}

/// `rate instance.input = 0.01;`: the probability that random simulation makes a free boolean
/// input true (an input event present) in a tick, beside the `assume`s.
#[derive(Clone, Debug, PartialEq)]
pub struct Rate {
    /// The input: `instance.input`, `instance[i].input` or `instance[*].input`.
    pub target: Path,
    /// The probability as written (a decimal literal such as `0.01`, or `0`/`1`).
    pub value: String,
    /// Where the probability is written.
    pub value_span: Span,
    /// Whole declaration.
    pub span: Span,
}

/// The kinds of property.
#[derive(Clone, Debug, PartialEq)]
pub enum PropertyKind {
    /// `invariant NAME: expr [assuming expr];`
    Invariant {
        /// Must hold in every reachable state.
        expr: Expr,
        /// Only states where this holds are checked.
        assuming: Option<Expr>,
    },
    /// `reachable NAME: expr;`
    Reachable {
        /// Some reachable state satisfies it.
        expr: Expr,
    },
    /// `respond NAME: trigger => response within N;` (or `within 2 s` with a declared tick)
    Respond {
        /// When this holds ...
        trigger: Expr,
        /// ... this must hold within `within` ticks (0 = the same tick).
        response: Expr,
        /// The bound: a constant tick count, or a duration converted with the file's `tick`.
        within: Delay,
    },
    /// `respond NAME: trigger => response;` (no bound: the response must come eventually).
    RespondEventually {
        /// When this holds ...
        trigger: Expr,
        /// ... this must hold then or later.
        response: Expr,
    },
    /// `ltl NAME: formula;`
    Ltl {
        /// The LTL formula every run must satisfy.
        formula: Formula,
    },
    /// `ctl NAME: formula;`
    Ctl {
        /// The CTL formula the initial states must satisfy.
        formula: Formula,
    },
    /// `nonblocking NAME: expr;` (from every reachable state a state where `expr` holds
    /// stays reachable: `AG EF expr`).
    Nonblocking {
        /// The marked condition.
        expr: Expr,
    },
    /// `fair NAME: expr;` (justice) or `fair NAME: trigger => expr;` (compassion): a fairness
    /// constraint on the runs the temporal properties speak of.
    Fair {
        /// For compassion: runs where this holds infinitely often ...
        trigger: Option<Expr>,
        /// ... (or every run, for justice) must have this hold infinitely often.
        expr: Expr,
    },
}

/// A named property.
#[derive(Clone, Debug, PartialEq)]
pub struct Property {
    /// Its name (part of the verification contract).
    pub name: Ident,
    /// What it says.
    pub kind: PropertyKind,
    /// Whole declaration.
    pub span: Span,
}
