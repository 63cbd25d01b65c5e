//! The JSON trace (a contract): `{"ticks":[{"tick","active","vars","events"}], ...}`, and
//! `"time"` (seconds, a number) after `"tick"` when the model declares its tick length.

use serde_json::{json, Map, Value};
use statecheck_ir::view::TraceView as Views;
use statecheck_ir::{Program, ValueKind};

/// A value as JSON: booleans as `true`/`false`, enums as their literal, integers as numbers.
pub fn value(kind: &ValueKind, v: i64) -> Value {
    match kind {
        ValueKind::Bool => Value::Bool(v != 0),
        ValueKind::Int => json!(v),
        ValueKind::Enum(_) => Value::String(kind.format(v)),
    }
}

/// One tick, given by its number and slots, as a JSON object (with `"time"` in seconds when
/// the model declares `tick`).
pub fn tick_of(p: &Program, views: &Views, tick: u64, slots: &[i64]) -> Value {
    let mut active = Map::new();
    for (i, inst) in views.instances.iter().enumerate() {
        active.insert(inst.name.clone(), json!(views.active(p, i, slots, false)));
    }
    let mut vars = Map::new();
    for v in &views.vars {
        vars.insert(v.name.clone(), value(&v.display, slots[v.slot as usize]));
    }
    let mut o = Map::new();
    o.insert("tick".into(), json!(tick));
    if let Some(t) = p.seconds(tick) {
        o.insert("time".into(), json!(t));
    }
    o.insert("active".into(), Value::Object(active));
    o.insert("vars".into(), Value::Object(vars));
    o.insert("events".into(), json!(views.present_events(slots)));
    Value::Object(o)
}
