//! The synthesis library's typed errors: a limit that stopped an engine (with the figures it
//! had reached), or a supervisor or system that does not fit the expected interface.

use std::fmt;

/// What went wrong, with [`ErrorKind`] saying which kind of failure it is.
#[derive(Clone, Debug)]
pub struct Error {
    /// The kind of failure.
    pub kind: ErrorKind,
}

/// Which resource limit stopped an engine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// More states than `--max-states`.
    States(u64),
    /// More memory (the engine's own estimate of its data) than `--max-memory`, in bytes.
    Memory(u64),
    /// The time budget (`--timeout`) ran out.
    Time,
    /// The caller asked the engine to stop (its stop flag was set).
    Stopped,
}

/// Figures reached when a limit stopped an engine.
#[derive(Clone, Debug, Default)]
pub struct Partial {
    /// The phase it was in (`reachability`, `fixpoint`, `guards`).
    pub phase: &'static str,
    /// Product states found so far (explicit: enumerated; symbolic: in the reached set).
    pub states: f64,
    /// Seconds spent.
    pub seconds: f64,
    /// The engine's estimate of the memory its data used, in bytes.
    pub bytes: u64,
}

/// The kinds of [`Error`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A limit was hit before the answer was known (the CLI's exit 3, `unknown`).
    Limit {
        /// Which limit.
        limit: Limit,
        /// How far the engine got.
        partial: Partial,
    },
    /// The requested system does not exist, or none was named where several exist.
    System(String),
    /// A supervisor system does not follow the bridge interface, or its run failed.
    Supervisor(String),
    /// An engine name that is not one of `explicit`, `symbolic`, `auto`.
    Engine(String),
}

impl Error {
    /// An error of `kind`.
    pub fn new(kind: ErrorKind) -> Error {
        Error { kind }
    }

    pub(crate) fn supervisor(msg: impl Into<String>) -> Error {
        Error::new(ErrorKind::Supervisor(msg.into()))
    }
}

impl From<String> for Error {
    fn from(s: String) -> Error {
        Error::supervisor(s)
    }
}

impl From<&str> for Error {
    fn from(s: &str) -> Error {
        Error::supervisor(s)
    }
}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Limit::States(n) => write!(f, "the state limit ({n} states) was reached"),
            Limit::Memory(b) => write!(f, "the memory limit ({} MiB) was reached", b >> 20),
            Limit::Time => write!(f, "the time limit was reached"),
            Limit::Stopped => write!(f, "stopped"),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            ErrorKind::Limit { limit, partial } => write!(
                f,
                "{limit} during {} after {:.3} s ({:.0} product states, about {} MiB)",
                partial.phase,
                partial.seconds,
                partial.states,
                partial.bytes >> 20
            ),
            ErrorKind::System(s) | ErrorKind::Supervisor(s) => f.write_str(s),
            ErrorKind::Engine(s) => write!(f, "unknown engine `{s}` (explicit, symbolic, auto)"),
        }
    }
}

impl std::error::Error for Error {}
