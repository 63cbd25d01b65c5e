//! Running a program: scenario-driven or random inputs, with the model's properties monitored
//! on every tick.

use crate::scenario::Scenario;
use statecheck_ir::{Machine, Program, RuntimeError};

/// One tick of a trace: every slot's value right after the tick (state, the tick's inputs and
/// its temporaries such as present local events).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TickRecord {
    /// Tick number, from 0.
    pub tick: u64,
    /// All slot values after the tick.
    pub slots: Vec<i64>,
}

/// Why a run ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Stop {
    /// All ticks ran.
    Completed,
    /// A run-time error stopped the tick (the trace ends with the tick before).
    RuntimeError {
        /// The tick that failed.
        tick: u64,
        /// The error.
        error: RuntimeError,
    },
    /// A property was violated after the tick (the trace includes the tick).
    Violation {
        /// The tick after which it was violated.
        tick: u64,
        /// The property's name.
        property: String,
    },
    /// The inputs of a tick violated an `assume`.
    AssumeViolated {
        /// The tick.
        tick: u64,
        /// Index into `Program::assumes`.
        assume: usize,
    },
}

/// A finished run.
#[derive(Clone, Debug)]
pub struct Run {
    /// The ticks that completed.
    pub trace: Vec<TickRecord>,
    /// Why it ended.
    pub stop: Stop,
    /// For each `reachable` property: the first tick at which it held.
    pub reached: Vec<(String, Option<u64>)>,
    /// Coverage counters, if requested.
    pub coverage: Option<Vec<u64>>,
    /// With coverage: each tick after which more states or transitions had been covered than
    /// before it, with the counts (how coverage grew along the run).
    pub coverage_growth: Vec<Growth>,
    /// The inputs applied, one full vector per tick (for `--save-scenario`).
    pub inputs: Vec<Vec<i64>>,
    /// When the run ended with [`Stop::AssumeViolated`] because the input source found no
    /// inputs: why (a random source's deadlock, or draws exhausted).
    pub no_input: Option<NoInput>,
}

/// Coverage after a tick that covered something new (see [`Run::coverage_growth`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Growth {
    /// The tick.
    pub tick: u64,
    /// States entered at least once by the end of the tick.
    pub states: u32,
    /// Transitions (and choice branches) taken at least once by the end of the tick.
    pub transitions: u32,
}

/// The numbers of state and of transition coverage items with a non-zero count (items meant
/// never to be covered, an observer's `error`, left out as in the coverage report).
pub fn covered_counts(program: &Program, counts: &[u64]) -> (u32, u32) {
    let (mut s, mut t) = (0, 0);
    for (c, &n) in program.covers.iter().zip(counts) {
        if n > 0 && !c.expected_unreached {
            match c.kind {
                statecheck_ir::CoverKind::State(_) => s += 1,
                _ => t += 1,
            }
        }
    }
    (s, t)
}

/// Why an input source gave no inputs for a tick.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoInput {
    /// No input vector satisfies the `assume`s in the current state (a state-only `assume`
    /// fails, or every candidate was tried): a deadlock of the closed system.
    Deadlock {
        /// Index into `Program::assumes` of one that blocks.
        assume: usize,
    },
    /// No vector that satisfies them was found within the draws allowed; there may be one.
    NotFound {
        /// Index into `Program::assumes` of one that the last draw violated.
        assume: usize,
    },
}

impl NoInput {
    /// The `assume` named.
    pub fn assume(self) -> usize {
        match self {
            NoInput::Deadlock { assume } | NoInput::NotFound { assume } => assume,
        }
    }
}

/// Options of a run.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Count state entries and transition firings.
    pub coverage: bool,
    /// Do not record the trace (for long random runs that only want coverage or checks).
    pub no_trace: bool,
    /// Go on after a property violation (benchmarks, coverage): the run ends as
    /// [`Stop::Violation`] of the first one when all ticks ran.
    pub keep_going: bool,
}

/// Where a run gets its inputs from.
pub trait InputSource {
    /// Fill `inputs` (in `Program::inputs` order) for `tick`; the machine holds the state
    /// before the tick. Return false when the run is over, an error when no inputs satisfy
    /// the `assume`s.
    fn next(&mut self, tick: u64, machine: &Machine, inputs: &mut [i64]) -> Result<bool, NoInput>;
}

/// Inputs from a scenario: held inputs keep their value, events last one tick.
pub struct ScenarioInputs<'s> {
    scenario: &'s Scenario,
}

impl<'s> ScenarioInputs<'s> {
    /// Inputs replaying `scenario`.
    pub fn new(scenario: &'s Scenario) -> Self {
        ScenarioInputs { scenario }
    }
}

impl InputSource for ScenarioInputs<'_> {
    fn next(&mut self, tick: u64, machine: &Machine, inputs: &mut [i64]) -> Result<bool, NoInput> {
        let Some(changes) = self.scenario.tick(tick as usize) else {
            return Ok(false);
        };
        let p = machine.program();
        for (k, inp) in p.inputs.iter().enumerate() {
            if inp.is_event {
                inputs[k] = 0;
            }
        }
        for &(k, v) in changes {
            inputs[k] = v;
        }
        Ok(true)
    }
}

/// Receives a run tick by tick, as it is computed (see [`run_streaming`]).
pub trait Sink {
    /// The inputs of `tick` (in `Program::inputs` order), once they satisfy the `assume`s and
    /// before the step: every tick that is attempted, including one that fails.
    fn inputs(&mut self, tick: u64, inputs: &[i64]) {
        let _ = (tick, inputs);
    }
    /// Every slot after `tick`: every tick that completed, including one that violates a
    /// property, but not one that ended in a run-time error.
    fn tick(&mut self, tick: u64, slots: &[i64]) {
        let _ = (tick, slots);
    }
}

/// The sink of [`run`]: the trace and the inputs kept in memory.
struct Collect<'a> {
    trace: Option<&'a mut Vec<TickRecord>>,
    inputs: &'a mut Vec<Vec<i64>>,
}

impl Sink for Collect<'_> {
    fn inputs(&mut self, _tick: u64, inputs: &[i64]) {
        self.inputs.push(inputs.to_vec());
    }
    fn tick(&mut self, tick: u64, slots: &[i64]) {
        if let Some(t) = &mut self.trace {
            t.push(TickRecord {
                tick,
                slots: slots.to_vec(),
            });
        }
    }
}

/// Run `program` from its initial state with inputs from `source`, keeping the trace (unless
/// [`Options::no_trace`]) and the inputs in the [`Run`].
pub fn run(program: &Program, source: &mut dyn InputSource, opts: Options) -> Run {
    let mut trace = Vec::new();
    let mut inputs = Vec::new();
    let mut sink = Collect {
        trace: (!opts.no_trace).then_some(&mut trace),
        inputs: &mut inputs,
    };
    let mut r = run_streaming(program, source, opts, &mut sink);
    r.trace = trace;
    r.inputs = inputs;
    r
}

/// Run `program` from its initial state with inputs from `source`, handing each tick to
/// `sink` as it is computed and keeping nothing per tick: the [`Run`]'s trace and inputs are
/// empty, and memory does not grow with the number of ticks.
pub fn run_streaming(
    program: &Program,
    source: &mut dyn InputSource,
    opts: Options,
    sink: &mut dyn Sink,
) -> Run {
    let mut m = Machine::new(program);
    if opts.coverage {
        m.enable_coverage();
    }
    let mut inputs: Vec<i64> = program
        .inputs
        .iter()
        .map(|i| program.slots[i.slot as usize].init)
        .collect();
    let mut reached = unreached(program);
    let mut no_input = None;
    let mut first_violation = None;
    let mut growth: Vec<Growth> = Vec::new();
    let mut tick = 0u64;
    let stop = loop {
        match source.next(tick, &m, &mut inputs) {
            Ok(true) => {}
            Ok(false) => break Stop::Completed,
            Err(why) => {
                no_input = Some(why);
                break Stop::AssumeViolated {
                    tick,
                    assume: why.assume(),
                };
            }
        }
        let result = tick_once(program, &mut m, tick, &inputs, &mut reached, &mut || {
            sink.inputs(tick, &inputs);
        });
        // The violating tick is part of the trace; a failed or refused one is not.
        if matches!(result, Ok(()) | Err(Stop::Violation { .. })) {
            sink.tick(tick, m.slots());
            if let Some(c) = m.coverage() {
                let (states, transitions) = covered_counts(program, c);
                if growth
                    .last()
                    .is_none_or(|g| (g.states, g.transitions) != (states, transitions))
                {
                    growth.push(Growth {
                        tick,
                        states,
                        transitions,
                    });
                }
            }
        }
        match result {
            Err(v @ Stop::Violation { .. }) if opts.keep_going => {
                first_violation.get_or_insert(v);
            }
            Err(stop) => break stop,
            Ok(()) => {}
        }
        tick += 1;
    };
    let stop = match (stop, first_violation) {
        (Stop::Completed, Some(v)) => v,
        (stop, _) => stop,
    };
    Run {
        trace: Vec::new(),
        stop,
        reached,
        coverage: m.coverage().map(<[u64]>::to_vec),
        coverage_growth: growth,
        inputs: Vec::new(),
        no_input,
    }
}

/// One tick of a run, as [`run`] does it: set the inputs (one value per input, in
/// [`Program::inputs`] order), check the `assume`s, step, then check the properties on the
/// new state and record the `reachable` ones that hold (`reached` has one entry per
/// `reachable` property, in declaration order).
///
/// `accepted` is called once the inputs satisfy the `assume`s, before the step (`run` records
/// the inputs there). On `Err`, the stop says why the run ends: after
/// [`Stop::Violation`] the machine holds the violating state (the trace includes that tick);
/// after [`Stop::RuntimeError`] it holds the slots at the error; after
/// [`Stop::AssumeViolated`] nothing was stepped.
pub fn tick_once(
    program: &Program,
    m: &mut Machine,
    tick: u64,
    inputs: &[i64],
    reached: &mut [(String, Option<u64>)],
    accepted: &mut dyn FnMut(),
) -> Result<(), Stop> {
    for (k, inp) in program.inputs.iter().enumerate() {
        m.set(inp.slot, inputs[k]);
    }
    if let Some(a) = program
        .assumes
        .iter()
        .position(|a| m.eval(*a).map_or(true, |v| v == 0))
    {
        return Err(Stop::AssumeViolated { tick, assume: a });
    }
    accepted();
    if let Err(error) = m.step() {
        return Err(Stop::RuntimeError { tick, error });
    }
    if let Some(name) = first_violation(program, m, tick, reached) {
        return Err(Stop::Violation {
            tick,
            property: name,
        });
    }
    Ok(())
}

/// The `reachable` properties of a program, none reached yet (the `reached` of [`tick_once`]).
pub fn unreached(program: &Program) -> Vec<(String, Option<u64>)> {
    program
        .properties
        .iter()
        .filter(|p| p.goal.is_reach())
        .map(|p| (p.name.clone(), None))
        .collect()
}

/// The first property (in declaration order) that the machine's current state violates;
/// records `reachable` properties that now hold.
fn first_violation(
    p: &Program,
    m: &mut Machine,
    tick: u64,
    reached: &mut [(String, Option<u64>)],
) -> Option<String> {
    let mut holds = |e| m.eval(e).is_ok_and(|v| v != 0);
    let mut r = 0;
    for prop in &p.properties {
        if prop.goal.is_reach() {
            if reached[r].1.is_none() && prop.goal.decided_by(&mut holds) {
                reached[r].1 = Some(tick);
            }
            r += 1;
        } else if prop.goal.decided_by(&mut holds) {
            return Some(prop.name.clone());
        }
    }
    None
}
