//! `statecheck export aiger`.

use anyhow::{bail, Result};
use clap::Args;

/// Arguments of `statecheck export aiger`.
#[derive(Args)]
pub struct AigerArgs {
    /// The `.sc` model file.
    model: String,
}

/// Run the command; returns the exit code.
pub fn run(a: AigerArgs) -> Result<u8> {
    let _ = a.model;
    bail!("not implemented yet")
}
