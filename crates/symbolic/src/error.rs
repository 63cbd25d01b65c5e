//! The symbolic engines' errors, for the public functions that can fail outright (a verdict
//! `unknown` is not an error: it is an [`Outcome`](crate::engine::Outcome)).

/// Why a certificate or a reduction could not be had.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
}

/// The kinds of [`Error`].
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A certificate file is malformed.
    CertificateSyntax {
        /// The line (1-based), when one is to blame.
        line: Option<usize>,
        /// What is wrong.
        message: String,
    },
    /// A certificate does not prove its property: the named obligation is satisfiable.
    CertificateFails {
        /// `an initial state violates the invariant`, `the invariant is not inductive`, ...
        obligation: &'static str,
    },
    /// The SAT solver gave no answer.
    SolverFailed,
    /// A time or stop limit ended the computation (the sentence says which).
    Limit(String),
}

impl Error {
    pub(crate) fn syntax(line: Option<usize>, message: impl Into<String>) -> Error {
        Error {
            kind: ErrorKind::CertificateSyntax {
                line,
                message: message.into(),
            },
        }
    }

    pub(crate) fn of(kind: ErrorKind) -> Error {
        Error { kind }
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.kind {
            ErrorKind::CertificateSyntax {
                line: Some(l),
                message,
            } => write!(f, "line {l}: {message}"),
            ErrorKind::CertificateSyntax {
                line: None,
                message,
            } => f.write_str(message),
            ErrorKind::CertificateFails { obligation } => {
                write!(f, "the certificate fails: {obligation}")
            }
            ErrorKind::SolverFailed => f.write_str("the SAT solver failed"),
            ErrorKind::Limit(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for Error {}
