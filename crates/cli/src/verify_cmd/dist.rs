//! `statecheck verify --workers N [--hosts FILE --process I]`: the explicit search distributed
//! over timely dataflow workers (`statecheck-dist`, docs/distributed.md), its verdicts
//! printed like the explicit engine's, its communication figures added.

use super::{cex, report, watch, VerifyArgs};
use crate::load::Loaded;
use anyhow::{bail, Context, Result};
use serde_json::json;
use statecheck_dist::{DistReport, DistStats};
use statecheck_explicit::Options;
use statecheck_ir::Program;

/// The addresses of a host file: one `host:port` per line, in process order (timely's
/// convention); blank lines and lines starting with `#` are skipped.
pub fn read_hosts(path: &str) -> Result<Vec<String>> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read host file {path}"))?;
    let hosts: Vec<String> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(str::to_string)
        .collect();
    if let Some(bad) = hosts.iter().find(|h| h.rsplit_once(':').is_none()) {
        bail!("host file {path}: `{bad}` is not host:port");
    }
    if hosts.is_empty() {
        bail!("host file {path} names no host");
    }
    Ok(hosts)
}

/// Run the distributed search and print its report; the exit code.
pub fn run(a: &VerifyArgs, loaded: &Loaded, program: &Program, check: Options) -> Result<u8> {
    let workers = a.workers.unwrap_or(1);
    let hosts = match &a.hosts {
        Some(f) => read_hosts(f)?,
        None => Vec::new(),
    };
    let process = a.process.unwrap_or(0);
    let cancel = statecheck_verify::Cancel::new();
    watch::on_interrupt(&cancel);
    let _memory = check.max_memory.map(|m| watch::memory(&cancel, m));
    let check = Options {
        stop: Some(cancel.flag()),
        ..check
    };
    let opts = statecheck_dist::Options {
        check,
        workers,
        hosts,
        process,
    };
    let mut out = statecheck_dist::verify(program, &opts)?;
    if cancel.reason() == Some(statecheck_verify::CancelReason::Memory) {
        // The resident-set watchdog stopped the run: say so, not "stopped on request".
        out.report.stats.limit = opts
            .check
            .max_memory
            .map(statecheck_explicit::Limit::Memory);
    }
    let DistReport { report: rep, dist } = &out;
    // Only the first process writes counterexample files (the others find the same ones).
    let dir = if process == 0 {
        a.cex_dir.as_deref()
    } else {
        None
    };
    cex::create_dir(dir)?;
    let write = cex::Write {
        vcd: a.vcd,
        minimise: !a.no_minimise,
        // The distributed run's counterexamples come after it ends; they are few (one per
        // violated property, walked back across workers) and are always replayed.
        deadline: None,
    };
    let cexs: Vec<Option<cex::Cex>> = rep
        .results
        .iter()
        .map(|r| cex::one(loaded, program, r, dir, write))
        .collect::<Result<_>>()?;
    let meta: Vec<report::Meta> = rep
        .results
        .iter()
        .map(|r| report::Meta {
            engine: "explicit",
            time_s: None,
            reason: r
                .note
                .clone()
                .filter(|_| r.verdict == statecheck_explicit::Verdict::Unknown),
            decided_at_s: None,
            symmetry_of: None,
        })
        .collect();
    if a.json || a.json_lines {
        let mut v = report::json(program, &loaded.sources, rep, &cexs, &meta);
        v["stats"]["distributed"] = dist_json(dist, rep.stats.states);
        if a.json_lines {
            for r in v["results"].as_array().into_iter().flatten() {
                crate::write_out(None, &format!("{r}\n"))?;
            }
            let s = json!({"stats": v["stats"]});
            crate::write_out(None, &format!("{s}\n"))?;
        } else {
            crate::write_out(None, &format!("{}\n", serde_json::to_string(&v)?))?;
        }
    } else {
        let names = rep.results.iter().map(|r| r.name.as_str());
        let columns = report::Columns::new(names, false);
        let mut t = columns.header();
        for (r, m) in rep.results.iter().zip(&meta) {
            t.push_str(&columns.row(r, m));
        }
        t.push_str(&report::tail(
            loaded, program, rep, &cexs, a.quiet, true, &a.show,
        ));
        if !a.quiet {
            t.push_str(&dist_line(dist, rep.stats.states));
        }
        crate::write_out(None, &t)?;
    }
    Ok(super::exit_code(&rep.results))
}

/// The `distributed` object of the JSON statistics.
fn dist_json(d: &DistStats, states: u64) -> serde_json::Value {
    json!({
        "workers": d.workers,
        "processes": d.processes,
        "exchange_bytes": d.exchange_bytes,
        "control_bytes": d.control_bytes,
        "bytes_per_state": d.bytes_per_state(states),
        "worker_states": d.worker_states,
        "process_peak_bytes": d.process_peak_bytes,
        "rounds": d.rounds,
    })
}

/// The human-readable line of communication figures.
fn dist_line(d: &DistStats, states: u64) -> String {
    let per_worker: Vec<String> = d.worker_states.iter().map(u64::to_string).collect();
    format!(
        "distributed: {} worker(s) in {} process(es), {} exchanged ({:.1} bytes/state), states per worker [{}], {} rounds\n",
        d.workers,
        d.processes,
        statecheck_explicit::human_bytes(d.exchange_bytes + d.control_bytes),
        d.bytes_per_state(states),
        per_worker.join(", "),
        d.rounds
    )
}
