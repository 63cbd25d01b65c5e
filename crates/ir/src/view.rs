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

/// Everything a trace prints of a program.
#[derive(Clone, Debug)]
pub struct TraceView {
    /// Instances in declaration order.
    pub instances: Vec<InstanceView>,
    /// All non-event variables, instance by instance.
    pub vars: Vec<VarView>,
    /// All events: (`instance.event`, slot).
    pub events: Vec<(String, SlotId)>,
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
        TraceView {
            instances,
            vars,
            events,
        }
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
