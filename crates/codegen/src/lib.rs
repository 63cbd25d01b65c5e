//! Code generation from the IR [`Program`](statecheck_ir::Program): C99 and Rust step
//! functions, Modelica in the structure of the Modelica statechart paper, and Promela for SPIN.
//!
//! Generators never decide semantics: they translate the program statement by statement and
//! node by node. Every run-time check of the interpreter (range, division, shift, overflow) is
//! reproduced and reported through a status code, with the same site number.
//! Core crate: no I/O; every generator returns text.

pub mod c;
mod c_expr;
mod c_harness;
pub mod common;
pub mod modelica;
pub mod promela;
pub mod rust;

pub use c_harness::harness as c_harness;
pub use common::Source;
