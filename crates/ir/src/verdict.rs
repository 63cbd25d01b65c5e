//! The verdict vocabulary every engine, generator and front end shares: which properties a
//! program has (its own, then the built-ins), their kinds, the verdicts and the result of
//! deciding one property.
//!
//! This is the one place that lists the built-in properties and selects properties by name;
//! what a property *means* is compiled by the lowering into [`Program::properties`].

use crate::error::RuntimeError;
use crate::program::{Program, PropertyKind};

/// A built-in property: no run-time error of one kind in any reachable tick.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Builtin {
    /// No value leaves its range and no intermediate result overflows 64 bits.
    RangeOverflow,
    /// No division or remainder by zero.
    DivisionByZero,
    /// No shift amount outside `0..=62`.
    BadShift,
}

impl Builtin {
    /// Every built-in property, in report order.
    pub const ALL: [Builtin; 3] = [
        Builtin::RangeOverflow,
        Builtin::DivisionByZero,
        Builtin::BadShift,
    ];

    /// Its name (a contract: property names appear in JSON, scenarios and docs).
    pub const fn name(self) -> &'static str {
        match self {
            Builtin::RangeOverflow => "no_range_overflow",
            Builtin::DivisionByZero => "no_division_by_zero",
            Builtin::BadShift => "no_bad_shift",
        }
    }

    /// Its position in [`Builtin::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The built-in property called `name`, if there is one.
    pub fn named(name: &str) -> Option<Builtin> {
        Builtin::ALL.into_iter().find(|b| b.name() == name)
    }
}

/// Names of the built-in properties, in report order.
pub const BUILTINS: [&str; 3] = [
    Builtin::RangeOverflow.name(),
    Builtin::DivisionByZero.name(),
    Builtin::BadShift.name(),
];

/// What kind of property (as printed and in JSON).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PropKind {
    /// `invariant NAME: expr [assuming expr];`
    Invariant,
    /// `reachable NAME: expr;`
    Reachable,
    /// `respond NAME: trigger => response within N;`
    Respond,
    /// An observer chart's `error` state is never entered.
    Observer,
    /// A built-in property (no run-time error of a kind).
    Builtin,
    /// `ltl NAME: formula;`
    Ltl,
    /// `ctl NAME: formula;`
    Ctl,
    /// `nonblocking NAME: expr;`
    Nonblocking,
}

impl PropKind {
    /// The JSON and table word.
    pub fn as_str(self) -> &'static str {
        match self {
            PropKind::Invariant => "invariant",
            PropKind::Reachable => "reachable",
            PropKind::Respond => "respond",
            PropKind::Observer => "observer",
            PropKind::Builtin => "builtin",
            PropKind::Ltl => "ltl",
            PropKind::Ctl => "ctl",
            PropKind::Nonblocking => "nonblocking",
        }
    }

    /// The kind of a program's own property.
    pub fn of(kind: &PropertyKind) -> PropKind {
        match kind {
            PropertyKind::Invariant { .. } => PropKind::Invariant,
            PropertyKind::Reachable { .. } => PropKind::Reachable,
            PropertyKind::Respond { .. } => PropKind::Respond,
            PropertyKind::Observer { .. } => PropKind::Observer,
        }
    }
}

/// Where a property comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// The program's own property at this index of [`Program::properties`].
    Own(usize),
    /// A built-in property.
    Builtin(Builtin),
}

/// One property of a program, by name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PropertyRef {
    /// Its name.
    pub name: String,
    /// Its kind.
    pub kind: PropKind,
    /// Where it comes from.
    pub source: Source,
}

/// Every property of a program: its own in declaration order, then the built-ins.
pub fn properties(program: &Program) -> Vec<PropertyRef> {
    let own = program
        .properties
        .iter()
        .enumerate()
        .map(|(i, p)| PropertyRef {
            name: p.name.clone(),
            kind: PropKind::of(&p.kind),
            source: Source::Own(i),
        });
    let builtins = Builtin::ALL.into_iter().map(|b| PropertyRef {
        name: b.name().to_string(),
        kind: PropKind::Builtin,
        source: Source::Builtin(b),
    });
    own.chain(builtins).collect()
}

/// A property name that the program does not have.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownProperty {
    /// The name asked for.
    pub name: String,
    /// The names the program has, in report order.
    pub known: Vec<String>,
}

impl std::fmt::Display for UnknownProperty {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "no property named `{}`; the properties are: {}",
            self.name,
            self.known.join(", ")
        )
    }
}

impl std::error::Error for UnknownProperty {}

/// The properties named in `names` (all of them when `names` is empty), in report order.
pub fn select(program: &Program, names: &[String]) -> Result<Vec<PropertyRef>, UnknownProperty> {
    let all = properties(program);
    if names.is_empty() {
        return Ok(all);
    }
    // Sets, not linear searches: 10^4 names against 10^4 properties was quadratic.
    let known: std::collections::BTreeSet<&str> = all.iter().map(|s| s.name.as_str()).collect();
    if let Some(bad) = names.iter().find(|n| !known.contains(n.as_str())) {
        return Err(UnknownProperty {
            name: bad.clone(),
            known: all.into_iter().map(|s| s.name).collect(),
        });
    }
    let wanted: std::collections::BTreeSet<&str> = names.iter().map(String::as_str).collect();
    Ok(all
        .into_iter()
        .filter(|s| wanted.contains(s.name.as_str()))
        .collect())
}

/// The answer for one property.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Holds in every reachable state (exhaustive).
    Proved,
    /// A counterexample exists.
    Violated,
    /// A `reachable` target was reached (a witness exists).
    Reachable,
    /// A `reachable` target is reached in no reachable state (exhaustive).
    Unreachable,
    /// Nothing found up to the depth bound.
    Bounded,
    /// A limit stopped the run before an answer.
    Unknown,
}

impl Verdict {
    /// The JSON and table word.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Proved => "proved",
            Verdict::Violated => "violated",
            Verdict::Reachable => "reachable",
            Verdict::Unreachable => "unreachable",
            Verdict::Bounded => "bounded",
            Verdict::Unknown => "unknown",
        }
    }

    /// True for an answer that holds whatever the bounds: proved, violated, reachable,
    /// unreachable.
    pub fn is_definitive(self) -> bool {
        !matches!(self, Verdict::Bounded | Verdict::Unknown)
    }
}

/// The result for one property.
#[derive(Clone, Debug)]
pub struct PropResult {
    /// Property name.
    pub name: String,
    /// Its kind.
    pub kind: PropKind,
    /// The verdict.
    pub verdict: Verdict,
    /// Ticks of the counterexample or witness; otherwise the depth explored.
    pub depth: u64,
    /// The input vectors of each tick (in `Program::inputs` order) of a shortest
    /// counterexample or witness, ending with the deciding tick.
    pub counterexample: Option<Vec<Vec<i64>>>,
    /// The run-time error, for a violated built-in property.
    pub error: Option<RuntimeError>,
    /// Why a counterexample is missing, if it is.
    pub note: Option<String>,
    /// For a lasso counterexample of a temporal property: the first tick of the loop (the
    /// state after tick `loop_start - 1` recurs after the last tick).
    pub loop_start: Option<u64>,
}

impl PropResult {
    /// An `unknown` result with nothing else known.
    pub fn unknown(name: &str, kind: PropKind) -> PropResult {
        PropResult {
            name: name.to_string(),
            kind,
            verdict: Verdict::Unknown,
            depth: 0,
            counterexample: None,
            error: None,
            note: None,
            loop_start: None,
        }
    }
}
