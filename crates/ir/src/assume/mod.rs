//! The input vectors of one tick and the `assume`s that restrict them, solved once for every
//! consumer: the explicit engine enumerates the allowed vectors as transitions, the simulator
//! draws random inputs among them.
//!
//! [`reads`] classifies an `assume` conjunct by what it reads (inputs only, state only, or
//! both); [`InputSpace`] lists the vectors that the input-only conjuncts allow by a pruned
//! depth-first enumeration (interval evaluation of each conjunct over the partial assignment
//! rules out whole subtrees; the exact evaluator decides every complete vector), leaving the
//! state-dependent conjuncts to be evaluated per state or per vector.

mod enumerate;
mod interval;
pub mod reads;
mod relevant;
mod space;

pub use relevant::InputReads;
pub use space::{InputSpace, MAX_STATIC_ENUMERATION};
