//! `statecheck synth`: supervisory controller synthesis.

use anyhow::{bail, Result};
use clap::Args;

/// Arguments of `statecheck synth`.
#[derive(Args)]
pub struct SynthArgs {
    /// The `.sc` model file.
    model: String,
}

/// Run the command; returns the exit code.
pub fn run(a: SynthArgs) -> Result<u8> {
    let _ = a.model;
    bail!("not implemented yet")
}
