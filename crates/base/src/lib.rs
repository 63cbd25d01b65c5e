//! The shared vocabulary of statecheck: byte spans into a model's source text, a line index to
//! turn them into `line:col`, and diagnostics as plain data.
//!
//! Diagnostics are data, not text: every stage (parser, checker, linter, interpreter) returns
//! them beside its result, and only the CLI renders them. This keeps the core crates free of
//! I/O and lets tests compare diagnostics structurally or through the CLI's rendering.

pub mod codes;
mod diagnostic;
mod span;

pub use diagnostic::{Diagnostic, Label, Severity};
pub use span::{LineIndex, Span};
