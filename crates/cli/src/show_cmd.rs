//! `statecheck show --discretized FILE`: the model as the checker verifies it, with every
//! continuous variable discretized (docs/hybrid.md), printed as `.sc` text that checks and
//! verifies like the original.

use crate::{diag, load, outpath};
use anyhow::{bail, Result};

/// Arguments of `statecheck show`.
#[derive(clap::Args)]
pub struct ShowArgs {
    /// The `.sc` model file.
    pub model: String,
    /// Print the model with its continuous variables discretized into grid variables,
    /// modes and timers (the only view so far; required).
    #[arg(long)]
    pub discretized: bool,
    /// Write to this file instead of standard output.
    #[arg(short, long)]
    pub output: Option<String>,
}

/// Run `show`.
pub fn run(args: ShowArgs) -> Result<u8> {
    if !args.discretized {
        bail!("say what to show: `statecheck show --discretized FILE`");
    }
    let loaded = load::load(&args.model, false)?;
    let text = match statecheck_model::hybrid::discretized_source(&loaded.source, &loaded.file) {
        Ok(t) => t,
        Err(diags) => {
            diag::eprint_sources(&loaded.sources, &diags);
            return Err(load::ModelErrors.into());
        }
    };
    match args.output {
        Some(path) => {
            outpath::check(&path, "output")?;
            outpath::write(std::path::Path::new(&path), text.as_bytes())?;
        }
        None => print!("{text}"),
    }
    Ok(0)
}
