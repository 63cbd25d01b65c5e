//! Supremica's automata XML: [`read::read`] turns a file into a [`crate::Problem`],
//! [`write::write`] writes one (see `docs/synthesis.md`, "Supremica XML").

pub mod idents;
pub mod read;
pub mod write;
