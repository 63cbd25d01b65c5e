//! `statecheck export promela`: the closed system as a Promela model for SPIN.

use crate::load;
use anyhow::Result;
use clap::Args;
use statecheck_codegen::promela::{export, PromelaOptions};
use statecheck_codegen::Source;

/// Arguments of `statecheck export promela`.
#[derive(Args)]
pub struct PromelaArgs {
    /// The `.sc` model file.
    model: String,
    /// The system (or chart) to export.
    #[arg(long)]
    system: Option<String>,
    /// Assert only this property (repeatable; built-ins may be named too). Default: every
    /// invariant, respond and observer property; a `reachable` property is asserted negated.
    #[arg(long, value_name = "NAME")]
    property: Vec<String>,
    /// Output file (`.pml`); standard output when absent.
    #[arg(short, long)]
    output: Option<String>,
}

/// Run the command; returns the exit code.
pub fn run(a: PromelaArgs) -> Result<u8> {
    let loaded = load::load(&a.model, false)?;
    let sys = loaded.system(a.system.as_deref())?;
    let program = loaded.lower(sys)?;
    let src = Source::new(&loaded.path, &loaded.source);
    let opts = PromelaOptions {
        properties: a.property,
    };
    let text = export(&program, &src, &opts)?;
    match &a.output {
        Some(f) => crate::outpath::write(std::path::Path::new(f), text.as_bytes())?,
        None => print!("{text}"),
    }
    Ok(0)
}
