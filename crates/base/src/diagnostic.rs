//! Diagnostics as data: severity, stable code, message, labelled spans and a hint.

use crate::Span;

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// Informational; never fails a command.
    Note,
    /// A design-rule finding or a suspicious construct; the model still runs.
    Warning,
    /// The model cannot be used.
    Error,
}

/// A secondary span with a message, shown beside the primary one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What to say there.
    pub message: String,
}

/// One finding about a model, with a stable code such as `E0201` or `W0304`.
///
/// Codes are part of the contract: documentation and tests refer to them, so a code keeps its
/// meaning forever and new findings get new codes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// Error, warning or note.
    pub severity: Severity,
    /// Stable code, e.g. `E0102`.
    pub code: &'static str,
    /// One-line summary.
    pub message: String,
    /// The offending span.
    pub span: Span,
    /// What to say under the primary span (may be empty).
    pub label: String,
    /// Related spans.
    pub secondary: Vec<Label>,
    /// How to fix it, if we know.
    pub hint: Option<String>,
}

impl Diagnostic {
    /// An error with the given code, message and primary span.
    pub fn error(code: &'static str, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic::new(Severity::Error, code, message, span)
    }

    /// A warning with the given code, message and primary span.
    pub fn warning(code: &'static str, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic::new(Severity::Warning, code, message, span)
    }

    fn new(
        severity: Severity,
        code: &'static str,
        message: impl Into<String>,
        span: Span,
    ) -> Diagnostic {
        Diagnostic {
            severity,
            code,
            message: message.into(),
            span,
            label: String::new(),
            secondary: Vec::new(),
            hint: None,
        }
    }

    /// Set the text shown under the primary span.
    pub fn with_label(mut self, label: impl Into<String>) -> Diagnostic {
        self.label = label.into();
        self
    }

    /// Add a related span.
    pub fn with_secondary(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.secondary.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    /// Set the hint.
    pub fn with_hint(mut self, hint: impl Into<String>) -> Diagnostic {
        self.hint = Some(hint.into());
        self
    }

    /// True for errors.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}
