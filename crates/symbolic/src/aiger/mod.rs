//! The AIGER 1.9 format of hardware model checkers: bad-state properties, invariant
//! constraints, latches with reset values, symbol tables; ASCII (`aag`) and binary (`aig`).

mod read;
mod write;

pub use read::{parse, AigerError};
pub use write::{ascii, binary};
