//! What a trace shows (the JSON trace contract): instances with their state paths and `in()`
//! expressions, non-event variables, and events — computed exactly as the CLI's trace views.

use statecheck_ir::{ExprId, Program, SlotId, SlotRole, ValueKind};
use statecheck_model::{Model, NodeKind};

/// An observable instance.
#[derive(Clone, Debug)]
pub struct ObsInstance {
    /// Instance name, e.g. `fam[1]`.
    pub name: String,
    /// Non-root, non-region state paths with their `in()` expression and whether they are leaves.
    pub states: Vec<(String, ExprId, bool)>,
}

/// Everything a trace prints.
#[derive(Clone, Debug)]
pub struct Observables {
    /// Instances in declaration order.
    pub instances: Vec<ObsInstance>,
    /// Non-event variables: `instance.var`, slot, display.
    pub vars: Vec<(String, SlotId, ValueKind)>,
    /// Events: `instance.event`, slot.
    pub events: Vec<(String, SlotId)>,
}

impl Observables {
    /// The observables of a lowered system of `model`.
    pub fn new(model: &Model, p: &Program) -> Observables {
        let mut instances = Vec::new();
        let mut vars = Vec::new();
        let mut events = Vec::new();
        for inst in &p.instances {
            let Some(chart) = model.charts.get(inst.chart as usize) else {
                continue;
            };
            let states = chart
                .states
                .iter()
                .enumerate()
                .filter(|(s, node)| *s != 0 && !node.is_region)
                .map(|(s, node)| {
                    let leaf = matches!(node.kind, NodeKind::Simple);
                    (node.path.clone(), inst.active[s], leaf)
                })
                .collect();
            instances.push(ObsInstance {
                name: inst.name.clone(),
                states,
            });
            for (v, var) in chart.vars.iter().enumerate() {
                let slot = inst.var_slots[v];
                if slot == u32::MAX {
                    continue;
                }
                let name = format!("{}.{}", inst.name, var.name);
                if var.is_event {
                    events.push((name, slot));
                } else {
                    vars.push((name, slot, p.slots[slot as usize].display.clone()));
                }
            }
        }
        Observables {
            instances,
            vars,
            events,
        }
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
