//! Simulation on the IR: scenarios in and out, deterministic and random runs, property
//! monitoring along every run, and coverage counts.
//!
//! Nothing here decides what a tick does: runs drive [`statecheck_ir::Machine`]. The crate does
//! no I/O; the CLI reads scenario files and renders traces.

pub mod choices;
pub mod guided;
pub mod hunt;
pub mod lasso;
pub mod minimise;
pub mod random;
pub mod run;
pub mod scenario;

pub use run::{
    covered_counts, run, run_streaming, tick_once, unreached, Growth, InputSource, NoInput,
    Options, Run, ScenarioInputs, Sink, Stop, TickRecord,
};
pub use scenario::{Scenario, ScenarioError, ScenarioWriter};
