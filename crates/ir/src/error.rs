//! Run-time errors of a tick, shared by the reference evaluator (`interp.rs`) and the register
//! code (`vm/run.rs`), which both report them the same way.

use crate::program::SiteId;
use statecheck_model::ops;

/// Why a tick stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RuntimeError {
    /// What went wrong.
    pub kind: RuntimeErrorKind,
    /// Where (index into [`Program::sites`](crate::Program::sites)).
    pub site: SiteId,
}

/// The kinds of run-time error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RuntimeErrorKind {
    /// A value outside the destination's range.
    Range {
        /// The value.
        value: i64,
        /// Allowed minimum.
        lo: i64,
        /// Allowed maximum.
        hi: i64,
    },
    /// Division or remainder by zero.
    DivisionByZero,
    /// Shift amount outside `0..=62`.
    BadShift,
    /// A 64-bit overflow in an intermediate result.
    Overflow,
}

impl RuntimeErrorKind {
    /// The built-in property this error violates.
    pub fn builtin_property(&self) -> &'static str {
        self.builtin().name()
    }

    /// The built-in property this error violates.
    pub fn builtin(&self) -> crate::verdict::Builtin {
        use crate::verdict::Builtin;
        match self {
            RuntimeErrorKind::Range { .. } | RuntimeErrorKind::Overflow => Builtin::RangeOverflow,
            RuntimeErrorKind::DivisionByZero => Builtin::DivisionByZero,
            RuntimeErrorKind::BadShift => Builtin::BadShift,
        }
    }

    /// A sentence describing the error.
    pub fn describe(&self) -> String {
        match self {
            RuntimeErrorKind::Range { value, lo, hi } => {
                format!("value {value} is out of range {lo}..{hi}")
            }
            RuntimeErrorKind::DivisionByZero => "division by zero".into(),
            RuntimeErrorKind::BadShift => "shift amount outside 0..62".into(),
            RuntimeErrorKind::Overflow => "arithmetic overflow".into(),
        }
    }
}

/// Errors travel boxed so that `Result<i64, Fault>` fits in two registers on the hot path.
pub(crate) type Fault = Box<RuntimeError>;

pub(crate) fn fault(kind: RuntimeErrorKind, site: SiteId) -> Fault {
    Box::new(RuntimeError { kind, site })
}

pub(crate) fn op_fault(e: ops::OpError, site: SiteId) -> Fault {
    let kind = match e {
        ops::OpError::DivisionByZero => RuntimeErrorKind::DivisionByZero,
        ops::OpError::BadShift => RuntimeErrorKind::BadShift,
        ops::OpError::Overflow => RuntimeErrorKind::Overflow,
    };
    fault(kind, site)
}
