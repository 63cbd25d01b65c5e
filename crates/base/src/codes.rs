//! The table of diagnostic codes: one entry per stable code, with a title and an explanation.
//!
//! This is the one source of `statecheck explain CODE` and of the index `docs/diagnostics.md`
//! (generated from it by [`markdown_index`]; a test compares the file and fails when they
//! differ, and another fails when a code emitted anywhere in the sources has no entry).
//! Codes are a contract: an entry keeps its meaning forever and is never reused.

/// One diagnostic code.
#[derive(Clone, Copy, Debug)]
pub struct CodeInfo {
    /// The code, e.g. `E0111`.
    pub code: &'static str,
    /// A short title.
    pub title: &'static str,
    /// What it means and what to do.
    pub explanation: &'static str,
    /// The document under `docs/` that describes the construct.
    pub doc: &'static str,
}

const fn code(
    code: &'static str,
    title: &'static str,
    explanation: &'static str,
    doc: &'static str,
) -> CodeInfo {
    CodeInfo {
        code,
        title,
        explanation,
        doc,
    }
}

/// Every code: errors of the parser (E00xx) and of the checker (E01xx), warnings of the
/// checker (W02xx) and of the design-rule lints (W03xx), errors of synthesis (E07xx), of
/// scenario files (E08xx) and of external tools (E09xx).
pub const CODES: &[CodeInfo] = &[
    code("E0001", "unexpected character", "A character that cannot start a token (such as `@`, `$`, a `#` comment or a quoted string from another language) was skipped. Comments are `// …` or `/* … */`; the language has no strings.", "grammar.md"),
    code("E0002", "unterminated block comment", "A `/*` comment is never closed and runs to the end of the file. Close it with `*/`; block comments do not nest.", "grammar.md"),
    code("E0003", "integer literal out of range", "The literal does not fit in a signed 64-bit integer. Values of variables are bounded by their `int[lo..hi]` type anyway.", "language.md"),
    code("E0004", "malformed integer literal", "A digit that is invalid for the base, or no digits after `0x`/`0b`.", "language.md"),
    code("E0005", "source is not UTF-8", "A model file must be UTF-8 text; the diagnostic points at the first byte that is not.", "language.md"),
    code("E0010", "unexpected token", "The parser expected something else here (the message says what); it skipped to the next `;`, `}` or keyword and went on.", "grammar.md"),
    code("E0011", "missing `;`", "Declarations, transitions and statements end with `;`.", "grammar.md"),
    code("E0012", "unclosed delimiter", "A `{`, `(` or `[` is never closed; the secondary label shows where it was opened.", "grammar.md"),
    code("E0013", "nesting too deep", "More nested states, blocks or expressions than the parser accepts (256 levels, or expressions more than 512 operators tall). Split the model into named parts.", "grammar.md"),
    code("E0014", "empty transition", "`on` without trigger, guard or target can never be taken. Add an event, a guard or a target.", "language.md"),
    code("E0015", "`=` where a comparison is expected", "`=` assigns; `==` compares. The quick fix replaces `=` with `==`.", "language.md"),
    code("E0016", "chained comparison", "Comparisons do not chain: `a < b < c` is an error; write `a < b && b < c`.", "language.md"),
    code("E0017", "declaration in the wrong place", "Variables and properties belong at chart level, instances and connections in a system, `parallel { … }` only at chart level.", "language.md"),
    code("E0018", "malformed duration", "A duration is a number, name or parenthesised expression followed by `ms`, `s` or `min`, e.g. `after(3 s)`, `tick 100 ms;`.", "language.md"),
    code("E0019", "`if` expression as an operand", "An `if … then … else …` expression used as an operand needs parentheses: `(if c then a else b) + 1`.", "language.md"),
    code("E0020", "missing `return`", "A function body with braces is `let` bindings followed by one `return expr;`.", "language.md"),
    code("E0021", "malformed import", "An import is `import \"path.sc\";` or `import \"path.sc\" { Name, ... };`: the path is a non-empty string and a name list is not empty.", "components.md"),
    code("E0022", "malformed `rate`", "A rate is `rate instance.input = 0.01;`: the probability is a decimal literal from 0 to 1 (no spaces around the point).", "language.md"),
    code("E0023", "malformed speed", "A speed in `der(x) = …` is units per second: a decimal (`0.8`), a constant's name, or a ratio (`1/2`), optionally negative; a profile is `profile(1 for 2 s, 4)`.", "hybrid.md"),
    code("E0030", "malformed CTL until", "A CTL until is written `A[p U q]` or `E[p U q]`; the `U` is missing.", "properties.md"),
    code("E0101", "unknown name", "A name (variable, event, constant, enum literal, type, function, state, chart, instance) is not declared where it is used. The hint suggests a similar declared name when there is one.", "language.md"),
    code("E0102", "declared twice", "Two declarations of the same kind share a name in one scope (charts, systems, variables, properties, …).", "language.md"),
    code("E0103", "type mismatch", "An expression has the wrong type for its place: a condition that is not `bool`, an `int` given to a `bool`, an enum literal of another enum, an event used as a value, a connection between ports of different types, a chart argument of the wrong type.", "language.md"),
    code("E0104", "value out of range", "A constant value lies outside the range of its type or of what the construct accepts (an initial value outside `int[lo..hi]`, an empty range, a `within` bound, a non-positive tick length, a chart argument outside its parameter's range).", "language.md"),
    code("E0105", "not a constant", "A place that needs a value known before the run (a constant, a type bound, an instance count, a delay, a chart argument) was given an expression that reads variables, or constants depend on each other in a cycle.", "language.md"),
    code("E0106", "missing `initial`", "A chart or state with child states must say which child is entered first: `initial NAME;`.", "language.md"),
    code("E0107", "bad `initial`", "`initial` does not name a child state of this state, or a parallel state (whose regions all start) declares one.", "language.md"),
    code("E0108", "duplicate at one level", "Two states, regions or junctions of one parent share a name, or an element that may appear once (such as `tick`, `initial`, `history`) appears twice.", "language.md"),
    code("E0109", "states and regions mixed", "A state holds either child states (exclusive) or regions (parallel), not both; regions hold states, not actions or transitions.", "language.md"),
    code("E0110", "not an event", "A trigger or `raise` names a variable, or an assignment writes an event. Events are raised and tested; variables are assigned and read.", "language.md"),
    code("E0111", "unknown transition target", "No state or junction of that name is visible from the transition's source. Targets are looked up from the source state outwards; a state in another region or deeper needs a dotted path such as `right.B`.", "language.md"),
    code("E0112", "wrong number of arguments", "A call passes more or fewer arguments than the function (or `min`, `max`, `abs`, `int`) takes.", "language.md"),
    code("E0113", "function used before its declaration, or recursive", "Functions are inlined, so they may only call functions declared before them and never themselves.", "language.md"),
    code("E0114", "empty declaration", "An enum has no literals, or a chart has no states.", "language.md"),
    code("E0115", "bad `history`", "`history` belongs in an exclusive state with children; a parallel state's regions take it instead.", "language.md"),
    code("E0116", "cannot `raise` this event", "Only the chart's output and local events can be raised; inputs come from the environment.", "language.md"),
    code("E0117", "`after` of zero ticks", "`after(n)` must wait at least one tick.", "language.md"),
    code("E0119", "junction loop", "Following junction branches can lead back to the same junction within one transition, which would never end.", "language.md"),
    code("E0120", "duration without a tick length", "A delay or bound in time units (`after(3 s)`, `within 2 s`) needs the file's `tick` declaration, and must divide into whole ticks.", "language.md"),
    code("E0121", "observer without `error` state", "An observer reports a violation by entering its top-level state `error`; declare one.", "properties.md"),
    code("E0122", "bad `order`", "`order` lists each instance once and never observers (which always run last).", "language.md"),
    code("E0123", "bad connection", "A connection is `connect instance.output -> instance.input;` between existing ports of one type; `[*]` on the sending side only with `[*]` on the receiving side (element by element, E0188); an input is driven at most once.", "language.md"),
    code("E0125", "bad input rate", "A `rate` names a free boolean input or input event of the system (not one driven by a connection, not an integer), once, with a probability from 0 to 1.", "tools.md"),
    code("E0124", "too many junctions on one transition", "A transition passes through more junctions than the checker expands (on one path or in all); simplify the junction graph.", "language.md"),
    code("E0140", "cannot import", "The imported file was not found next to the importing file, in a `--lib` directory or on `STATECHECK_PATH` (the hint lists the places tried), or the imports are too many, too large or nested too deep.", "components.md"),
    code("E0141", "import cycle", "A file imports itself, directly or through other files; the diagnostic shows the chain.", "components.md"),
    code("E0142", "imported name not declared", "A name in an import list is not a chart or system of the imported file.", "components.md"),
    code("E0143", "file imported twice", "One file imports the same file twice; one import is enough.", "components.md"),
    code("E0150", "bad chart argument", "An instance gives an argument that its chart (or component) does not take: more positional arguments than it has parameters, a named argument that is not a parameter, a parameter given twice, or arguments to a chart or component without parameters. Arguments are `Chart(1, 2)` in parameter order, or `Chart(hi = 2)` by name.", "components.md"),
    code("E0151", "missing chart argument", "An instance of a parameterised chart (or component) gives no value for a parameter that has no default. Give it positionally or by name (`instance s: Sensor(lo = 0, hi = 5);`), or give the parameter a default in the chart (`hi: int = 5`).", "components.md"),
    code("E0152", "interface port missing", "A chart declared `implements I` but does not declare one of `I`'s ports. Declare it in the chart with the interface's direction, kind and type.", "components.md"),
    code("E0153", "interface port of another kind", "A chart declares a port of an interface it implements with another direction (input/output) or kind (event/variable) than the interface.", "components.md"),
    code("E0154", "interface port of another type", "A chart declares a port of an interface it implements with an incompatible type: `bool` and enums must be the same; an input's integer range must contain the interface's range (the chart accepts everything others may send), an output's range must lie within it (the chart sends only what the interface promises).", "components.md"),
    code("E0155", "not a port of the slot's interface", "A connection to a slot (an instance declared by an interface) names a port the interface does not declare, or uses an input as a source or an output as a destination. Connections to a slot are checked against its interface, so that every chart a configuration may choose fits.", "components.md"),
    code("E0156", "chart not allowed in this configuration", "A configuration binds a slot to a chart that does not declare `implements` the slot's interface, or binds an instance declared with a chart to another chart (a configuration may change only its arguments; declare the instance by an interface to swap charts).", "components.md"),
    code("E0157", "slot without a chart", "A slot (an instance declared by an interface) needs a chart from every configuration of its system; a system with slots needs at least one `configuration`.", "components.md"),
    code("E0170", "component contains itself", "A component instantiates itself, directly or through other components (the message shows the cycle), or components are nested deeper than 32 levels. Components nest finitely: the flattening would not end.", "components.md"),
    code("E0171", "unconnected component port", "An input port of a component feeds no inner instance (`connect port -> inst.input;` is missing), or an output port is driven by none (`connect inst.output -> port;`). Every port of a component must lead to an instance inside it.", "components.md"),
    code("E0172", "component port mismatch", "A connection or path uses a component's port wrongly: a port the component does not declare, an input port used as a destination inside the component or an output port read inside it, an input port wired straight to an output port, an output port driven twice, or a port wired to an inner variable of another kind (event/variable, direction) or an incompatible type (the inner input must accept every value of an input port; the inner output's values must lie in an output port's type).", "components.md"),
    code("E0173", "not supported in a component", "Components declare only input and output ports without initial values, and contain instances, connections, `order`, assumptions, rates and properties; observers, requirements and configurations belong in the system that instantiates the component. A system whose flattening visits more than 4096 instances (with a chart array's length not known before checking) is refused too.", "components.md"),
    code("E0174", "too many instances once flattened", "A system (or a component running alone) flattens to more than 4096 chart instances: each instance of a component holds all of its instances, so a few levels of nesting multiply (2 instances per component over 30 levels is 2^30). The count is computed before flattening, from each component's own count, and shown in the message.", "components.md"),
    code("E0175", "too many component copies", "More than 256 different argument lists of parameterised components: each distinct list is a copy of the component, and a component that instantiates itself with other arguments (`Chain(n - 1)` inside `Chain(n)`) would copy without end. Nest a fixed number of levels.", "components.md"),
    code("E0176", "bad index of a component array", "A path into an array of components (`instance cells[3]: Cell;`) must name one element with an integer literal (or a parameter) within range: `cells[1].feeder.pos`. `cells.x` (no index), `cells[*].x` and `cells[3].x` (out of range) are refused.", "components.md"),
    code("E0177", "instance named like the scheduler", "An interleaved system (`system S interleaved { … }`) has an implicit instance `sched` whose input `sched.unit` chooses the unit that steps in each tick; an instance of the system may not be named `sched`. Rename it.", "components.md"),
    code("E0184", "bad array declaration", "An array of variables, `input rm[N]: T;`, needs a length that is a compile-time constant (literals, constants, the chart's parameters) within 1..4096. Each element is an ordinary variable named `rm[0]` … `rm[N-1]`.", "language.md"),
    code("E0185", "array index out of range", "A constant index must lie within the array (`rm[k]` with 0 <= k < N), and only arrays are indexed: `x[0]` on a scalar variable is refused. In a system, `bus.rm[2]` names an element of instance `bus`'s array `rm`.", "language.md"),
    code("E0186", "array index not constant", "Arrays of variables are expanded before checking, so an index must be a compile-time constant: a literal, a constant, a chart parameter or a `for` loop's variable. To select an element by a variable `i`, write the selection out: `for k in 0..N { if i == k { y = rm[k]; } }`.", "language.md"),
    code("E0187", "bad `for` loop", "`for k in lo..hi { … }` is unrolled before checking: its bounds must be compile-time constants, its variable must not hide a variable of the chart or an enclosing loop's variable, and all loops of a chart unroll to at most 65536 statements.", "language.md"),
    code("E0188", "array connection shape", "`connect a[*].x -> b[*].y;` (instance arrays), `connect e.out[*] -> f[*].in;` (scatter) and `connect p[*].o -> s.in[*];` (gather) connect element by element: both sides need the same length, and one endpoint has at most one `[*]`. (`[*]` on the sending side alone, many outputs to one input, is E0123.)", "components.md"),
    code("E0189", "array without index", "An array of variables is named one element at a time (`rm[0]`, `bus.rm[k]`) in expressions and assignments; `[*]` appears only in connections.", "language.md"),
    code("E0190", "bad event rename", "An instance's rename block (`instance p1: Phil { take -> take1; }`) names something that is not a `controllable event` or `uncontrollable event` of the chart, or renames one event twice. The hint lists the chart's events.", "synthesis.md"),
    code("E0191", "rename not allowed here", "Renames belong to single chart instances: an instance array would give every element the same names, and a component instance has no events of its own (rename on the chart instances inside it).", "synthesis.md"),
    code("E0160", "CTL operator in an LTL formula", "`ltl` formulas use the temporal operators `G F X U R W` without path quantifiers; `A`/`E` belong to `ctl` formulas.", "properties.md"),
    code("E0161", "LTL operator in a CTL formula", "In a `ctl` formula every temporal operator needs a path quantifier: `AG`, `EF`, `A[p U q]`, ….", "properties.md"),
    code("E0180", "bad continuous variable or grid", "A `continuous x: [lo .. hi] = init;` needs constant whole-number bounds with lo < hi and an initial value inside; `grid x N;` needs N >= 1 cells of whole-number width ((hi - lo) divisible by N), and at most 2000 grid points in all.", "hybrid.md"),
    code("E0181", "clock reading not a whole number of ticks", "The time a motion takes from one grid point to the next (cell length / speed, or the profile's time) must be a whole number of ticks. The hint names the nearest tick lengths that work; or change the grid or the speed.", "hybrid.md"),
    code("E0182", "misplaced hybrid element", "`continuous`, `grid` and `sensor` are declared at a chart's top level (not in observers); `der(x)` goes in a state, once per state, for a continuous variable of the chart; a sensor's output is a `bool` output or local; a speed profile keeps one direction; the generated names `x_mode`, `x_ticks`, `x_from` must be free.", "hybrid.md"),
    code("E0183", "speed not a constant", "The right-hand side of `der(x) = …` is a constant speed (a decimal, `a/b`, a constant or a chart parameter) or a `profile(…)` of them. A speed that depends on a variable (`der(x) = k * (target - x)`) has no closed-form clock readings and is not accepted: every reading of the discretization is exact by construction. Approximate such dynamics with a profile of constant speeds.", "hybrid.md"),
    code("E0131", "transition leaves the chart's top level", "The lowering refuses a transition whose source and target lie in different top-level regions, or that would leave the chart.", "semantics.md"),
    code("W0201", "no initial value", "A variable without `= value` starts at its type's default (the lowest value, `false`, the first literal); say it explicitly.", "lints.md"),
    code("W0202", "instance connected to itself", "The input reads the instance's own output slot: a value the instance wrote earlier in the same step (an earlier region, an entry or transition action) is seen in that tick; otherwise the previous tick's value. Usually a mistake; a `local` variable says the same more clearly (`tests/semantics/self_connect`).", "lints.md"),
    code("W0301", "state with no incoming transition", "No transition enters the state and it is not its parent's `initial`: it can never be active.", "lints.md"),
    code("W0302", "state isolated from its level's initial state", "The state cannot be reached from the `initial` state of its level.", "lints.md"),
    code("W0303", "two transitions with the same `priority`", "Two transitions of one state have the same explicit priority; their order is then textual, which the priority was meant to override.", "lints.md"),
    code("W0304", "transition that can never fire", "An earlier transition (or choice branch) always preempts it.", "lints.md"),
    code("W0305", "guard that is always false", "The guard is constant `false`: the transition never fires.", "lints.md"),
    code("W0306", "self-transition on a composite state", "It exits and re-enters the whole subtree (resetting it), which is often not intended.", "lints.md"),
    code("W0307", "choice without `else`", "All guards of the choice can be false, and then the transition does not fire.", "lints.md"),
    code("W0308", "unused variable or event", "An input never read, an output never written, or a local never used.", "lints.md"),
    code("W0309", "local written but never read", "A local variable or event is written (or raised) but never read.", "lints.md"),
    code("W0310", "transition without a target suppresses `during`", "A transition that fires ends its state's reaction for the tick (rule R4), internal ones included: in the ticks where it fires, the state's `during` action does not run. Do the transition's work inside `during` with an `if` to run both.", "lints.md"),
    code("W0316", "connection breaks an array's symmetry", "`verify --symmetry` treats the elements of an instance array as interchangeable only when nothing outside can tell them apart: every connection into an element comes from outside the array and is made for every element (`connect x.out -> arr[*].in;`), and no connection reads an element's output. The named connection is not of that form, so the array's states are stored without reduction (docs/verification.md, \"Symmetry reduction\").", "verification.md"),
    code("W0317", "property, assume or observer breaks an array's symmetry", "`verify --symmetry` needs every property to read no element or to be a chart property of the elements (one per element, answered together), no `assume` reading elements, and no observer. The named one is not, so the array's states are stored without reduction (docs/verification.md, \"Symmetry reduction\").", "verification.md"),
    code("W0318", "array elements whose slots do not correspond", "The elements of the array differ in their state slots (ranges or initial values), so they are not interchangeable and `verify --symmetry` does not reduce the array.", "verification.md"),
    code("E0701", "synthesis: bad instance", "Synthesis systems hold single instances of existing charts (no arrays): events synchronise by name.", "synthesis.md"),
    code("E0702", "synthesis: not a plant or requirement", "A synthesis system holds only `plant chart` and `requirement chart` instances.", "synthesis.md"),
    code("E0703", "synthesis: declaration other than an event", "Plant and requirement charts declare only `controllable event` and `uncontrollable event`.", "synthesis.md"),
    code("E0704", "synthesis: event both controllable and uncontrollable", "Each event has one controllability across the system.", "synthesis.md"),
    code("E0705", "synthesis: reserved name", "`none` is reserved in the emitted supervisor.", "synthesis.md"),
    code("E0706", "synthesis: unknown event", "A requirement names an event that no chart of the system declares.", "synthesis.md"),
    code("E0707", "synthesis: no plant", "A synthesis system needs at least one plant.", "synthesis.md"),
    code("E0708", "synthesis: not a flat automaton", "Plant and requirement charts are flat: states with `on EVENT -> STATE;` transitions only (no children, actions, guards or timers).", "synthesis.md"),
    code("E0709", "synthesis: bad state or `initial`", "A target names no state, or the chart does not have exactly one `initial` state.", "synthesis.md"),
    code("E0710", "synthesis: bad transition", "A transition is `on EVENT -> STATE;` with an event of the chart and a sibling state as target.", "synthesis.md"),
    code("E0711", "synthesis: nondeterministic", "Two transitions on one event leave the same state.", "synthesis.md"),
    code("E0712", "synthesis: bad state requirement", "State requirements use `in(instance.State)`, `!`, `&&`, `||`, `true` and `false`.", "synthesis.md"),
    code("E0720", "Supremica XML: malformed XML", "The file is not well-formed XML; the position is where the XML parser stopped.", "synthesis.md"),
    code("E0721", "Supremica XML: unexpected structure", "The file is not a Supremica automata file: the root is <Automata> holding <Automaton name= type=> elements with <Events>, <States> and <Transitions>; a required attribute is missing, or a flag is not `true`/`false`.", "synthesis.md"),
    code("E0722", "Supremica XML: unknown or repeated id", "A transition names a state or event id that its automaton does not declare, or an id is declared twice.", "synthesis.md"),
    code("E0723", "Supremica XML: nondeterministic automaton", "Two transitions on one event leave the same state to different states; synthesis needs deterministic automata.", "synthesis.md"),
    code("E0724", "Supremica XML: initial state", "An automaton has no initial state, or more than one.", "synthesis.md"),
    code("E0725", "Supremica XML: event both controllable and uncontrollable", "Events synchronise by label; every automaton must give a label the same controllability.", "synthesis.md"),
    code("E0726", "Supremica XML: automaton type", "Automata are `Plant`, `Specification` or `Supervisor` (synthesised against) or `Property` (skipped); the file needs at least one `Plant`.", "synthesis.md"),
    code("E0727", "Supremica XML export: requirement too large", "A state requirement over several automata is written as a product of copies of them; that product exceeds the export limit.", "synthesis.md"),
    code("E0734", "synthesis: connection", "Events of a synthesis system synchronise by name; a `connect` (also one made by a component port that feeds several inner events) would not relabel an event, so it is refused; to give an instance's events other names, rename them (`instance p1: Phil { take -> take1; }`, E0190).", "synthesis.md"),
    code("E0801", "scenario: bad repeat count", "A scenario line ends with `* N` where N is a whole number of at least 1.", "language.md"),
    code("E0802", "scenario: empty item", "Items of a scenario line are separated by single commas.", "language.md"),
    code("E0803", "scenario: unknown input", "The name is not a free input of the system: it is misspelt (the hint suggests the closest input), or it is computed or connected inside the system.", "language.md"),
    code("E0804", "scenario: ambiguous input", "A bare name matches inputs of several instances; qualify it as `instance.input`.", "language.md"),
    code("E0805", "scenario: value given to an event", "An input event is present (its bare name on the line) or absent (left out); it takes no value, not even `true`.", "language.md"),
    code("E0806", "scenario: variable without a value", "A bare name makes an event present; an input variable needs `name = value`.", "language.md"),
    code("E0807", "scenario: value out of range", "The value lies outside the input's declared range `int[lo..hi]`.", "language.md"),
    code("E0808", "scenario: value of the wrong type", "A `bool` takes `true` or `false` (not `1` or `0`), an enum one of its literals, an integer a decimal, hex or binary literal.", "language.md"),
    code("E0810", "scenario: misplaced `loop:`", "A scenario has at most one `loop:` line; it follows the first tick and precedes at least one tick (tick 0 only initialises).", "language.md"),
    code("E0809", "scenario: too long", "The scenario would expand (with its `* N` repeats) to more ticks than a run may have.", "language.md"),
    code("E0901", "Graphviz not found", "`statecheck dot --svg` runs Graphviz's `dot -Tsvg`, which is not installed or not on `PATH` (install the `graphviz` package, or drop `--svg` to write DOT text). Exit code 2.", "tools.md"),
    code("E0902", "Graphviz failed", "Graphviz's `dot -Tsvg` exited with an error on the drawing; its message is shown. Exit code 2.", "tools.md"),
];

/// The entry of a code (case-insensitive), if any.
pub fn lookup(code: &str) -> Option<&'static CodeInfo> {
    CODES.iter().find(|c| c.code.eq_ignore_ascii_case(code))
}

/// The page `statecheck explain CODE` prints.
pub fn page(c: &CodeInfo) -> String {
    format!(
        "{}: {}\n\n{}\n\nSee docs/{}. Examples: tests/diagnostics/{}_*.sc (if present).\n",
        c.code,
        c.title,
        c.explanation,
        c.doc,
        c.code.to_ascii_lowercase()
    )
}

/// The text of `docs/diagnostics.md`.
pub fn markdown_index() -> String {
    let mut s = String::from(
        "# Diagnostic codes\n\nGenerated from `crates/base/src/codes.rs` (the table behind \
         `statecheck explain CODE`); do not edit by hand: run\n\
         `UPDATE_EXPECT=1 cargo test -p statecheck-cli --test explain`.\n\n\
         | code | title | explanation | see |\n|---|---|---|---|\n",
    );
    for c in CODES {
        s.push_str(&format!(
            "| {} | {} | {} | [{}]({}) |\n",
            c.code,
            c.title.replace('|', "\\|"),
            c.explanation.replace('|', "\\|"),
            c.doc,
            c.doc
        ));
    }
    s
}
