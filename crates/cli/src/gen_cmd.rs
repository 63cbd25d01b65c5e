//! `statecheck gen`: code generation (C99, Rust, Modelica) from the IR.

use anyhow::{bail, Result};
use clap::Args;

/// Arguments of `statecheck gen`.
#[derive(Args)]
pub struct GenArgs {
    /// Target language: c, rust or modelica.
    target: String,
    /// The `.sc` model file.
    model: String,
}

/// Run the command; returns the exit code.
pub fn run(a: GenArgs) -> Result<u8> {
    let _ = (a.target, a.model);
    bail!("not implemented yet")
}
