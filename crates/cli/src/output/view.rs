//! What a tick record shows: active states, variable values and present events per instance.

use statecheck_ir::{eval, Program, SlotId, ValueKind};
use statecheck_model::{Model, NodeKind};

/// A displayable variable of an instance.
pub struct VarView {
    /// `instance.var`.
    pub name: String,
    /// Its slot.
    pub slot: SlotId,
    /// How to show it.
    pub display: ValueKind,
    /// Bit width for VCD.
    pub width: u32,
    /// True for booleans.
    pub is_bool: bool,
}

/// Everything a renderer needs to know about a program's observable variables and states.
pub struct Views {
    /// Per instance (declaration order): its name.
    pub instances: Vec<String>,
    /// Per instance: state paths (non-root, non-region) with their `in()` expression.
    pub states: Vec<Vec<(String, u32, bool)>>,
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
            let chart = &model.charts[inst.chart as usize];
            let mut st = Vec::new();
            for (s, node) in chart.states.iter().enumerate() {
                if s == 0 || node.is_region {
                    continue;
                }
                let leaf = matches!(node.kind, NodeKind::Simple);
                st.push((node.path.clone(), inst.active[s], leaf));
            }
            states.push(st);
            for (v, var) in chart.vars.iter().enumerate() {
                let slot = inst.var_slots[v];
                if slot == u32::MAX {
                    continue;
                }
                let name = format!("{}.{}", inst.name, var.name);
                if var.is_event {
                    events.push((name, slot));
                } else {
                    let s = &p.slots[slot as usize];
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
        Views {
            instances: p.instances.iter().map(|i| i.name.clone()).collect(),
            states,
            vars,
            events,
        }
    }

    /// Active state paths of instance `i` in `slots` (`leaves_only` drops composites).
    pub fn active(&self, p: &Program, i: usize, slots: &[i64], leaves_only: bool) -> Vec<String> {
        self.states[i]
            .iter()
            .filter(|(_, _, leaf)| !leaves_only || *leaf)
            .filter(|(_, e, _)| eval(&p.nodes, slots, *e).is_ok_and(|v| v != 0))
            .map(|(path, _, _)| path.clone())
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
