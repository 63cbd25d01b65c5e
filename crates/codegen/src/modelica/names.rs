//! Modelica names and types of a program: one enumeration type per hierarchy level (the paper's
//! `MainStateT`, `GoStateT`), the model's own enums, and a unique identifier for every slot,
//! type, helper function and view variable (Modelica keywords and built-ins avoided).

use crate::common::ident;
use statecheck_ir::{Program, SlotId, SlotRole, ValueKind};
use statecheck_model::{Model, NodeKind, StateId, Type};
use std::collections::{BTreeMap, BTreeSet};

/// The Modelica type of a slot or of a translated expression.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Ty {
    /// `Integer`.
    Int,
    /// `Boolean`.
    Bool,
    /// An enumeration: index into [`Names::enums`].
    Enum(usize),
}

/// A generated `type T = enumeration(...)`.
pub(crate) struct EnumType {
    /// Type name.
    pub name: String,
    /// Literal names in value order (a level type ends with its `InActive` literal).
    pub literals: Vec<String>,
    /// Description string.
    pub doc: String,
    /// Name of the function mapping a 0-based index to a literal (emitted only when used).
    pub of_int: String,
}

/// One hierarchy level: an exclusive node with its active-child selector.
pub(crate) struct Level {
    /// The selector slot (the IR's region slot).
    pub slot: SlotId,
    /// Instance index.
    pub instance: u32,
    /// The exclusive node.
    pub node: StateId,
    /// The paper's state variable of the level: the selector, or `InActive` when the node is
    /// not active.
    pub view: String,
    /// Its enumeration type.
    pub ty: usize,
}

/// Names of the helper functions (emitted only when used).
pub(crate) struct Helpers {
    /// Bitwise and.
    pub and: String,
    /// Bitwise or.
    pub or: String,
    /// Bitwise exclusive or.
    pub xor: String,
    /// Left shift.
    pub shl: String,
    /// Arithmetic right shift.
    pub shr: String,
}

/// Every name the generated model uses.
pub(crate) struct Names {
    /// The model (class) name.
    pub model: String,
    /// Variable name of each slot.
    pub vars: Vec<String>,
    /// Type of each slot.
    pub tys: Vec<Ty>,
    /// Enumeration types: hierarchy levels first, then the model's enums.
    pub enums: Vec<EnumType>,
    /// Hierarchy levels in slot order.
    pub levels: Vec<Level>,
    /// The tick period parameter.
    pub period: String,
    /// Integer temporaries (an array).
    pub tmp: String,
    /// Boolean temporaries (an array).
    pub tmpb: String,
    /// Expression locals (an array).
    pub loc: String,
    /// State coverage counters (an array).
    pub state_cov: String,
    /// Transition coverage counters (an array).
    pub trans_cov: String,
    /// Helper functions.
    pub helpers: Helpers,
}

/// Modelica keywords and the built-in names a generated model must not shadow, separated by
/// whitespace.
const RESERVED: &str = "\
    algorithm and annotation block break class connect connector constant constrainedby \
    der discrete each else elseif elsewhen encapsulated end enumeration equation \
    expandable extends external false final flow for function if import impure in \
    initial inner input loop model not operator or outer output package parameter \
    partial protected public pure record redeclare replaceable return stream then true \
    type when while within time Real Integer Boolean String sample pre edge change \
    terminal noEvent smooth abs sign sqrt div mod rem ceil floor integer min max sum \
    product size ndims fill zeros ones cat array assert terminate reinit delay \
    cardinality homotopy semiLinear inStream actualStream spatialDistribution \
    getInstanceName Clock hold previous subSample superSample shiftSample backSample \
    noClock interval firstTick AssertionLevel StateSelect ExternalObject Connections \
    Modelica scalar vector matrix transpose identity diagonal linspace cross skew \
    outerProduct symmetric sin cos tan asin acos atan atan2 sinh cosh tanh exp log log10 \
    initialStructuralState Subtask";

/// A Modelica identifier made of `text`'s letters, digits and underscores, never a keyword or
/// built-in.
pub(crate) fn mo_ident(text: &str) -> String {
    let s = ident(text);
    if RESERVED.split_whitespace().any(|w| w == s) {
        format!("{s}_")
    } else {
        s
    }
}

/// Hands out unique names in one scope.
#[derive(Default)]
struct Registry {
    taken: BTreeSet<String>,
}

impl Registry {
    fn fresh(&mut self, base: &str) -> String {
        let base = mo_ident(base);
        let mut name = base.clone();
        let mut k = 2;
        while !self.taken.insert(name.clone()) {
            name = format!("{base}_{k}");
            k += 1;
        }
        name
    }
}

/// Unique literal names for `names` (sanitized; numbered on clashes).
fn literals(names: &[String]) -> Vec<String> {
    let mut reg = Registry::default();
    names.iter().map(|n| reg.fresh(n)).collect()
}

fn lc_first(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_lowercase().chain(c).collect(),
        None => String::new(),
    }
}

#[derive(Clone, PartialEq, Eq, PartialOrd, Ord)]
enum TypeKey {
    Level(u32, StateId),
    User(u32),
    Anon(Vec<String>),
}

impl Names {
    /// Name everything in `p` (a lowered system of `model`).
    pub(crate) fn new(p: &Program, model: &Model) -> Names {
        let mut reg = Registry::default();
        let model_name = reg.fresh(&p.name);
        let period = reg.fresh("period");
        let tmp = reg.fresh("tmp");
        let tmpb = reg.fresh("tmpb");
        let loc = reg.fresh("loc");
        let state_cov = reg.fresh("stateCoverage");
        let trans_cov = reg.fresh("transitionCoverage");
        let helpers = Helpers {
            and: reg.fresh("scAnd"),
            or: reg.fresh("scOr"),
            xor: reg.fresh("scXor"),
            shl: reg.fresh("scShl"),
            shr: reg.fresh("scShr"),
        };
        // Types: every level first (the paper's state variable types), then the model's enums.
        let mut keys: BTreeMap<TypeKey, usize> = BTreeMap::new();
        let mut enums: Vec<EnumType> = Vec::new();
        let mut levels = Vec::new();
        let mut tys = vec![Ty::Int; p.slots.len()];
        for (k, s) in p.slots.iter().enumerate() {
            let SlotRole::Region { instance, node } = s.role else {
                continue;
            };
            let Some(inst) = p.instances.get(instance as usize) else {
                continue;
            };
            let chart = model.charts.get(inst.chart as usize);
            let state = chart.and_then(|c| c.states.get(node as usize));
            let path = state.map_or(String::new(), |n| n.path.clone());
            let level = if path.is_empty() {
                "Main".to_string()
            } else {
                ident(&path)
            };
            let key = TypeKey::Level(inst.chart, node);
            let ty = match keys.get(&key) {
                Some(t) => *t,
                None => {
                    let chart_name = chart.map_or(inst.name.as_str(), |c| c.name.as_str());
                    let mut lits = match &s.display {
                        ValueKind::Enum(n) => n.clone(),
                        _ => (0..=s.hi).map(|v| format!("S{v}")).collect(),
                    };
                    if let (Some(c), Some(n)) = (chart, state) {
                        if let NodeKind::Or { children, .. } = &n.kind {
                            lits = children
                                .iter()
                                .map(|ch| {
                                    c.states
                                        .get(*ch as usize)
                                        .map_or(String::new(), |x| x.name.clone())
                                })
                                .collect();
                        }
                    }
                    let mut inactive = "InActive".to_string();
                    while lits.iter().any(|l| ident(l) == inactive) {
                        inactive.push('_');
                    }
                    lits.push(inactive);
                    let name = reg.fresh(&format!("{chart_name}_{level}StateT"));
                    let where_ = if path.is_empty() {
                        format!("the top level of `{chart_name}`")
                    } else {
                        format!("`{chart_name}.{path}`")
                    };
                    enums.push(EnumType {
                        of_int: reg.fresh(&format!("{name}_of")),
                        name,
                        literals: literals(&lits),
                        doc: format!("active child of {where_}"),
                    });
                    keys.insert(key, enums.len() - 1);
                    enums.len() - 1
                }
            };
            tys[k] = Ty::Enum(ty);
            let view = format!("{}_{}State", inst.name, lc_first(&level));
            levels.push(Level {
                slot: k as SlotId,
                instance,
                node,
                view,
                ty,
            });
        }
        for (k, s) in p.slots.iter().enumerate() {
            if matches!(s.role, SlotRole::Region { .. }) {
                continue;
            }
            tys[k] = match (&s.display, &s.role) {
                (ValueKind::Enum(lits), role) => {
                    let user = match role {
                        SlotRole::Var { instance, var } | SlotRole::Input { instance, var } => {
                            user_enum(p, model, *instance, *var)
                        }
                        _ => None,
                    };
                    let key = match user {
                        Some(id) => TypeKey::User(id),
                        None => TypeKey::Anon(lits.clone()),
                    };
                    let ty = match keys.get(&key) {
                        Some(t) => *t,
                        None => {
                            let (base, doc) = match user.and_then(|id| model.enums.get(id as usize))
                            {
                                Some(e) => (e.name.clone(), format!("enum `{}`", e.name)),
                                None => (format!("{}T", s.name), format!("values of `{}`", s.name)),
                            };
                            let name = reg.fresh(&base);
                            enums.push(EnumType {
                                of_int: reg.fresh(&format!("{name}_of")),
                                name,
                                literals: literals(lits),
                                doc,
                            });
                            keys.insert(key, enums.len() - 1);
                            enums.len() - 1
                        }
                    };
                    Ty::Enum(ty)
                }
                (ValueKind::Bool, _) => Ty::Bool,
                (
                    _,
                    SlotRole::Started
                    | SlotRole::Pending { .. }
                    | SlotRole::Present { .. }
                    | SlotRole::Abort { .. }
                    | SlotRole::Visited { .. },
                ) => Ty::Bool,
                _ => Ty::Int,
            };
        }
        let vars = p.slots.iter().map(|s| reg.fresh(&s.name)).collect();
        for l in &mut levels {
            l.view = reg.fresh(&l.view);
        }
        Names {
            model: model_name,
            vars,
            tys,
            enums,
            levels,
            period,
            tmp,
            tmpb,
            loc,
            state_cov,
            trans_cov,
            helpers,
        }
    }

    /// `T.literal` for value `v` of enumeration `ty`, if it has one.
    pub(crate) fn literal(&self, ty: usize, v: i64) -> Option<String> {
        let e = self.enums.get(ty)?;
        let l = e.literals.get(usize::try_from(v).ok()?)?;
        Some(format!("{}.{l}", e.name))
    }
}

/// The model enum a chart variable is declared with.
fn user_enum(p: &Program, model: &Model, instance: u32, var: u32) -> Option<u32> {
    let inst = p.instances.get(instance as usize)?;
    let chart = model.charts.get(inst.chart as usize)?;
    match chart.vars.get(var as usize)?.ty {
        Type::Enum(id) => Some(id),
        _ => None,
    }
}
