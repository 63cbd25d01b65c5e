//! The portfolio's errors: a bad option, found before any engine runs.

/// Why [`verify`](crate::verify) could not run.
#[derive(Debug)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
}

/// The kinds of [`Error`].
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The explicit engine refused its options (an unknown property, threads).
    Explicit(statecheck_explicit::Error),
    /// A property name the program does not have.
    UnknownProperty(statecheck_ir::verdict::UnknownProperty),
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.kind {
            ErrorKind::Explicit(e) => e.fmt(f),
            ErrorKind::UnknownProperty(u) => u.fmt(f),
        }
    }
}

impl std::error::Error for Error {}

impl From<statecheck_explicit::Error> for Error {
    fn from(e: statecheck_explicit::Error) -> Error {
        Error {
            kind: ErrorKind::Explicit(e),
        }
    }
}

impl From<statecheck_ir::verdict::UnknownProperty> for Error {
    fn from(u: statecheck_ir::verdict::UnknownProperty) -> Error {
        Error {
            kind: ErrorKind::UnknownProperty(u),
        }
    }
}
