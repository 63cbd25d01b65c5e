//! What a name can mean where it is written: global items, a chart's variables and states, a
//! system's instances, and a function's parameters.

use crate::model::{Chart, ChartId, EnumDef, StateId, VarId};
use crate::types::{EnumId, Type};
use statecheck_base::Span;
use statecheck_syntax::ast;
use std::collections::HashMap;

/// File-level declarations, collected before any chart is checked.
#[derive(Clone, Default)]
pub(crate) struct Globals {
    /// Constants by name: type, value, declaration span.
    pub consts: HashMap<String, (Type, i64, Span)>,
    /// Every constant of the file with its declaration span, including those not yet checked
    /// (to tell "declared later" from "unknown").
    pub declared_consts: HashMap<String, Span>,
    /// Constants in declaration order (for the model).
    pub const_order: Vec<String>,
    /// Enum definitions.
    pub enums: Vec<EnumDef>,
    /// Enum ids by name.
    pub enum_ids: HashMap<String, EnumId>,
    /// Which enums declare a literal of a given name.
    pub literal_owners: HashMap<String, Vec<EnumId>>,
    /// Functions by name, with their declaration index (a function may call only earlier ones).
    /// All functions are entered before any body is checked, so a call to a later one is
    /// reported as such rather than as an unknown name.
    pub fns: HashMap<String, (usize, ast::FnDecl)>,
    /// Tick length in milliseconds.
    pub tick_ms: Option<i64>,
    /// Top-level chart names to ids.
    pub chart_ids: HashMap<String, ChartId>,
}

/// One instance name visible in a system scope: a single instance or an array.
#[derive(Clone, Debug)]
pub(crate) struct InstanceGroup {
    /// Flat index of element 0.
    pub first: u32,
    /// Number of elements; `None` for a plain (non-array) instance.
    pub len: Option<u32>,
    /// The chart instantiated.
    pub chart: ChartId,
}

/// Where names are looked up while checking an expression.
pub(crate) struct Scope<'a> {
    /// The chart whose variables and states are visible unqualified.
    pub chart: Option<&'a Chart>,
    /// Instance names visible as the first path segment (systems and observers).
    pub instances: Option<&'a HashMap<String, InstanceGroup>>,
    /// All charts, to resolve `inst.var` and `in(inst.path)`.
    pub charts: &'a [Chart],
    /// Function parameters and `let` bindings, substituted by value.
    pub locals: Vec<(String, crate::model::Expr)>,
    /// Index of the function being checked: only earlier functions may be called.
    pub fn_limit: usize,
}

impl Scope<'static> {
    /// A scope that sees only file-level declarations: constants, enums and the functions
    /// before index `fn_limit` (`usize::MAX`: all of them). For constant expressions
    /// (initial values, array lengths, arguments, bounds).
    pub fn constants(fn_limit: usize) -> Scope<'static> {
        Scope {
            chart: None,
            instances: None,
            charts: &[],
            locals: Vec::new(),
            fn_limit,
        }
    }
}

impl<'a> Scope<'a> {
    /// A variable of this scope's chart.
    pub fn own_var(&self, name: &str) -> Option<VarId> {
        self.chart.and_then(|c| c.var(name))
    }

    /// A state of a chart by its path segments (names from the root).
    pub fn state_in(chart: &Chart, names: &[&str]) -> Option<StateId> {
        chart.state_by_path(&names.join("."))
    }
}
