//! What a tick shows — active states, variable values, present events — computed exactly as
//! `statecheck sim --json` does (`crates/cli/src/output/view.rs`): states from the lowering's
//! `InstanceLayout::active` expressions, values from the slots.

use statecheck_ir::{eval, Program, SlotId, ValueKind};
use statecheck_model::Model;

/// A displayable variable.
pub struct VarView {
    /// `instance.var`.
    pub name: String,
    /// Its slot.
    pub slot: SlotId,
    /// How to show it.
    pub display: ValueKind,
}

/// The observable parts of a program.
pub struct Views {
    /// Per instance: its name.
    pub instances: Vec<String>,
    /// Per instance: `(state path, in() expression, state id)` of every non-root,
    /// non-region state.
    pub states: Vec<Vec<(String, u32, usize)>>,
    /// All non-event variables, instance by instance.
    pub vars: Vec<VarView>,
    /// All events: (`instance.event`, slot).
    pub events: Vec<(String, SlotId)>,
}

impl Views {
    /// Collect the views of a program.
    pub fn new(model: &Model, p: &Program) -> Views {
        let mut states = Vec::new();
        let mut vars = Vec::new();
        let mut events = Vec::new();
        for inst in &p.instances {
            let Some(chart) = model.charts.get(inst.chart as usize) else {
                states.push(Vec::new());
                continue;
            };
            let st = chart
                .states
                .iter()
                .enumerate()
                .filter(|(s, node)| *s != 0 && !node.is_region)
                .filter_map(|(s, node)| Some((node.path.clone(), *inst.active.get(s)?, s)))
                .collect();
            states.push(st);
            for (v, var) in chart.vars.iter().enumerate() {
                let Some(&slot) = inst.var_slots.get(v) else {
                    continue;
                };
                if slot == u32::MAX {
                    continue;
                }
                let name = format!("{}.{}", inst.name, var.name);
                if var.is_event {
                    events.push((name, slot));
                } else {
                    vars.push(VarView {
                        name,
                        slot,
                        display: p.slots[slot as usize].display.clone(),
                    });
                }
            }
        }
        Views {
            instances: p.instances.iter().map(|i| i.name.clone()).collect(),
            states,
            vars,
            events,
        }
    }

    /// Active state paths of instance `i` in `slots`, in state order.
    pub fn active(&self, p: &Program, i: usize, slots: &[i64]) -> Vec<String> {
        self.states[i]
            .iter()
            .filter(|(_, e, _)| eval(&p.nodes, slots, *e).is_ok_and(|v| v != 0))
            .map(|(path, _, _)| path.clone())
            .collect()
    }

    /// Active state ids of instance `i` (for highlighting).
    pub fn active_ids(&self, p: &Program, i: usize, slots: &[i64]) -> Vec<usize> {
        self.states[i]
            .iter()
            .filter(|(_, e, _)| eval(&p.nodes, slots, *e).is_ok_and(|v| v != 0))
            .map(|(_, _, s)| *s)
            .collect()
    }

    /// Names of the events present in `slots`.
    pub fn present_events(&self, slots: &[i64]) -> Vec<String> {
        self.events
            .iter()
            .filter(|(_, s)| slots[*s as usize] != 0)
            .map(|(n, _)| n.clone())
            .collect()
    }
}
