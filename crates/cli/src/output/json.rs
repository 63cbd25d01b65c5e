//! The JSON trace (a contract): `{"ticks":[{"tick","active","vars","events"}], ...}`.

use serde_json::{json, Map, Value};
use statecheck_ir::view::TraceView as Views;
use statecheck_ir::{Program, ValueKind};
use statecheck_sim::TickRecord;

/// A value as JSON: booleans as `true`/`false`, enums as their literal, integers as numbers.
pub fn value(kind: &ValueKind, v: i64) -> Value {
    match kind {
        ValueKind::Bool => Value::Bool(v != 0),
        ValueKind::Int => json!(v),
        ValueKind::Enum(_) => Value::String(kind.format(v)),
    }
}

/// One tick as a JSON object.
pub fn tick(p: &Program, views: &Views, rec: &TickRecord) -> Value {
    let mut active = Map::new();
    for (i, inst) in views.instances.iter().enumerate() {
        active.insert(
            inst.name.clone(),
            json!(views.active(p, i, &rec.slots, false)),
        );
    }
    let mut vars = Map::new();
    for v in &views.vars {
        vars.insert(
            v.name.clone(),
            value(&v.display, rec.slots[v.slot as usize]),
        );
    }
    json!({"tick": rec.tick, "active": active, "vars": vars, "events": views.present_events(&rec.slots)})
}
