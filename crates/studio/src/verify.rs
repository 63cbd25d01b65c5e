//! "Verify" from the page: the properties decided by the portfolio of `crates/verify` (the
//! library behind `statecheck verify`), each verdict sent to the page the moment it is
//! decided, with its counterexample or witness as a scenario the page can replay (minimised
//! as the CLI minimises it: `statecheck_sim::minimise`).

use crate::load::Loaded;
use serde_json::{json, Value};
use statecheck_sim::scenario;
use statecheck_verify::{Engine, Event, ExplicitOptions, Meta, Options, PropResult};
use std::sync::Arc;
use std::time::Duration;

/// Longest verification the page may ask for.
pub const MAX_TIMEOUT_S: u64 = 300;
/// Timeout when the page names none.
pub const DEFAULT_TIMEOUT_S: u64 = 30;

/// The engine named by the page (`auto` when `None`).
pub fn engine(name: Option<&str>) -> Result<Engine, String> {
    let name = name.unwrap_or("auto");
    Engine::from_name(name).ok_or_else(|| format!("unknown engine `{name}` ({})", Engine::names()))
}

/// One result as the page shows it.
pub fn result(l: &Loaded, index: usize, r: &PropResult, meta: &Meta) -> Value {
    let p = &l.program;
    let scenario_text = r.counterexample.as_ref().map(|raw| {
        // Minimised as `statecheck verify` minimises it (by default), so that the page replays
        // the trace the CLI writes: inputs that do not matter kept at their previous value.
        let minimised = statecheck_sim::minimise::Target::of(r)
            .and_then(|t| statecheck_sim::minimise::minimise(p, raw, &t));
        let vectors = minimised.as_ref().unwrap_or(raw);
        let sc = match r.loop_start {
            Some(k) => scenario::from_lasso(p, vectors, k as usize),
            None => scenario::from_input_vectors(p, vectors),
        };
        format!(
            "# {} for `{}` ({}, {}): {} ticks, from the studio's verify\n{}",
            if r.verdict.as_str() == "reachable" {
                "witness"
            } else {
                "counterexample"
            },
            r.name,
            r.kind.as_str(),
            r.verdict.as_str(),
            r.depth,
            scenario::format(&sc, p)
        )
    });
    // The tick that decides the property (the last of the counterexample or witness).
    let tick = r.counterexample.as_ref().map(|_| r.depth.saturating_sub(1));
    json!({
        "type": "verdict",
        "tick": tick,
        "time_text": tick.and_then(|t| p.time_text(t)),
        "index": index,
        "name": r.name,
        "kind": r.kind.as_str(),
        "verdict": r.verdict.as_str(),
        "depth": r.depth,
        "engine": meta.engine,
        "time_s": meta.time_s.or(meta.decided_at_s),
        "reason": meta.reason,
        "note": r.note,
        "scenario": scenario_text,
    })
}

/// Run the verification (blocking: call it off the async threads); `send` gets each verdict
/// as it is decided and a final `verify_done` message.
pub fn run(l: Arc<Loaded>, engine: Engine, timeout_s: u64, send: &(dyn Fn(Value) + Sync)) {
    let opts = Options::new(
        engine,
        ExplicitOptions {
            timeout: Some(Duration::from_secs(timeout_s.clamp(1, MAX_TIMEOUT_S))),
            threads: 1,
            ..ExplicitOptions::default()
        },
    );
    let t0 = std::time::Instant::now();
    let outcome = statecheck_verify::verify(&l.program, &opts, &|e| {
        if let Event::Decided {
            index,
            result: r,
            meta,
        } = e
        {
            send(result(&l, index, r, meta));
        }
    });
    let done = match outcome {
        Ok(run) => {
            let results: Vec<Value> = run
                .report
                .results
                .iter()
                .zip(&run.meta)
                .enumerate()
                .map(|(i, (r, m))| result(&l, i, r, m))
                .collect();
            json!({"type": "verify_done", "results": results, "time_s": t0.elapsed().as_secs_f64()})
        }
        Err(e) => json!({"type": "verify_done", "error": e.to_string(), "results": []}),
    };
    send(done);
}
