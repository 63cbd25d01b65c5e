//! `statecheck export promela`.

use anyhow::{bail, Result};
use clap::Args;

/// Arguments of `statecheck export promela`.
#[derive(Args)]
pub struct PromelaArgs {
    /// The `.sc` model file.
    model: String,
}

/// Run the command; returns the exit code.
pub fn run(a: PromelaArgs) -> Result<u8> {
    let _ = a.model;
    bail!("not implemented yet")
}
