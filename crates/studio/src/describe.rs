//! The model as the page draws it: charts (state tree, transitions with their labels as
//! written), instances, inputs with their ranges, variables, events, coverage items and
//! properties — all data the page needs before the first tick, sent once per session.

use crate::load::Loaded;
use serde_json::{json, Value};
use statecheck_base::Span;
use statecheck_ir::{CoverKind, SlotId, ValueKind};
use statecheck_model::{Branch, Chart, ChartRole, Dest, NodeKind, Trigger};
use statecheck_syntax::ast::{HistoryKind, VarKind};

/// Longest label text sent (the page shows the full text of longer ones in a tooltip).
const MAX_LABEL: usize = 400;

/// The description of a loaded model (a JSON object; see docs/studio.md, "Protocol").
pub fn describe(l: &Loaded) -> Value {
    let p = &l.program;
    let charts: Vec<Value> = l.model.charts.iter().map(|c| chart(c, &l.source)).collect();
    let instances: Vec<Value> = p
        .instances
        .iter()
        .map(|i| json!({"name": i.name, "chart": i.chart, "observer": i.observer}))
        .collect();
    let inputs: Vec<Value> = p
        .inputs
        .iter()
        .enumerate()
        .map(|(k, inp)| {
            let s = &p.slots[inp.slot as usize];
            let mut v = value_type(&s.display, s.lo, s.hi);
            v["index"] = json!(k);
            v["name"] = json!(inp.name);
            v["instance"] = json!(inp.instance);
            v["event"] = json!(inp.is_event);
            v["init"] = crate::protocol::value_json(&s.display, s.init);
            v
        })
        .collect();
    // Every variable and event of every instance, with its slot: connected inputs share
    // their source's slot, which is how the page draws messages between instances.
    let mut vars = Vec::new();
    let mut events = Vec::new();
    for (i, inst) in p.instances.iter().enumerate() {
        let Some(chart) = l.model.charts.get(inst.chart as usize) else {
            continue;
        };
        for (v, var) in chart.vars.iter().enumerate() {
            let Some(&slot) = inst.var_slots.get(v) else {
                continue;
            };
            if slot == u32::MAX {
                continue;
            }
            let s = &p.slots[slot as usize];
            let kind = match var.kind {
                VarKind::Input => "input",
                VarKind::Output => "output",
                VarKind::Local => "local",
            };
            let mut j = value_type(&s.display, s.lo, s.hi);
            j["name"] = json!(format!("{}.{}", inst.name, var.name));
            j["instance"] = json!(i);
            j["kind"] = json!(kind);
            j["slot"] = json!(slot);
            j["free"] = json!(is_input(p, slot));
            if var.is_event {
                events.push(j);
            } else {
                vars.push(j);
            }
        }
    }
    let covers: Vec<Value> = p
        .covers
        .iter()
        .map(|c| {
            let mut v = match c.kind {
                CoverKind::State(s) => json!({"instance": c.instance, "kind": "state", "state": s}),
                CoverKind::Transition(t) => {
                    json!({"instance": c.instance, "kind": "transition", "transition": t})
                }
                CoverKind::Branch(t, b) => {
                    json!({"instance": c.instance, "kind": "branch", "transition": t, "branch": b})
                }
            };
            // An observer's `error` state (and what leads only to it): never a coverage gap.
            v["expected_unreached"] = json!(c.expected_unreached);
            v
        })
        .collect();
    let properties: Vec<Value> = p.properties.iter().map(|q| json!(q.name)).collect();
    json!({
        "path": l.path,
        "system": p.name,
        "tick_ms": l.model.tick_ms,
        "charts": charts,
        "instances": instances,
        "inputs": inputs,
        "vars": vars,
        "events": events,
        "covers": covers,
        "properties": properties,
        "history_cap": crate::session::HISTORY_CAP,
        "max_batch": crate::session::MAX_BATCH,
    })
}

fn is_input(p: &statecheck_ir::Program, slot: SlotId) -> bool {
    p.inputs.iter().any(|i| i.slot == slot)
}

fn value_type(kind: &ValueKind, lo: i64, hi: i64) -> Value {
    match kind {
        ValueKind::Bool => json!({"type": "bool"}),
        ValueKind::Int => json!({"type": "int", "lo": lo, "hi": hi}),
        ValueKind::Enum(names) => json!({"type": "enum", "variants": names}),
    }
}

fn chart(c: &Chart, src: &str) -> Value {
    let states: Vec<Value> = c
        .states
        .iter()
        .enumerate()
        .map(|(id, s)| {
            let (kind, children, initial, history) = match &s.kind {
                NodeKind::Simple => ("simple", vec![], None, None),
                NodeKind::Or {
                    children,
                    initial,
                    history,
                } => (
                    "or",
                    children.clone(),
                    children.get(*initial).copied(),
                    history.as_ref().map(|h| match h {
                        HistoryKind::Shallow => "shallow",
                        HistoryKind::Deep => "deep",
                    }),
                ),
                NodeKind::And { regions } => ("and", regions.clone(), None, None),
            };
            json!({
                "id": id,
                "name": s.name,
                "path": s.path,
                "parent": s.parent,
                "region": s.is_region,
                "kind": kind,
                "children": children,
                "initial": initial,
                "history": history,
                "actions": actions(s, src),
            })
        })
        .collect();
    let transitions: Vec<Value> = c
        .transitions
        .iter()
        .enumerate()
        .map(|(id, t)| {
            let label = head(text(src, t.span), true);
            let after = match t.trigger {
                Trigger::After(k) => Some(k),
                _ => None,
            };
            json!({
                "id": id,
                "source": t.source,
                "label": label,
                "after_ticks": after,
                "priority": t.priority,
                "dest": dest(&t.dest, src),
            })
        })
        .collect();
    json!({
        "name": c.name,
        "observer": c.role == ChartRole::Observer,
        "states": states,
        "transitions": transitions,
    })
}

fn dest(d: &Dest, src: &str) -> Value {
    match d {
        Dest::Internal => json!({"kind": "internal"}),
        Dest::State(s) => json!({"kind": "state", "state": s}),
        Dest::Choice(branches) => json!({
            "kind": "choice",
            "branches": branches.iter().map(|b| branch(b, src)).collect::<Vec<_>>(),
        }),
    }
}

fn branch(b: &Branch, src: &str) -> Value {
    let label = head(text(src, b.span), false);
    json!({"label": if b.guard.is_none() && label.is_empty() { "else".to_string() } else { label }, "dest": dest(&b.dest, src)})
}

/// `entry`/`during`/`exit` presence, for the `en/du/ex` line of a state box.
fn actions(s: &statecheck_model::StateNode, _src: &str) -> Value {
    let mut v = Vec::new();
    if !s.entry.is_empty() {
        v.push("en");
    }
    if !s.during.is_empty() {
        v.push("du");
    }
    if !s.exit.is_empty() {
        v.push("ex");
    }
    json!(v)
}

fn text(src: &str, span: Span) -> &str {
    src.get(span.start as usize..span.end as usize)
        .unwrap_or("")
}

/// The label of a transition (or branch) as written: everything before its top-level `->`,
/// without the leading `on`, comments and line breaks — `trigger [guard] / { action }` — plus
/// `priority N` if given.
fn head(t: &str, strip_on: bool) -> String {
    let no_comments: String = t
        .lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join(" ");
    let bytes = no_comments.as_bytes();
    let mut depth = 0i32;
    let mut end = no_comments.len();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' => depth -= 1,
            b'-' if depth == 0 && bytes.get(i + 1) == Some(&b'>') => {
                end = i;
                break;
            }
            _ => {}
        }
        i += 1;
    }
    let mut h = no_comments[..end]
        .trim()
        .trim_end_matches(';')
        .trim()
        .to_string();
    if strip_on {
        if let Some(rest) = h.strip_prefix("on") {
            if rest.is_empty() || rest.starts_with(|c: char| c.is_whitespace() || c == '[') {
                h = rest.trim().to_string();
            }
        }
    }
    // Priority is written after the target; keep it visible.
    let tail = &no_comments[end..];
    if let (Some(k), false) = (tail.rfind("priority"), tail.contains('{')) {
        let pr = tail[k..].trim().trim_end_matches(';').trim();
        h = format!("{h} {pr}");
    }
    let mut out = h.split_whitespace().collect::<Vec<_>>().join(" ");
    if out.len() > MAX_LABEL {
        let mut cut = MAX_LABEL;
        while !out.is_char_boundary(cut) {
            cut -= 1;
        }
        out.truncate(cut);
        out.push('…');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::head;

    #[test]
    fn labels_are_the_text_before_the_arrow() {
        assert_eq!(
            head("on go [x > 1] / { n += 1; } -> Busy;", true),
            "go [x > 1] / { n += 1; }"
        );
        assert_eq!(head("on [a -> b] -> T;", true), "[a -> b]");
        assert_eq!(
            head("on after(3 s) -> T priority 2;", true),
            "after(3 s) priority 2"
        );
        assert_eq!(
            head("on [k == 1] / { n = 0; };", true),
            "[k == 1] / { n = 0; }"
        );
        assert_eq!(head("on [x] // why\n  -> T;", true), "[x]");
        assert_eq!(head("online -> T;", true), "online");
    }
}
