//! The explicit engine's errors: bad options, found before any exploration.

use statecheck_ir::verdict::UnknownProperty;

/// Why [`verify`](crate::verify) could not start.
#[derive(Debug)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
}

/// The kinds of [`Error`].
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A property name the program does not have.
    UnknownProperty(UnknownProperty),
    /// The worker threads could not be started.
    Threads {
        /// How many were asked for.
        threads: usize,
        /// The operating system's reason.
        reason: String,
    },
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.kind {
            ErrorKind::UnknownProperty(u) => u.fmt(f),
            ErrorKind::Threads { threads, reason } => {
                write!(f, "cannot start {threads} threads: {reason}")
            }
        }
    }
}

impl std::error::Error for Error {}

impl From<UnknownProperty> for Error {
    fn from(u: UnknownProperty) -> Error {
        Error {
            kind: ErrorKind::UnknownProperty(u),
        }
    }
}
