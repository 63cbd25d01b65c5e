//! `statecheck analyse FILE [--scenario S]`: the continuous model's exact times
//! (docs/hybrid.md). Without a scenario, each moving state's clock readings at the grid
//! points; with one, the exact times at which the continuous motion reaches each critical
//! point during the run, beside the tick at which the discretized model got there; with
//! `--depth N`, the same for every sequence of discrete choices (`analyse_choices.rs`).

use crate::{diag, load, Exit};
use anyhow::{bail, Result};
use statecheck_model::hybrid::{self, analyse, ChartPlans, Ratio};
use statecheck_sim::{scenario, Options, ScenarioInputs};

/// Arguments of `statecheck analyse`.
#[derive(clap::Args)]
pub struct AnalyseArgs {
    /// The `.sc` model file.
    pub model: String,
    /// The system (or chart) to run with `--scenario`.
    #[arg(long)]
    pub system: Option<String>,
    /// A scenario file: follow its run and list when each critical point is reached.
    #[arg(long)]
    pub scenario: Option<String>,
    /// For every sequence of discrete choices up to this many (the free inputs, chosen at
    /// tick 1, at each switch of a motion and when the system rests), list when each sensor's
    /// zone is entered and left, exactly, and whether the grid contains each time.
    #[arg(long, conflicts_with = "scenario")]
    pub depth: Option<usize>,
    /// With `--depth`: the most sequences listed (more: the output says it is truncated and
    /// the exit code is 3).
    #[arg(long, default_value_t = 200, requires = "depth")]
    pub max_runs: usize,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// Run `analyse`.
pub fn run(a: AnalyseArgs) -> Result<u8> {
    let loaded = load::load(&a.model, false)?;
    let mut charts = match hybrid::plans(&loaded.file) {
        Ok(c) => c,
        Err(diags) => {
            diag::eprint_sources(&loaded.sources, &diags);
            return Err(load::ModelErrors.into());
        }
    };
    // A parameterised chart is discretized per copy, with its values (`Mover(20)`).
    for cp in &loaded.model.hybrid {
        if !charts.iter().any(|c| c.chart == cp.chart) {
            charts.push(cp.clone());
        }
    }
    if charts.is_empty() {
        bail!(
            "`{}` declares no continuous variable (docs/hybrid.md)",
            a.model
        );
    }
    let Some(ms) = loaded.model.tick_ms else {
        bail!("the model declares no `tick`");
    };
    let tick = Ratio::new(ms as i128, 1000).unwrap_or(Ratio::ZERO);
    if let Some(depth) = a.depth {
        return crate::analyse_choices::run(&loaded, &a, depth, &charts, tick);
    }
    match &a.scenario {
        None => readings(&charts, tick, a.json),
        Some(path) => events(&loaded, &a, path, &charts, tick),
    }
}

fn readings(charts: &[ChartPlans], tick: Ratio, json: bool) -> Result<u8> {
    let mut vars = Vec::new();
    let mut text = String::new();
    for c in charts {
        for p in &c.plans {
            let pts: Vec<String> = p.points.iter().map(i64::to_string).collect();
            text.push_str(&format!(
                "{}.{}: [{} .. {}], grid {{{}}}{}\n",
                c.chart,
                p.var,
                p.lo,
                p.hi,
                pts.join(", "),
                if p.forced.is_empty() {
                    String::new()
                } else {
                    let f: Vec<String> = p.forced.iter().map(i64::to_string).collect();
                    format!(", critical points added: {}", f.join(", "))
                }
            ));
            let mut modes = Vec::new();
            for m in analyse::readings(p, tick) {
                text.push_str(&format!("  {} (from {}):\n", m.state, m.from));
                text.push_str("    point  time (s)  ticks\n");
                for r in &m.readings {
                    text.push_str(&format!(
                        "    {:>5}  {:>8}  {:>5}\n",
                        r.point,
                        r.seconds.to_string(),
                        r.ticks.to_string()
                    ));
                }
                modes.push(serde_json::json!({
                    "state": m.state,
                    "from": m.from,
                    "readings": m.readings.iter().map(|r| serde_json::json!({
                        "point": r.point,
                        "seconds": r.seconds.to_string(),
                        "ticks": r.ticks.to_string(),
                    })).collect::<Vec<_>>(),
                }));
            }
            vars.push(serde_json::json!({
                "chart": c.chart,
                "variable": p.var,
                "lo": p.lo,
                "hi": p.hi,
                "grid": p.points,
                "forced": p.forced,
                "coarse": p.coarse,
                "modes": modes,
            }));
        }
    }
    if json {
        let v = serde_json::json!({ "tick_seconds": tick.to_string(), "variables": vars });
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        print!("{text}");
    }
    Ok(0)
}

fn events(
    loaded: &load::Loaded,
    a: &AnalyseArgs,
    path: &str,
    charts: &[ChartPlans],
    tick: Ratio,
) -> Result<u8> {
    crate::outpath::note_input(path);
    let text =
        std::fs::read_to_string(path).map_err(|e| anyhow::anyhow!("cannot read `{path}`: {e}"))?;
    let sys = loaded.system(a.system.as_deref())?;
    let program = loaded.lower(sys)?;
    let sc = match scenario::parse(&text, &program) {
        Ok(s) => s,
        Err(errs) => {
            let (kept, more) = diag::cap_scenario_errors(&errs);
            diag::eprint(
                path,
                &text,
                &crate::sim_cmd::scenario_diagnostics(&text, &kept),
            );
            eprint!("{more}");
            return Err(Exit(1).into());
        }
    };
    // The motion is followed over the whole scenario, past any property violation.
    let opts = Options {
        keep_going: true,
        ..Options::default()
    };
    let run = statecheck_sim::run(&program, &mut ScenarioInputs::new(&sc), opts);
    let mut rows = Vec::new();
    for inst in &program.instances {
        let Some(chart) = loaded.model.charts.get(inst.chart as usize) else {
            continue;
        };
        // A parameterised copy is named `Chart(args)`.
        let base = chart.name.split('(').next().unwrap_or(&chart.name);
        let Some(cp) = charts
            .iter()
            .find(|c| c.chart == chart.name)
            .or_else(|| charts.iter().find(|c| c.chart == base))
        else {
            continue;
        };
        for p in &cp.plans {
            let slot = |name: &str| {
                chart
                    .vars
                    .iter()
                    .position(|v| v.name == name)
                    .and_then(|i| inst.var_slots.get(i).copied())
            };
            let (Some(ps), Some(mslot)) = (slot(&p.var), slot(&format!("{}_mode", p.var))) else {
                continue;
            };
            let col = |s: statecheck_ir::SlotId| -> Vec<i64> {
                run.trace
                    .iter()
                    .map(|r| r.slots.get(s as usize).copied().unwrap_or(0))
                    .collect()
            };
            for e in analyse::events(p, tick, &col(mslot), &col(ps)) {
                let zones: Vec<&str> = p
                    .sensors
                    .iter()
                    .filter(|(_, l, h)| *l == e.point || *h == e.point)
                    .map(|(n, _, _)| n.as_str())
                    .collect();
                rows.push((inst.name.clone(), p.var.clone(), zones.join(" "), e));
            }
        }
    }
    rows.sort_by_key(|r| r.3.seconds);
    let status = |e: &analyse::Event| -> &'static str {
        match (e.ticks.as_int(), e.model_tick) {
            (Some(t), Some(m)) if t == m as i128 => "exact",
            (None, _) => "between ticks",
            (_, None) => "not reached by the model",
            _ => "model differs",
        }
    };
    if a.json {
        let v: Vec<_> = rows
            .iter()
            .map(|(i, var, zones, e)| {
                serde_json::json!({
                    "instance": i,
                    "variable": var,
                    "point": e.point,
                    "sensors": zones,
                    "state": e.state,
                    "seconds": e.seconds.to_string(),
                    "ticks": e.ticks.to_string(),
                    "model_tick": e.model_tick,
                    "status": status(e),
                })
            })
            .collect();
        println!(
            "{}",
            serde_json::to_string_pretty(&serde_json::json!({
                "tick_seconds": tick.to_string(),
                "ticks_run": run.trace.len(),
                "events": v,
            }))?
        );
    } else {
        println!(
            "variable          reaches  sensor bound  in state  time (s)  tick  model tick  status"
        );
        for (i, var, zones, e) in &rows {
            println!(
                "{:<16}  {:>7}  {:<12}  {:<8}  {:>8}  {:>4}  {:>10}  {}",
                format!("{i}.{var}"),
                e.point,
                zones,
                e.state,
                e.seconds.to_string(),
                e.ticks.to_string(),
                e.model_tick.map_or("-".to_string(), |t| t.to_string()),
                status(e)
            );
        }
    }
    Ok(0)
}
