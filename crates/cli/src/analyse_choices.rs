//! `statecheck analyse FILE --depth N`: for every sequence of discrete choices up to N (the
//! system's free inputs, chosen at tick 1, after every transition of a plant with continuous
//! variables and when the system comes to rest; `statecheck_sim::choices`), the exact times at which
//! each sensor's zone is entered and left, whether each time is a tick at which the
//! discretized model's sensor changes, and the property violations along the way.

use crate::{analyse_cmd::AnalyseArgs, load};
use anyhow::{bail, Result};
use statecheck_ir::{Program, SlotId};
use statecheck_model::hybrid::{analyse, ChartPlans, Plan, Ratio};
use statecheck_sim::choices::{self, ChoiceRun, End, Limits, Truncation};

/// What to read of one continuous variable of one instance: its recorded columns.
struct Watched<'a> {
    instance: String,
    plan: &'a Plan,
    /// Column of the mode slot in the recorded rows.
    mode: usize,
    /// Columns of the sensors' outputs (`None` when a sensor has no slot).
    sensors: Vec<Option<usize>>,
}

/// Run `analyse --depth`.
pub fn run(
    loaded: &load::Loaded,
    a: &AnalyseArgs,
    depth: usize,
    charts: &[ChartPlans],
    tick: Ratio,
) -> Result<u8> {
    let sys = loaded.system(a.system.as_deref())?;
    let program = loaded.lower(sys)?;
    let mut record: Vec<SlotId> = Vec::new();
    let mut col = |s: SlotId| -> usize {
        record.iter().position(|r| *r == s).unwrap_or_else(|| {
            record.push(s);
            record.len() - 1
        })
    };
    let mut watched = Vec::new();
    let mut watch = Vec::new();
    for inst in &program.instances {
        let Some(chart) = loaded.model.charts.get(inst.chart as usize) else {
            continue;
        };
        let base = chart.name.split('(').next().unwrap_or(&chart.name);
        let Some(cp) = charts
            .iter()
            .find(|c| c.chart == chart.name)
            .or_else(|| charts.iter().find(|c| c.chart == base))
        else {
            continue;
        };
        // A switch of the dynamics is a transition of the plant: a change of its states.
        for r in inst.region_slots.iter().flatten() {
            if !watch.contains(r) {
                watch.push(*r);
            }
        }
        for p in &cp.plans {
            let slot = |name: &str| {
                chart
                    .vars
                    .iter()
                    .position(|v| v.name == name)
                    .and_then(|i| inst.var_slots.get(i).copied())
            };
            let Some(ms) = slot(&format!("{}_mode", p.var)) else {
                continue;
            };
            let mode = col(ms);
            let sensors = p
                .sensors
                .iter()
                .map(|(o, _, _)| slot(o).map(&mut col))
                .collect();
            watched.push(Watched {
                instance: inst.name.clone(),
                plan: p,
                mode,
                sensors,
            });
        }
    }
    if watched.is_empty() {
        bail!(
            "system `{}` has no instance of a chart with a continuous variable",
            program.name
        );
    }
    let limits = Limits {
        depth,
        max_runs: a.max_runs,
        ..Limits::default()
    };
    let en = choices::enumerate(&program, &watch, &record, limits);
    if let Some(Truncation::Valuations(n)) = en.truncated {
        bail!(
            "the free inputs of `{}` have {n} valuations per choice, more than the {} that \
             `analyse --depth` tries; analyse a smaller system (--system) or close the loop",
            program.name,
            limits.max_valuations
        );
    }
    let reports: Vec<Report> = en
        .runs
        .iter()
        .map(|r| report(&program, &watched, r, tick))
        .collect();
    let truncated = en.truncated.as_ref().map(|t| match t {
        Truncation::Runs(n) => format!(
            "truncated: only the first {n} sequences are listed (raise --max-runs or lower --depth)"
        ),
        Truncation::Ticks(n) => {
            format!("truncated: {n} ticks simulated in all, the limit (lower --depth)")
        }
        Truncation::Valuations(n) => format!("{n} valuations per choice"),
    });
    if a.json {
        let v = serde_json::json!({
            "tick_seconds": tick.to_string(),
            "system": program.name,
            "depth": depth,
            "valuations": en.valuations,
            "complete": truncated.is_none(),
            "truncated": truncated,
            "runs": reports.iter().map(Report::json).collect::<Vec<_>>(),
        });
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        println!(
            "system {}: {} sequence(s) of up to {depth} choice(s), {} input valuation(s) per choice, tick {} s",
            program.name,
            reports.len(),
            en.valuations,
            tick
        );
        for (i, r) in reports.iter().enumerate() {
            print!("\n{}", r.text(i + 1));
        }
        if let Some(t) = &truncated {
            println!("\n{t}");
        }
    }
    Ok(if truncated.is_some() { 3 } else { 0 })
}

/// Seconds at a tick, exact.
fn at(tick: Ratio, k: u64) -> Ratio {
    Ratio::int(k as i64)
        .checked_mul(tick)
        .unwrap_or(Ratio::ZERO)
}

/// An input of a choice: name, value, and whether the choice changed it.
type InputValue = (String, String, bool);

/// One sequence, ready to print.
struct Report {
    /// (tick, time, every input with its value and whether the choice changed it).
    choices: Vec<(u64, Ratio, Vec<InputValue>)>,
    switches: Vec<(u64, Ratio, String, String)>,
    zones: Vec<(String, String, analyse::ZoneEvent)>,
    violations: Vec<(u64, Ratio, String)>,
    end: String,
    ticks: usize,
}

fn report(program: &Program, watched: &[Watched], run: &ChoiceRun, tick: Ratio) -> Report {
    let mut prev: Vec<i64> = program
        .inputs
        .iter()
        .map(|i| program.slots[i.slot as usize].init)
        .collect();
    let mut choices = Vec::new();
    for c in &run.choices {
        let mut set = Vec::new();
        for (k, inp) in program.inputs.iter().enumerate() {
            let v = c.inputs[k];
            let changed = v != prev[k] || (inp.is_event && v != 0);
            let kind = &program.slots[inp.slot as usize].display;
            set.push((inp.name.clone(), kind.format(v), changed));
        }
        prev.clone_from(&c.inputs);
        choices.push((c.tick, at(tick, c.tick), set));
    }
    let mut switches = Vec::new();
    let mut zones = Vec::new();
    for w in watched {
        let modes: Vec<i64> = run.rows.iter().map(|r| r[w.mode]).collect();
        for k in 1..modes.len() {
            if modes[k] != modes[k - 1] {
                let state = usize::try_from(modes[k] - 1)
                    .ok()
                    .and_then(|i| w.plan.modes.get(i))
                    .map_or("still".to_string(), |m| m.path.join("."));
                // The new motion starts at the tick before (see `analyse::motions`).
                let t = k as u64 - 1;
                switches.push((
                    t,
                    at(tick, t),
                    format!("{}.{}", w.instance, w.plan.var),
                    state,
                ));
            }
        }
        let cols: Vec<Vec<i64>> = w
            .sensors
            .iter()
            .map(|c| match c {
                Some(c) => run.rows.iter().map(|r| r[*c]).collect(),
                None => Vec::new(),
            })
            .collect();
        for e in analyse::zone_events(w.plan, tick, &modes, &cols) {
            let name = w
                .plan
                .sensors
                .get(e.sensor)
                .map_or(String::new(), |s| format!("{}.{}", w.instance, s.0));
            zones.push((name, format!("{}.{}", w.instance, w.plan.var), e));
        }
    }
    switches.sort_by_key(|s| s.0);
    zones.sort_by_key(|z| z.2.seconds);
    // The first violation of each property (a violated invariant stays violated for a while).
    let mut violations: Vec<(u64, Ratio, String)> = Vec::new();
    for (t, p) in &run.violations {
        if !violations.iter().any(|v| &v.2 == p) {
            violations.push((*t, at(tick, *t), p.clone()));
        }
    }
    let last = run.rows.len().saturating_sub(1) as u64;
    let end = match run.end {
        End::Depth => format!("depth reached; last tick {last} ({} s)", at(tick, last)),
        End::Rest => format!("at rest from tick {last} ({} s)", at(tick, last)),
        End::SegmentLimit => format!(
            "no switch for {} ticks (the limit); last tick {last}",
            Limits::default().max_segment_ticks
        ),
        End::RuntimeError(t) => format!("run-time error in tick {t} ({} s)", at(tick, t)),
        End::Blocked(t) => format!("no inputs satisfy the assumptions at tick {t}"),
    };
    Report {
        choices,
        switches,
        zones,
        violations,
        end,
        ticks: run.rows.len(),
    }
}

/// The status of a zone event for people and JSON.
fn status(e: &analyse::ZoneEvent) -> String {
    match (e.expected_tick, e.model_tick) {
        _ if e.on_grid() => "on grid".into(),
        (None, Some(m)) => format!("between ticks (model: tick {m})"),
        (None, None) => "between ticks".into(),
        (Some(_), None) => "not seen in the model".into(),
        (Some(_), Some(m)) => format!("model differs (tick {m})"),
    }
}

impl Report {
    fn text(&self, n: usize) -> String {
        let mut s = String::new();
        let ch: Vec<String> = self
            .choices
            .iter()
            .map(|(t, secs, set)| {
                let set: Vec<String> = set
                    .iter()
                    .filter(|c| c.2)
                    .map(|(k, v, _)| format!("{k}={v}"))
                    .collect();
                let set = if set.is_empty() {
                    "inputs held".to_string()
                } else {
                    set.join(" ")
                };
                format!("tick {t} ({secs} s): {set}")
            })
            .collect();
        s.push_str(&format!("sequence {n}: {}\n", ch.join("; ")));
        for (t, secs, var, state) in &self.switches {
            s.push_str(&format!(
                "  tick {t:>5} {secs:>9} s  {var} moves: {state}\n"
            ));
        }
        if !self.zones.is_empty() {
            s.push_str(
                "  zone                  event     time (s)  ticks  expected  model tick  status\n",
            );
        }
        for (name, _, e) in &self.zones {
            s.push_str(&format!(
                "  {:<20}  {:<8}  {:>8}  {:>5}  {:>8}  {:>10}  {}\n",
                name,
                if e.entered { "entered" } else { "left" },
                e.seconds.to_string(),
                e.ticks.to_string(),
                e.expected_tick.map_or("-".into(), |t| t.to_string()),
                e.model_tick.map_or("-".into(), |t| t.to_string()),
                status(e)
            ));
        }
        for (t, secs, p) in &self.violations {
            s.push_str(&format!(
                "  property `{p}` first violated at tick {t} ({secs} s)\n"
            ));
        }
        s.push_str(&format!("  ends: {}\n", self.end));
        s
    }

    fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "choices": self.choices.iter().map(|(t, secs, set)| serde_json::json!({
                "tick": t,
                "seconds": secs.to_string(),
                "inputs": set.iter().map(|(k, v, _)| (k.clone(), serde_json::Value::String(v.clone()))).collect::<serde_json::Map<_, _>>(),
                "changed": set.iter().filter(|c| c.2).map(|c| c.0.clone()).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
            "switches": self.switches.iter().map(|(t, secs, var, state)| serde_json::json!({
                "tick": t, "seconds": secs.to_string(), "variable": var, "state": state,
            })).collect::<Vec<_>>(),
            "zones": self.zones.iter().map(|(name, var, e)| serde_json::json!({
                "sensor": name,
                "variable": var,
                "event": if e.entered { "entered" } else { "left" },
                "state": e.state,
                "seconds": e.seconds.to_string(),
                "ticks": e.ticks.to_string(),
                "expected_tick": e.expected_tick,
                "model_tick": e.model_tick,
                "on_grid": e.on_grid(),
                "status": status(e),
            })).collect::<Vec<_>>(),
            "violations": self.violations.iter().map(|(t, secs, p)| serde_json::json!({
                "property": p, "tick": t, "seconds": secs.to_string(),
            })).collect::<Vec<_>>(),
            "end": self.end,
            "ticks_run": self.ticks,
        })
    }
}
