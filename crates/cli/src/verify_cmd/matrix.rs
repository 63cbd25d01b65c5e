//! `verify --all-configs`: every configuration of a system verified against the same
//! properties (docs/components.md), printed as a matrix of configurations × properties, or
//! as one JSON object. A configuration whose verdict is `violated` does not stop the others.

use crate::load::Loaded;
use anyhow::{bail, Result};
use statecheck_model::components::CONFIG_SEP;
use std::time::Instant;

/// One configuration's results.
struct Row {
    config: String,
    seconds: f64,
    states: u64,
    /// Per property in report order.
    cells: Vec<Cell>,
}

/// One property's verdict in one configuration.
struct Cell {
    property: String,
    verdict: &'static str,
    depth: u64,
    /// When the model declares a tick: the deciding tick of a counterexample or witness and
    /// its time in seconds (as `statecheck_ir::time` writes it). Models without a tick keep
    /// the matrix they had.
    tick: Option<(u64, String)>,
}

/// How the matrix is verified and printed.
pub struct Matrix<'a> {
    /// The engine, limits and properties of every configuration's run.
    pub opts: &'a statecheck_verify::Options,
    /// `--symmetry`: each configuration's interchangeable arrays are detected in its own
    /// program (a configuration may break a symmetry another keeps).
    pub symmetry: bool,
    /// Print the symmetry warnings (W0316–W0318) of each configuration.
    pub warn: bool,
    /// One JSON object instead of the table.
    pub json: bool,
}

/// Verify `base` in each configuration; print the matrix; the exit code is the worst over
/// all configurations (1 violated, else 3 unknown, else 0).
pub fn run(loaded: &Loaded, base: &str, how: &Matrix) -> Result<u8> {
    let json = how.json;
    let configs = loaded.configurations(base);
    if configs.is_empty() {
        bail!("system `{base}` declares no configurations: --all-configs needs some");
    }
    let mut rows = Vec::new();
    let mut code = 0u8;
    for config in &configs {
        let name = format!("{base}{CONFIG_SEP}{config}");
        let sys = loaded.system(Some(&name))?;
        let program = loaded.lower(sys)?;
        let mut opts = how.opts.clone();
        if how.symmetry {
            let found = statecheck_ir::symmetry::detect(sys, &program);
            if how.warn {
                crate::diag::eprint_sources(&loaded.sources, &found.diagnostics);
            }
            opts.check.symmetry = Some(std::sync::Arc::new(found.symmetry));
        }
        let start = Instant::now();
        let run = match statecheck_verify::verify(&program, &opts, &|_| {}) {
            Ok(r) => r,
            Err(e) => bail!("configuration `{config}`: {e}"),
        };
        let results = &run.report.results;
        code = code.max(match super::exit_code(results) {
            1 => 2, // ranks above unknown
            3 => 1,
            _ => 0,
        });
        rows.push(Row {
            config: config.clone(),
            seconds: start.elapsed().as_secs_f64(),
            states: run.report.stats.states,
            cells: results
                .iter()
                .map(|r| Cell {
                    property: r.name.clone(),
                    verdict: r.verdict.as_str(),
                    depth: r.depth,
                    tick: r.counterexample.as_ref().and_then(|_| {
                        let t = r.depth.saturating_sub(1);
                        program.time_text(t).map(|time| (t, time))
                    }),
                })
                .collect(),
        });
    }
    let text = if json {
        format!("{}\n", serde_json::to_string(&to_json(base, &rows))?)
    } else {
        let mut t = table(&rows);
        for r in &rows {
            if r.cells
                .iter()
                .any(|c| matches!(c.verdict, "violated" | "unreachable"))
            {
                t.push_str(&format!(
                    "configuration `{}` fails: its counterexamples with `statecheck verify {} --system {base} --config {}`\n",
                    r.config, loaded.path, r.config
                ));
            }
        }
        t
    };
    crate::write_out(None, &text)?;
    Ok(match code {
        2 => 1,
        1 => 3,
        _ => 0,
    })
}

/// Properties as columns (in the first configuration's order, then any others), one row per
/// configuration with its time and state count.
fn table(rows: &[Row]) -> String {
    let mut props: Vec<&str> = Vec::new();
    for r in rows {
        for c in &r.cells {
            if !props.contains(&c.property.as_str()) {
                props.push(&c.property);
            }
        }
    }
    let mut head = vec!["configuration".to_string()];
    head.extend(props.iter().map(|p| p.to_string()));
    head.push("states".into());
    head.push("time".into());
    let mut lines = vec![head];
    for r in rows {
        let mut line = vec![r.config.clone()];
        for p in &props {
            // With a declared tick, a counterexample's or witness's time follows its verdict.
            let cell = r
                .cells
                .iter()
                .find(|c| c.property == *p)
                .map_or("-".to_string(), |c| match &c.tick {
                    Some((_, time)) => format!("{} ({time} s)", c.verdict),
                    None => c.verdict.to_string(),
                });
            line.push(cell);
        }
        line.push(r.states.to_string());
        line.push(format!("{:.3} s", r.seconds));
        lines.push(line);
    }
    let cols = lines[0].len();
    let width: Vec<usize> = (0..cols)
        .map(|i| {
            lines
                .iter()
                .map(|l| l[i].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for l in &lines {
        let cells: Vec<String> = l
            .iter()
            .zip(&width)
            .map(|(c, w)| format!("{c:<w$}"))
            .collect();
        out.push_str(cells.join("  ").trim_end());
        out.push('\n');
    }
    out
}

fn to_json(base: &str, rows: &[Row]) -> serde_json::Value {
    let configs: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            let results: Vec<serde_json::Value> = r
                .cells
                .iter()
                .map(|c| {
                    let mut o = serde_json::json!({"property": c.property, "verdict": c.verdict, "depth": c.depth});
                    if let Some((tick, time)) = &c.tick {
                        o["tick"] = serde_json::json!(tick);
                        if let Ok(t) = time.parse::<f64>() {
                            o["time"] = serde_json::json!(t);
                        }
                    }
                    o
                })
                .collect();
            serde_json::json!({
                "configuration": r.config,
                "system": format!("{base}{CONFIG_SEP}{}", r.config),
                "states": r.states,
                "time_s": r.seconds,
                "results": results,
            })
        })
        .collect();
    serde_json::json!({"system": base, "configurations": configs})
}
