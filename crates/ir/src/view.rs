//! What a trace shows (the JSON trace contract): per instance its state paths with their
//! `in()` expressions, the non-event variables, and the events. One view for every renderer:
//! the CLI's table, JSON, CSV and VCD, the generated C harness's observer and the studio.

use crate::interp::eval;
use crate::program::{ExprId, Program, SlotId, SlotRole, ValueKind};
use statecheck_model::{Model, NodeKind};

/// A state of an instance, as a trace shows it.
#[derive(Clone, Debug)]
pub struct StateView {
    /// Its dotted path within the chart (`Go.GoLeft`).
    pub path: String,
    /// The lowering's expression "this state is active".
    pub active: ExprId,
    /// True for a simple (leaf) state.
    pub leaf: bool,
    /// Its index among its chart's states (what a drawing of the chart refers to).
    pub id: usize,
}

/// An observable instance.
#[derive(Clone, Debug)]
pub struct InstanceView {
    /// Instance name, e.g. `fam[1]`.
    pub name: String,
    /// Its non-root, non-region states in chart order.
    pub states: Vec<StateView>,
}

/// A displayable (non-event) variable of an instance.
#[derive(Clone, Debug)]
pub struct VarView {
    /// `instance.var`.
    pub name: String,
    /// Its slot.
    pub slot: SlotId,
    /// How to show it.
    pub display: ValueKind,
    /// Bit width (for VCD).
    pub width: u32,
    /// True for booleans.
    pub is_bool: bool,
}

/// A column of a readable trace (the terminal table, a counterexample table): one slot,
/// shown once even when a connection makes it the value of several variables.
#[derive(Clone, Debug)]
pub struct Column {
    /// Its heading: the variable, or for a connected signal the connection
    /// (`a.out->b.in`, fan-out `a.out->b.in,c.in`), named from the writer.
    pub name: String,
    /// Every variable name it stands for (what `--show` patterns match).
    pub names: Vec<String>,
    /// Index into [`TraceView::vars`] (or [`TraceView::events`] for an event column).
    pub index: usize,
}

/// Everything a trace prints of a program.
#[derive(Clone, Debug)]
pub struct TraceView {
    /// Instances in declaration order.
    pub instances: Vec<InstanceView>,
    /// All non-event variables, instance by instance (the JSON, CSV and VCD contract).
    pub vars: Vec<VarView>,
    /// All events: (`instance.event`, slot).
    pub events: Vec<(String, SlotId)>,
    /// The variables a readable trace shows: each slot once (see [`Column`]), all of them
    /// unless [`TraceView::select`] chose some.
    pub var_columns: Vec<Column>,
    /// The events a readable trace shows, likewise.
    pub event_columns: Vec<Column>,
}

impl TraceView {
    /// The view of a lowered system of `model`.
    pub fn new(model: &Model, p: &Program) -> TraceView {
        let mut instances = Vec::new();
        let mut vars = Vec::new();
        let mut events = Vec::new();
        for inst in &p.instances {
            let Some(chart) = model.charts.get(inst.chart as usize) else {
                // Kept (without states) so that instance `i` of the view is instance `i` of
                // the program.
                instances.push(InstanceView {
                    name: inst.name.clone(),
                    states: Vec::new(),
                });
                continue;
            };
            let states = chart
                .states
                .iter()
                .enumerate()
                .filter(|(s, node)| *s != 0 && !node.is_region)
                .filter_map(|(s, node)| {
                    Some(StateView {
                        path: node.path.clone(),
                        active: *inst.active.get(s)?,
                        leaf: matches!(node.kind, NodeKind::Simple),
                        id: s,
                    })
                })
                .collect();
            instances.push(InstanceView {
                name: inst.name.clone(),
                states,
            });
            for (v, var) in chart.vars.iter().enumerate() {
                let slot = inst.var_slots[v];
                let Some(s) = p.slots.get(slot as usize) else {
                    continue;
                };
                let name = format!("{}.{}", inst.name, var.name);
                if var.is_event {
                    events.push((name, slot));
                } else {
                    vars.push(VarView {
                        name,
                        slot,
                        display: s.display.clone(),
                        width: s.width().max(1),
                        is_bool: s.display == ValueKind::Bool,
                    });
                }
            }
        }
        let var_names: Vec<(String, SlotId)> =
            vars.iter().map(|v| (v.name.clone(), v.slot)).collect();
        let var_columns = columns(model, p, &var_names);
        let event_columns = columns(model, p, &events);
        TraceView {
            instances,
            vars,
            events,
            var_columns,
            event_columns,
        }
    }

    /// Keep only the columns with a variable name matched by one of `patterns` (globs: `*`
    /// any characters, `?` one; each may list several separated by commas; no pattern keeps
    /// every column). Returns the patterns that matched nothing.
    pub fn select(&mut self, patterns: &[String]) -> Vec<String> {
        let globs: Vec<&str> = patterns
            .iter()
            .flat_map(|p| p.split(','))
            .map(str::trim)
            .filter(|g| !g.is_empty())
            .collect();
        if globs.is_empty() {
            return Vec::new();
        }
        let hit = |c: &Column| globs.iter().any(|g| c.names.iter().any(|n| glob(g, n)));
        let unmatched = globs
            .iter()
            .filter(|g| {
                !self
                    .var_columns
                    .iter()
                    .chain(&self.event_columns)
                    .any(|c| c.names.iter().any(|n| glob(g, n)))
            })
            .map(|g| g.to_string())
            .collect();
        self.var_columns.retain(|c| hit(c));
        self.event_columns.retain(|c| hit(c));
        unmatched
    }

    /// Active state paths of instance `i` in `slots` (`leaves_only` drops composites).
    pub fn active(&self, p: &Program, i: usize, slots: &[i64], leaves_only: bool) -> Vec<String> {
        self.instances[i]
            .states
            .iter()
            .filter(|s| !leaves_only || s.leaf)
            .filter(|s| eval(&p.nodes, slots, s.active).is_ok_and(|v| v != 0))
            .map(|s| s.path.clone())
            .collect()
    }

    /// Chart state indices of the active states of instance `i` in `slots` (for drawing).
    pub fn active_ids(&self, p: &Program, i: usize, slots: &[i64]) -> Vec<usize> {
        self.instances[i]
            .states
            .iter()
            .filter(|s| eval(&p.nodes, slots, s.active).is_ok_and(|v| v != 0))
            .map(|s| s.id)
            .collect()
    }

    /// Names of the events present in `slots`.
    pub fn present_events(&self, slots: &[i64]) -> Vec<String> {
        self.events
            .iter()
            .filter(|(_, s)| slots.get(*s as usize).is_some_and(|v| *v != 0))
            .map(|(n, _)| n.clone())
            .collect()
    }
}

/// One column per slot among `named` (in the order of their first variable), named from the
/// variable that owns the slot (the writer of a connection) followed by the others.
fn columns(model: &Model, p: &Program, named: &[(String, SlotId)]) -> Vec<Column> {
    let mut out: Vec<Column> = Vec::new();
    for (k, (name, slot)) in named.iter().enumerate() {
        if let Some(c) = out.iter_mut().find(|c| named[c.index].1 == *slot) {
            c.names.push(name.clone());
            continue;
        }
        out.push(Column {
            name: name.clone(),
            names: vec![name.clone()],
            index: k,
        });
    }
    for c in &mut out {
        if c.names.len() < 2 {
            continue;
        }
        let slot = named[c.index].1;
        // The owner of the slot is the writer; the others read it through a connection.
        let owner = match p.slots.get(slot as usize).map(|s| &s.role) {
            Some(SlotRole::Var { instance, var }) => {
                p.instances.get(*instance as usize).and_then(|i| {
                    let chart = model.charts.get(i.chart as usize)?;
                    let v = chart.vars.get(*var as usize)?;
                    Some(format!("{}.{}", i.name, v.name))
                })
            }
            _ => None,
        };
        let pos = owner
            .and_then(|o| c.names.iter().position(|n| *n == o))
            .unwrap_or(0);
        let mut names = c.names.clone();
        let writer = names.remove(pos);
        c.index = named
            .iter()
            .position(|(n, _)| *n == writer)
            .unwrap_or(c.index);
        c.name = format!("{writer}->{}", names.join(","));
    }
    out
}

/// True when `name` matches the glob `pat` (`*` any run of characters, `?` one character).
pub fn glob(pat: &str, name: &str) -> bool {
    let (p, n): (Vec<char>, Vec<char>) = (pat.chars().collect(), name.chars().collect());
    // Iterative matching with one backtrack point: linear in practice, never recursive.
    let (mut i, mut j) = (0, 0);
    let mut star: Option<(usize, usize)> = None;
    while j < n.len() {
        if i < p.len() && (p[i] == '?' || p[i] == n[j]) {
            i += 1;
            j += 1;
        } else if i < p.len() && p[i] == '*' {
            star = Some((i, j));
            i += 1;
        } else if let Some((si, sj)) = star {
            i = si + 1;
            j = sj + 1;
            star = Some((si, sj + 1));
        } else {
            return false;
        }
    }
    p[i..].iter().all(|c| *c == '*')
}

/// Names of the values of every slot, where they have names: enum literals, and the child
/// states of each active-state selector (so generated code can name states in enums).
pub fn value_names(model: &Model, p: &Program) -> Vec<Option<Vec<String>>> {
    p.slots
        .iter()
        .map(|s| match (&s.display, &s.role) {
            (ValueKind::Enum(names), _) => Some(names.clone()),
            (_, SlotRole::Region { instance, node }) => {
                let inst = p.instances.get(*instance as usize)?;
                let chart = model.charts.get(inst.chart as usize)?;
                match &chart.states.get(*node as usize)?.kind {
                    NodeKind::Or { children, .. } => Some(
                        children
                            .iter()
                            .map(|c| {
                                chart
                                    .states
                                    .get(*c as usize)
                                    .map_or_else(|| c.to_string(), |n| n.name.clone())
                            })
                            .collect(),
                    ),
                    _ => None,
                }
            }
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::glob;

    #[test]
    fn globs_match_as_in_a_shell() {
        assert!(glob("fam.*", "fam.stallNow"));
        assert!(glob("*.stall*", "fam[1].stallNow"));
        assert!(glob("a?c", "abc"));
        assert!(!glob("a?c", "abbc"));
        assert!(glob("*", ""));
        assert!(!glob("fam.*", "env.stallNow"));
        assert!(glob("*a*b", "xaxxab"));
        assert!(!glob("*a*b", "xaxxa"));
        assert!(glob("exact", "exact"));
        assert!(!glob("exact", "exactly"));
    }
}
