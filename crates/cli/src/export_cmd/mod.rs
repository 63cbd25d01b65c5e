//! `statecheck export`: other tools' input formats (AIGER for ABC, Promela for SPIN).

pub mod aiger;
pub mod promela;

use anyhow::Result;
use clap::Subcommand;

/// What to export.
#[derive(Subcommand)]
pub enum ExportCommand {
    /// An AIGER 1.9 file of one property (for ABC and other hardware model checkers).
    Aiger(aiger::AigerArgs),
    /// A Promela model of the closed system (for SPIN).
    Promela(promela::PromelaArgs),
}

/// Run the command; returns the exit code.
pub fn run(c: ExportCommand) -> Result<u8> {
    match c {
        ExportCommand::Aiger(a) => aiger::run(a),
        ExportCommand::Promela(a) => promela::run(a),
    }
}
