//! Fuzzing and differential testing of statecheck, on the stable toolchain (`docs/reliability.md`).
//!
//! - [`targets`]: the four fuzz targets (parser+checker, scenario reader, AIGER reader,
//!   formatter), each a function of a byte string that must not panic and must keep its
//!   target's promises (the formatter is idempotent and meaning-preserving, an AIGER file
//!   that parses writes back to one that parses the same).
//! - [`corpus`]: the seed corpus (the repository's models and scenarios plus
//!   `crates/fuzz/corpus/`), [`mutate`]: the byte- and token-level mutator, deterministic in
//!   (seed, execution index) so that a crash is found again from its index alone.
//! - [`runner`]: runs a target in worker processes (one per core), catching panics in the
//!   worker and aborts, stack overflows and timeouts in the parent; inputs that fail are saved.
//! - [`gen`] and [`diff`]: the differential fuzzer over random well-typed models.

pub mod corpus;
pub mod diff;
pub mod gen;
pub mod mutate;
pub mod runner;
pub mod targets;
