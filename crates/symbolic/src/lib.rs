//! SAT-based verification of the IR.
//!
//! [`blast`](blast::blast) turns a [`Program`](statecheck_ir::Program)'s step into an
//! And-Inverter Graph ([`aig`]); the engines — bounded model checking ([`bmc`]), k-induction
//! ([`kind`]) and IC3/PDR ([`ic3`]), and IC3 on localization abstractions refined by
//! counterexamples ([`localize`]) — decide one bad-state output of such a graph with an
//! incremental SAT solver (CaDiCaL, [`sat`]). [`aiger`] reads and writes the AIGER 1.9 format
//! of hardware model checkers; [`cert`] re-checks an inductive invariant independently of the
//! engine that found it; [`check`] runs an engine on a program's property and returns a
//! counterexample as input vectors, like the explicit engine.

pub mod aig;
pub mod aiger;
pub mod blast;
pub mod bmc;
pub mod bv;
pub mod cert;
pub mod check;
pub mod engine;
mod error;
pub mod ic3;
pub mod kind;
pub mod live;
pub mod localize;
pub mod sat;
pub mod scorr;
pub mod ternary;

pub use error::{Error, ErrorKind};
