//! `statecheck export`: other tools' input formats (AIGER for ABC, Promela for SPIN,
//! automata XML for Supremica).

pub mod aiger;
pub mod promela;
pub mod supremica;

use anyhow::Result;
use clap::Subcommand;

/// What to export.
#[derive(Subcommand)]
pub enum ExportCommand {
    /// An AIGER 1.9 file of one property (for ABC and other hardware model checkers).
    Aiger(aiger::AigerArgs),
    /// A Promela model of the closed system (for SPIN).
    Promela(promela::PromelaArgs),
    /// Supremica's automata XML of a synthesis system (plants, specifications, forbidden
    /// states).
    Supremica(supremica::SupremicaArgs),
}

/// Run the command; returns the exit code.
pub fn run(c: ExportCommand) -> Result<u8> {
    match c {
        ExportCommand::Aiger(a) => aiger::run(a),
        ExportCommand::Promela(a) => promela::run(a),
        ExportCommand::Supremica(a) => supremica::run(a),
    }
}
