//! The one IR of statecheck's synchronous step semantics, and its interpreter.
//!
//! [`lower`] compiles one system of a checked model into a [`Program`]: a tick as a small
//! imperative program (assignments, conditionals, switches on active-state slots, calls of
//! shared entry/exit procedures) over a flat vector of bounded integer slots. All of the
//! statechart semantics — priorities, exit/entry order, history, timers, events, parallel
//! regions, run-time checks — is decided in [`lower`](mod@lower); the simulator, the model
//! checkers and the code generators only execute or translate the program. [`Machine`] is the
//! reference interpreter.

pub mod assume;
mod error;
mod interp;
mod layout;
pub mod lower;
mod program;
pub mod symmetry;
pub mod temporal;
pub mod time;
pub mod verdict;
pub mod view;
mod vm;

pub use error::{RuntimeError, RuntimeErrorKind};
pub use interp::{eval, Machine, Prepared};
pub use lower::lower;
pub use program::*;
/// The operators of IR expressions and the kinds of variables, as the syntax defines them;
/// re-exported so that the IR's consumers need not depend on the parser.
pub use statecheck_syntax::ast::{BinOp, UnOp, VarKind};
