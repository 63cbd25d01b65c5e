//! The WebSocket protocol: requests from the page (validated here, never trusted) and the
//! replies built from a session. Documented in docs/studio.md, "Protocol".

use crate::session::{Session, TickOut};
use serde::Deserialize;
use serde_json::{json, Map, Value};
use statecheck_base::LineIndex;
use statecheck_ir::view::TraceView as Views;
use statecheck_ir::{Program, ValueKind};
use statecheck_sim::Stop;

/// Largest request the server reads (bytes); larger ones get an error reply.
pub const MAX_REQUEST: usize = 1 << 20;

/// A request from the page.
#[derive(Debug, Deserialize)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum Request {
    /// The model description again.
    Describe {
        /// Echoed in the reply.
        id: Option<u64>,
    },
    /// Set held inputs without stepping.
    Set {
        /// Echoed in the reply.
        id: Option<u64>,
        /// `instance.input` → value.
        set: Map<String, Value>,
    },
    /// Set held inputs, then run `n` ticks; `pulse` applies to the first tick only.
    Step {
        /// Echoed in the reply.
        id: Option<u64>,
        /// Ticks (1 if absent).
        n: Option<u64>,
        /// Held inputs to change first.
        #[serde(default)]
        set: Map<String, Value>,
        /// Inputs for the first tick only (events present, or a value for one tick).
        #[serde(default)]
        pulse: Map<String, Value>,
    },
    /// Run `n` ticks of seeded random inputs.
    Random {
        /// Echoed in the reply.
        id: Option<u64>,
        /// Ticks (1 if absent).
        n: Option<u64>,
        /// The seed (0 if absent).
        seed: Option<u64>,
    },
    /// Time travel: back to the state after tick `tick - 1`.
    Back {
        /// Echoed in the reply.
        id: Option<u64>,
        /// Ticks to keep.
        tick: u64,
    },
    /// Replay ticks undone by `back`.
    Forward {
        /// Echoed in the reply.
        id: Option<u64>,
        /// Ticks (1 if absent).
        n: Option<u64>,
    },
    /// Back to the initial state.
    Reset {
        /// Echoed in the reply.
        id: Option<u64>,
    },
    /// Reset and run a scenario (the `.scn` text).
    LoadScenario {
        /// Echoed in the reply.
        id: Option<u64>,
        /// The scenario.
        text: String,
    },
    /// Decide the properties (the `statecheck verify` portfolio); verdicts arrive as
    /// `verdict` messages as they are decided, then `verify_done`.
    Verify {
        /// Echoed in the reply.
        id: Option<u64>,
        /// `auto` (default), `explicit`, `bmc`, `kind`, `ic3` or `cegar`.
        engine: Option<String>,
        /// Seconds (30 if absent, at most 300).
        timeout_s: Option<u64>,
    },
    /// The inputs so far as a scenario.
    Save {
        /// Echoed in the reply.
        id: Option<u64>,
    },
}

/// An error reply.
pub fn error(id: Option<u64>, code: &str, message: &str) -> Value {
    json!({"type": "error", "id": id, "code": code, "message": message})
}

/// Parse a request; `Err` is the error reply.
pub fn parse(text: &str) -> Result<Request, Value> {
    if text.len() > MAX_REQUEST {
        return Err(error(
            None,
            "too_large",
            &format!(
                "request of {} bytes; at most {MAX_REQUEST} are read",
                text.len()
            ),
        ));
    }
    serde_json::from_str(text).map_err(|e| error(None, "malformed", &format!("bad request: {e}")))
}

/// A value as JSON (as `statecheck sim --json`): bools, enum literals, integers.
pub fn value_json(kind: &ValueKind, v: i64) -> Value {
    match kind {
        ValueKind::Bool => Value::Bool(v != 0),
        ValueKind::Int => json!(v),
        ValueKind::Enum(_) => Value::String(kind.format(v)),
    }
}

/// Resolve `name → value` pairs to (input index, value), checking names, types and ranges.
pub fn inputs(p: &Program, set: &Map<String, Value>) -> Result<Vec<(usize, i64)>, String> {
    let mut out = Vec::with_capacity(set.len());
    for (name, v) in set {
        let Some(k) = p.inputs.iter().position(|i| &i.name == name) else {
            return Err(format!("`{name}` is not an input of system `{}`", p.name));
        };
        let s = &p.slots[p.inputs[k].slot as usize];
        let value = match (&s.display, v) {
            (ValueKind::Bool, Value::Bool(b)) => i64::from(*b),
            (ValueKind::Int, Value::Number(n)) => match n.as_i64() {
                Some(x) if (s.lo..=s.hi).contains(&x) => x,
                _ => {
                    return Err(format!(
                        "`{name}` = {n} is out of its range {}..{}",
                        s.lo, s.hi
                    ))
                }
            },
            (ValueKind::Enum(names), Value::String(lit)) => {
                match names.iter().position(|x| x == lit) {
                    Some(i) => i as i64,
                    None => {
                        return Err(format!(
                            "`{lit}` is not a value of `{name}` ({})",
                            names.join(", ")
                        ))
                    }
                }
            }
            (kind, other) => {
                let want = match kind {
                    ValueKind::Bool => "true or false",
                    ValueKind::Int => "an integer",
                    ValueKind::Enum(_) => "an enum literal (a string)",
                };
                return Err(format!("`{name}` needs {want}, not {other}"));
            }
        };
        out.push((k, value));
    }
    Ok(out)
}

/// The held inputs as `name → value`.
pub fn held(s: &Session) -> Value {
    let p = s.program();
    let mut m = Map::new();
    for (inp, &v) in p.inputs.iter().zip(s.held()) {
        m.insert(
            inp.name.clone(),
            value_json(&p.slots[inp.slot as usize].display, v),
        );
    }
    Value::Object(m)
}

/// The state reply after a request that ran, replayed or undid ticks. `truncate`: the page
/// drops its records from this tick on before appending `ticks`.
pub fn state(s: &Session, id: Option<u64>, truncate: Option<u64>, ticks: &[TickOut]) -> Value {
    let loaded = s.loaded();
    let p = &loaded.program;
    let views = &loaded.views;
    let records: Vec<Value> = ticks
        .iter()
        .map(|t| record(p, views, t, &loaded.source, &loaded.path))
        .collect();
    json!({
        "type": "state",
        "id": id,
        "truncate": truncate,
        "ticks": records,
        "run": {
            "ticks": s.ticks(),
            "time_text": p.time_text(s.ticks()),
            "future": s.future_len(),
            "stop": s.stop().map(|st| stop(p, st, &loaded.source, &loaded.path)),
            "coverage": s.coverage(),
            "lasso": s.lasso().map(|l| json!({
                "start": l.start,
                "end": l.end,
                "following": l.following,
                "fair": l.fair,
                "broken": l.broken,
                "violated": l.violated.as_ref().map(|st| stop(p, st, &loaded.source, &loaded.path)),
            })),
        },
        "held": held(s),
    })
}

/// One tick as `statecheck sim --json` prints it (`tick`, `time` when the model declares a
/// tick, `active`, `vars`, `events`), plus `time_text` (the time as the CLI's table writes
/// it), `fired` (coverage items counted in the tick), `active_ids` (state ids per instance)
/// and `stop` when the run ended there.
pub fn record(p: &Program, views: &Views, t: &TickOut, source: &str, path: &str) -> Value {
    let mut r = json!({"tick": t.tick, "fired": t.fired});
    if let (Some(time), Some(text)) = (p.seconds(t.tick), p.time_text(t.tick)) {
        r["time"] = json!(time);
        r["time_text"] = json!(text);
    }
    if let Some(slots) = &t.slots {
        let mut active = Map::new();
        let mut ids = Vec::new();
        for (i, inst) in views.instances.iter().enumerate() {
            active.insert(inst.name.clone(), json!(views.active(p, i, slots, false)));
            ids.push(json!(views.active_ids(p, i, slots)));
        }
        let mut vars = Map::new();
        for v in &views.vars {
            vars.insert(
                v.name.clone(),
                value_json(&v.display, slots[v.slot as usize]),
            );
        }
        r["active"] = Value::Object(active);
        r["active_ids"] = Value::Array(ids);
        r["vars"] = Value::Object(vars);
        r["events"] = json!(views.present_events(slots));
    }
    if let Some(st) = &t.stop {
        r["stop"] = stop(p, st, source, path);
    }
    r
}

/// How a run stopped, with the message `statecheck sim` prints (and `time`, in seconds, beside
/// `tick` when the model declares a tick).
pub fn stop(p: &Program, st: &Stop, source: &str, path: &str) -> Value {
    let mut v = stop_fields(p, st, source, path);
    if let Some(t) = v["tick"].as_u64().and_then(|t| p.seconds(t)) {
        v["time"] = json!(t);
    }
    v
}

fn stop_fields(p: &Program, st: &Stop, source: &str, path: &str) -> Value {
    match st {
        Stop::Completed => json!({"status": "completed", "message": "run completed"}),
        Stop::Violation { tick, property } => json!({
            "status": "violated",
            "tick": tick,
            "property": property,
            "message": format!("property `{property}` violated at {}", p.tick_label(*tick)),
        }),
        Stop::RuntimeError { tick, error } => {
            let idx = LineIndex::new(source);
            let at = p.sites.get(error.site as usize).map(|s| {
                let (l, c) = idx.line_col(s.span.start);
                format!(" at {path}:{l}:{c}")
            });
            json!({
                "status": "runtime_error",
                "tick": tick,
                    "property": error.kind.builtin_property(),
                "message": format!("run-time error at {}: {}{}", p.tick_label(*tick), p.describe_error(error), at.unwrap_or_default()),
            })
        }
        Stop::AssumeViolated { tick, assume } => json!({
            "status": "assume_violated",
            "tick": tick,
            "message": format!("the inputs of tick {tick} violate `assume` #{} of the system (or no random inputs satisfy it)", assume + 1),
        }),
    }
}
