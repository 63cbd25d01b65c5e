//! The AIGER 1.9 format of hardware model checkers: bad-state properties, invariant
//! constraints, latches with reset values, symbol tables; ASCII (`aag`) and binary (`aig`).

mod abc_live;
mod read;
mod write;

pub use abc_live::{abc_kcs, abc_liveness};
pub use read::{parse, AigerError};
pub use write::{ascii, binary};
