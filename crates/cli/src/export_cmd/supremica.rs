//! `statecheck export supremica`: a synthesis system (plants, requirements, state
//! requirements) as Supremica's automata XML (see `docs/synthesis.md`, "Supremica XML").

use crate::supervisor::problem;
use anyhow::{anyhow, Result};
use clap::Args;
use statecheck_synth::supremica::write::write;

/// Arguments of `statecheck export supremica`.
#[derive(Args)]
pub struct SupremicaArgs {
    /// The `.sc` model file with plant and requirement charts and a system.
    model: String,
    /// The system of plants and requirements (default: the only system).
    #[arg(long)]
    system: Option<String>,
    /// Output file (`.xml`); standard output when absent.
    #[arg(short, long)]
    output: Option<String>,
}

/// Run the command; returns the exit code.
pub fn run(a: SupremicaArgs) -> Result<u8> {
    let p = problem(&a.model, a.system.as_deref())?;
    let text = write(&p).map_err(|e| anyhow!("{}: {e}", a.model))?;
    crate::write_out(a.output.as_deref(), &text)?;
    Ok(0)
}
