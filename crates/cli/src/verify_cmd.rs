//! `statecheck verify`: exhaustive verification of a system's properties.

use anyhow::{bail, Result};
use clap::Args;

/// Arguments of `statecheck verify`.
#[derive(Args)]
pub struct VerifyArgs {
    /// The `.sc` model file.
    model: String,
}

/// Run the command; returns the exit code.
pub fn run(a: VerifyArgs) -> Result<u8> {
    let _ = a.model;
    bail!("not implemented yet")
}
