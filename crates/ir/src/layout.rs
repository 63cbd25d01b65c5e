//! Slot allocation: decides which slot holds each variable, active child, timer, pending
//! event, monitor and temporary of a system, before any code is generated.

use crate::program::{Input, InstanceLayout, Slot, SlotId, SlotRole, ValueKind};
use statecheck_model::{Model, NodeKind, PropertyKind, System, Trigger, Type};
use statecheck_syntax::ast::VarKind;

/// Where everything of one system lives.
pub(crate) struct Layout {
    /// All slots, final numbering.
    pub slots: Vec<Slot>,
    /// Number of state slots.
    pub n_state: usize,
    /// Free inputs.
    pub inputs: Vec<Input>,
    /// Per instance: variables and regions (the `active` field is filled by the lowering).
    pub instances: Vec<InstanceLayout>,
    /// Per instance, per state: its timer slot and the largest `after` delay.
    pub timers: Vec<Vec<Option<(SlotId, i64)>>>,
    /// Per instance, per variable: the pending slot of a local event.
    pub pending: Vec<Vec<Option<SlotId>>>,
    /// Per instance, per parallel state: its abort flag.
    pub aborts: Vec<Vec<Option<SlotId>>>,
    /// The `Started` slot.
    pub started: SlotId,
    /// Per property: its monitor slot (respond properties only).
    pub monitors: Vec<Option<SlotId>>,
    /// Per instance, per OR node that remembers its child (history): has it ever been entered?
    pub visited: Vec<Vec<Option<SlotId>>>,
}

/// True when an OR node's active child must survive its exit (history on it, or deep history
/// above it).
pub(crate) fn remembers(chart: &statecheck_model::Chart, n: statecheck_model::StateId) -> bool {
    use statecheck_syntax::ast::HistoryKind;
    if let NodeKind::Or {
        history: Some(_), ..
    } = chart.states[n as usize].kind
    {
        return true;
    }
    let mut cur = chart.states[n as usize].parent;
    while let Some(p) = cur {
        if let NodeKind::Or {
            history: Some(HistoryKind::Deep),
            ..
        } = chart.states[p as usize].kind
        {
            return matches!(chart.states[n as usize].kind, NodeKind::Or { .. });
        }
        cur = chart.states[p as usize].parent;
    }
    false
}

/// A slot whose final index is known only once all slots are counted.
#[derive(Clone, Copy)]
enum Prov {
    State(u32),
    Input(u32),
    Temp(u32),
}

#[derive(Default)]
struct Alloc {
    state: Vec<Slot>,
    input: Vec<Slot>,
    temp: Vec<Slot>,
}

impl Alloc {
    fn push(&mut self, class: u8, slot: Slot) -> Prov {
        let v = match class {
            0 => &mut self.state,
            1 => &mut self.input,
            _ => &mut self.temp,
        };
        v.push(slot);
        let i = v.len() as u32 - 1;
        match class {
            0 => Prov::State(i),
            1 => Prov::Input(i),
            _ => Prov::Temp(i),
        }
    }
}

pub(crate) fn layout(model: &Model, sys: &System) -> Layout {
    let mut a = Alloc::default();
    let n = sys.instances.len();
    let mut var_prov: Vec<Vec<Option<Prov>>> = Vec::with_capacity(n);
    let mut region_prov: Vec<Vec<Option<Prov>>> = Vec::with_capacity(n);
    let mut timer_prov: Vec<Vec<Option<(Prov, i64)>>> = Vec::with_capacity(n);
    let mut pending_prov: Vec<Vec<Option<Prov>>> = Vec::with_capacity(n);
    let mut visited_prov: Vec<Vec<Option<Prov>>> = Vec::with_capacity(n);
    let mut abort_prov: Vec<Vec<Option<Prov>>> = Vec::with_capacity(n);

    // 1. Persistent state: variables, active children, timers, pending events.
    for (i, inst) in sys.instances.iter().enumerate() {
        let chart = &model.charts[inst.chart as usize];
        let mut vars = vec![None; chart.vars.len()];
        let mut pend = vec![None; chart.vars.len()];
        for (v, var) in chart.vars.iter().enumerate() {
            let (lo, hi) = model.bounds(var.ty);
            let name = format!("{}.{}", inst.name, var.name);
            match (var.kind, var.is_event) {
                (VarKind::Input, _) => {}
                (VarKind::Local, true) => {
                    pend[v] = Some(a.push(
                        0,
                        Slot {
                            name: format!("{name}$pending"),
                            role: SlotRole::Pending {
                                instance: i as u32,
                                var: v as u32,
                            },
                            lo: 0,
                            hi: 1,
                            init: 0,
                            display: ValueKind::Int,
                        },
                    ));
                }
                _ => {
                    vars[v] = Some(a.push(
                        0,
                        Slot {
                            name,
                            role: SlotRole::Var {
                                instance: i as u32,
                                var: v as u32,
                            },
                            lo,
                            hi,
                            init: var.init,
                            display: value_kind(model, var.ty),
                        },
                    ));
                }
            }
        }
        let mut regions = vec![None; chart.states.len()];
        let mut timers = vec![None; chart.states.len()];
        let mut visited = vec![None; chart.states.len()];
        for (s, node) in chart.states.iter().enumerate() {
            if let NodeKind::Or {
                children, initial, ..
            } = &node.kind
            {
                let label = if node.path.is_empty() {
                    String::new()
                } else {
                    format!(".{}", node.path)
                };
                regions[s] = Some(
                    a.push(
                        0,
                        Slot {
                            name: format!("{}{label}$active", inst.name),
                            role: SlotRole::Region {
                                instance: i as u32,
                                node: s as u32,
                            },
                            lo: 0,
                            hi: children.len() as i64 - 1,
                            init: *initial as i64,
                            display: ValueKind::Enum(
                                children
                                    .iter()
                                    .map(|c| chart.states[*c as usize].name.clone())
                                    .collect(),
                            ),
                        },
                    ),
                );
                if remembers(chart, s as u32) {
                    visited[s] = Some(a.push(
                        0,
                        Slot {
                            name: format!("{}{label}$visited", inst.name),
                            role: SlotRole::Visited {
                                instance: i as u32,
                                node: s as u32,
                            },
                            lo: 0,
                            hi: 1,
                            init: 0,
                            display: ValueKind::Bool,
                        },
                    ));
                }
            }
            let max_after = node
                .transitions
                .iter()
                .filter_map(|t| match chart.transitions[*t as usize].trigger {
                    Trigger::After(n) => Some(n),
                    _ => None,
                })
                .max();
            if let Some(m) = max_after {
                let p = a.push(
                    0,
                    Slot {
                        name: format!("{}.{}$timer", inst.name, node.path),
                        role: SlotRole::Timer {
                            instance: i as u32,
                            state: s as u32,
                        },
                        lo: 0,
                        hi: m,
                        init: 0,
                        display: ValueKind::Int,
                    },
                );
                timers[s] = Some((p, m));
            }
        }
        var_prov.push(vars);
        region_prov.push(regions);
        timer_prov.push(timers);
        pending_prov.push(pend);
        visited_prov.push(visited);
    }
    let started = a.push(
        0,
        Slot {
            name: "$started".into(),
            role: SlotRole::Started,
            lo: 0,
            hi: 1,
            init: 0,
            display: ValueKind::Int,
        },
    );
    let monitors_prov: Vec<Option<Prov>> = sys
        .properties
        .iter()
        .enumerate()
        .map(|(p, prop)| match &prop.kind {
            PropertyKind::Respond { within, .. } => Some(a.push(
                0,
                Slot {
                    name: format!("{}$waited", prop.name),
                    role: SlotRole::Monitor { property: p as u32 },
                    lo: 0,
                    hi: within + 1,
                    init: 0,
                    display: ValueKind::Int,
                },
            )),
            _ => None,
        })
        .collect();

    // 2. Free inputs: unconnected inputs, in instance order.
    let mut input_info = Vec::new();
    for (i, inst) in sys.instances.iter().enumerate() {
        let chart = &model.charts[inst.chart as usize];
        for (v, var) in chart.vars.iter().enumerate() {
            if var.kind != VarKind::Input
                || sys.connections.iter().any(|c| c.to == (i as u32, v as u32))
            {
                continue;
            }
            let (lo, hi) = model.bounds(var.ty);
            let name = format!("{}.{}", inst.name, var.name);
            let p = a.push(
                1,
                Slot {
                    name: name.clone(),
                    role: SlotRole::Input {
                        instance: i as u32,
                        var: v as u32,
                    },
                    lo,
                    hi,
                    init: if var.is_event { 0 } else { var.init },
                    display: value_kind(model, var.ty),
                },
            );
            var_prov[i][v] = Some(p);
            input_info.push((p, name, var.is_event, i as u32, v as u32));
        }
    }
    // Connected inputs alias their source.
    for c in &sys.connections {
        var_prov[c.to.0 as usize][c.to.1 as usize] = var_prov[c.from.0 as usize][c.from.1 as usize];
    }

    // 3. Temporaries: present local events, abort flags.
    for (i, inst) in sys.instances.iter().enumerate() {
        let chart = &model.charts[inst.chart as usize];
        for (v, var) in chart.vars.iter().enumerate() {
            if var.kind == VarKind::Local && var.is_event {
                var_prov[i][v] = Some(a.push(
                    2,
                    Slot {
                        name: format!("{}.{}", inst.name, var.name),
                        role: SlotRole::Present {
                            instance: i as u32,
                            var: v as u32,
                        },
                        lo: 0,
                        hi: 1,
                        init: 0,
                        display: ValueKind::Int,
                    },
                ));
            }
        }
        let mut aborts = vec![None; chart.states.len()];
        for (s, node) in chart.states.iter().enumerate() {
            if matches!(node.kind, NodeKind::And { .. }) {
                aborts[s] = Some(a.push(
                    2,
                    Slot {
                        name: format!("{}.{}$abort", inst.name, node.path),
                        role: SlotRole::Abort {
                            instance: i as u32,
                            state: s as u32,
                        },
                        lo: 0,
                        hi: 1,
                        init: 0,
                        display: ValueKind::Int,
                    },
                ));
            }
        }
        abort_prov.push(aborts);
    }

    let ns = a.state.len() as u32;
    let ni = a.input.len() as u32;
    let fin = move |p: Prov| -> SlotId {
        match p {
            Prov::State(i) => i,
            Prov::Input(i) => ns + i,
            Prov::Temp(i) => ns + ni + i,
        }
    };
    let instances = sys
        .instances
        .iter()
        .enumerate()
        .map(|(i, inst)| InstanceLayout {
            name: inst.name.clone(),
            chart: inst.chart,
            var_slots: var_prov[i]
                .iter()
                .map(|p| p.map_or(u32::MAX, fin))
                .collect(),
            region_slots: region_prov[i].iter().map(|p| p.map(fin)).collect(),
            active: Vec::new(),
            observer: model.charts[inst.chart as usize].role
                == statecheck_model::ChartRole::Observer,
        })
        .collect();
    let mut slots = a.state;
    slots.extend(a.input);
    slots.extend(a.temp);
    Layout {
        n_state: ns as usize,
        inputs: input_info
            .into_iter()
            .map(|(p, name, is_event, instance, var)| Input {
                slot: fin(p),
                name,
                is_event,
                instance,
                var,
                rate: sys
                    .rates
                    .iter()
                    .find(|r| (r.instance, r.var) == (instance, var))
                    .map(|r| r.rate),
            })
            .collect(),
        instances,
        timers: timer_prov
            .into_iter()
            .map(|v| v.into_iter().map(|t| t.map(|(p, m)| (fin(p), m))).collect())
            .collect(),
        pending: pending_prov
            .into_iter()
            .map(|v| v.into_iter().map(|p| p.map(fin)).collect())
            .collect(),
        aborts: abort_prov
            .into_iter()
            .map(|v| v.into_iter().map(|p| p.map(fin)).collect())
            .collect(),
        started: fin(started),
        monitors: monitors_prov.into_iter().map(|p| p.map(fin)).collect(),
        visited: visited_prov
            .into_iter()
            .map(|v| v.into_iter().map(|p| p.map(fin)).collect())
            .collect(),
        slots,
    }
}

fn value_kind(model: &Model, ty: Type) -> ValueKind {
    match ty {
        Type::Bool => ValueKind::Bool,
        Type::Int { .. } => ValueKind::Int,
        Type::Enum(e) => ValueKind::Enum(
            model
                .enums
                .get(e as usize)
                .map(|d| d.variants.clone())
                .unwrap_or_default(),
        ),
    }
}
