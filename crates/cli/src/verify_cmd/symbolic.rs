//! The SAT-based side of `statecheck verify`: the `--engine` choice, certificates, and AIGER
//! input files (the portfolio itself is `statecheck-verify`).

use anyhow::{bail, Context, Result};
use statecheck_ir::Program;
use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::check::{problems, Engine};
use statecheck_symbolic::engine::{Invariant, Limits, Outcome};
use statecheck_verify::{decide_circuit, race, Run};
use std::time::{Duration, Instant};

/// The engine chosen on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineArg {
    /// Explicit-state breadth-first search (the default).
    Explicit,
    /// Bounded model checking (shortest counterexamples; no proofs).
    Bmc,
    /// k-induction with simple-path constraints.
    Kind,
    /// IC3/PDR (proofs with an inductive invariant).
    Ic3,
    /// IC3 on localization abstractions refined by counterexamples (safety properties of
    /// large circuits that depend on a small part of them; liveness as with ic3).
    Cegar,
    /// Explicit and symbolic engines side by side; the first definitive verdict wins.
    Auto,
}

impl From<EngineArg> for statecheck_verify::Engine {
    fn from(e: EngineArg) -> statecheck_verify::Engine {
        use statecheck_verify::Engine as E;
        match e {
            EngineArg::Explicit => E::Explicit,
            EngineArg::Bmc => E::Bmc,
            EngineArg::Kind => E::Kind,
            EngineArg::Ic3 => E::Ic3,
            EngineArg::Cegar => E::Cegar,
            EngineArg::Auto => E::Auto,
        }
    }
}

impl EngineArg {
    fn symbolic(self) -> Option<Engine> {
        statecheck_verify::Engine::from(self).symbolic()
    }
}

fn limits(timeout: Option<Duration>, depth: Option<u64>) -> Limits {
    Limits {
        deadline: timeout.map(|t| Instant::now() + t),
        attempt_deadline: None,
        max_depth: depth.map(|d| d as usize),
        stop: None,
    }
}

/// Write the certificate of the single proved property of a run.
pub fn write_certificate(run: &Run, file: &str) -> Result<()> {
    let found: Vec<(usize, &(Aig, Invariant))> = run
        .invariants
        .iter()
        .enumerate()
        .filter_map(|(i, x)| x.as_ref().map(|x| (i, x)))
        .collect();
    match found.as_slice() {
        [(i, (aig, inv))] => {
            let name = &run.report.results[*i].name;
            let text = statecheck_symbolic::cert::write(aig, name, inv);
            crate::outpath::write(std::path::Path::new(file), text.as_bytes())?;
            eprintln!(
                "wrote {file}: inductive invariant of `{name}`, {} clause(s)",
                inv.len()
            );
            Ok(())
        }
        [] => bail!(
            "no certificate written: no property was proved by IC3 (use --engine ic3 and a property that holds)"
        ),
        _ => bail!("--certificate needs exactly one property: choose it with --property"),
    }
}

/// `--check-certificate FILE`: check the invariant in FILE for the one circuit given.
pub fn check_certificate(aig: &Aig, name: &str, file: &str) -> Result<u8> {
    crate::outpath::note_input(file);
    let text = std::fs::read_to_string(file).with_context(|| format!("cannot read `{file}`"))?;
    let inv = statecheck_symbolic::cert::parse(&text, aig.latches.len())
        .map_err(|e| anyhow::anyhow!("{file}: {e}"))?;
    match statecheck_symbolic::cert::check(aig, &inv) {
        Ok(()) => {
            println!(
                "certificate valid: {file} proves `{name}` ({} clause(s); initiation, consecution and safety each checked by one SAT call)",
                inv.len()
            );
            Ok(0)
        }
        Err(e) => {
            println!("certificate INVALID for `{name}`: {e}");
            Ok(1)
        }
    }
}

/// The one-property circuit of `name` in a program (for `--check-certificate`).
pub fn model_problem(p: &Program, names: &[String]) -> Result<(Aig, String)> {
    let [name] = names else {
        bail!("--check-certificate needs exactly one --property");
    };
    let (bl, idx) = problems(p, names)?;
    let Some(&(pi, _)) = idx.first() else {
        bail!("no property named `{name}`");
    };
    Ok((bl.problem(pi), name.clone()))
}

/// Names of an AIGER file's properties (`b0`, `b1`, ... unless the symbol table names them).
/// The bad outputs' names as shown and selected: the file's symbols with control characters
/// escaped (a symbol is external text and must not drive the terminal), else `bN`.
/// Justice properties follow, named by their symbols or `jN`.
fn aiger_names(aig: &Aig) -> Vec<String> {
    let bad = (0..aig.bad.len()).map(|i| match aig.bad_names.get(i).cloned().flatten() {
        Some(n) => crate::diag::escape_controls(&n).into_owned(),
        None => format!("b{i}"),
    });
    let justice =
        (0..aig.justice.len()).map(|i| match aig.justice_names.get(i).cloned().flatten() {
            Some(n) => crate::diag::escape_controls(&n).into_owned(),
            None => format!("j{i}"),
        });
    bad.chain(justice).collect()
}

/// Read an AIGER file.
pub fn load_aiger(path: &str) -> Result<Aig> {
    crate::outpath::note_input(path);
    let bytes = std::fs::read(path).with_context(|| format!("cannot read `{path}`"))?;
    statecheck_symbolic::aiger::parse(&bytes).map_err(|e| anyhow::anyhow!("{path}: {e}"))
}

/// The circuit of bad output `i`.
fn single(aig: &Aig, i: usize) -> Aig {
    let mut g = aig.clone();
    g.bad = vec![aig.bad[i]];
    g.bad_names = vec![aig.bad_names.get(i).cloned().flatten()];
    g.reduced()
}

/// Options of an AIGER run.
pub struct AigerRun<'a> {
    /// The file.
    pub path: &'a str,
    /// Properties to check (names or `bN`); all when empty.
    pub properties: &'a [String],
    /// The engine (`auto` and `explicit` mean IC3 with BMC alongside).
    pub engine: EngineArg,
    /// Time limit.
    pub timeout: Option<Duration>,
    /// Depth bound.
    pub depth: Option<u64>,
    /// JSON output.
    pub json: bool,
    /// Write the certificate here.
    pub certificate: Option<&'a str>,
    /// Check this certificate instead of verifying.
    pub check_certificate: Option<&'a str>,
}

/// `statecheck verify FILE.aag|FILE.aig`.
pub fn run_aiger(a: &AigerRun) -> Result<u8> {
    let aig = load_aiger(a.path)?;
    let names = aiger_names(&aig);
    let chosen: Vec<usize> = if a.properties.is_empty() {
        (0..names.len()).collect()
    } else {
        let mut v = Vec::new();
        for p in a.properties {
            match names.iter().position(|n| n == p) {
                Some(i) => v.push(i),
                None => bail!(
                    "no property named `{p}` in {}; the properties are: {}",
                    a.path,
                    names.join(", ")
                ),
            }
        }
        v
    };
    if let Some(cf) = a.check_certificate {
        let [i] = chosen.as_slice() else {
            bail!("--check-certificate needs exactly one property: choose it with --property");
        };
        if *i >= aig.bad.len() {
            bail!(
                "`{}` is a justice property: certificates are for bad-state properties",
                names[*i]
            );
        }
        return check_certificate(&single(&aig, *i), &names[*i], cf);
    }
    let engine = a.engine.symbolic().unwrap_or(Engine::Ic3);
    let mut rows = Vec::new();
    let mut invariants = Vec::new();
    let mut code = 0u8;
    for &i in &chosen {
        if i >= aig.bad.len() {
            rows.push(justice_row(&aig, i - aig.bad.len(), &names[i], a));
            code = match rows.last().map(|r| r.1) {
                Some("violated") => 1,
                Some("unknown") if code == 0 => 3,
                _ => code,
            };
            continue;
        }
        let g = single(&aig, i);
        let lim = limits(a.timeout, a.depth);
        let t = Instant::now();
        let out = if matches!(a.engine, EngineArg::Auto | EngineArg::Explicit) {
            race(&g, &lim)
        } else {
            (decide_circuit(engine, &g, &lim), engine.as_str())
        };
        let time = t.elapsed().as_secs_f64();
        let (verdict, depth, reason) = match &out.0 {
            Outcome::Reached(tr) => ("violated", tr.inputs.len(), None),
            Outcome::Proved(inv) => {
                if let Some(inv) = inv {
                    invariants.push((g.clone(), names[i].clone(), inv.clone()));
                }
                ("proved", 0, None)
            }
            Outcome::Bounded(k) => ("bounded", *k, None),
            Outcome::Unknown { why, cleared } => ("unknown", *cleared, Some(why.clone())),
        };
        code = match verdict {
            "violated" => 1,
            "unknown" if code == 0 => 3,
            _ => code,
        };
        rows.push((names[i].clone(), verdict, out.1, depth, time, reason, "bad"));
    }
    if let Some(cf) = a.certificate {
        match invariants.as_slice() {
            [(g, name, inv)] => {
                let text = statecheck_symbolic::cert::write(g, name, inv);
                crate::outpath::write(std::path::Path::new(cf), text.as_bytes())?;
                eprintln!(
                    "wrote {cf}: inductive invariant of `{name}`, {} clause(s)",
                    inv.len()
                );
            }
            [] => bail!("no certificate written: no property was proved by IC3"),
            _ => bail!("--certificate needs exactly one property: choose it with --property"),
        }
    }
    if a.json {
        let results: Vec<serde_json::Value> = rows
            .iter()
            .map(|(n, v, e, d, t, r, kind)| {
                let mut o = serde_json::json!({"property": n, "kind": kind, "verdict": v,
                    "engine": e, "depth": d, "time_s": t, "counterexample": null});
                if let Some(r) = r {
                    o["reason"] = serde_json::json!(r);
                }
                o
            })
            .collect();
        let v = serde_json::json!({"results": results, "stats": {"inputs": aig.inputs.len(),
            "latches": aig.latches.len(), "ands": aig.num_ands(), "constraints": aig.constraints.len()}});
        crate::write_out(None, &format!("{v}\n"))?;
    } else {
        let w = rows.iter().map(|r| r.0.len()).max().unwrap_or(8).max(8);
        let mut out = format!(
            "{:<w$}  {:<9}  {:<6}  {:>5}  time\n",
            "property", "verdict", "engine", "depth"
        );
        for (n, v, e, d, t, r, _) in &rows {
            out.push_str(&format!(
                "{n:<w$}  {v:<9}  {e:<6}  {d:>5}  {t:.3} s{}\n",
                r.as_ref().map(|x| format!("  ({x})")).unwrap_or_default()
            ));
        }
        crate::write_out(None, &out)?;
    }
    Ok(code)
}

/// One row of `verify FILE.aig`: property, verdict, engine, depth, seconds, reason, kind.
type Row = (
    String,
    &'static str,
    &'static str,
    usize,
    f64,
    Option<String>,
    &'static str,
);

/// The row of justice property `k`: a lasso violates it (depth: its frames), a proof of no
/// fair run proves it.
fn justice_row(aig: &Aig, k: usize, name: &str, a: &AigerRun) -> Row {
    use statecheck_symbolic::live::{LiveOutcome, Method};
    let method = match a.engine {
        EngineArg::Auto | EngineArg::Explicit => None,
        EngineArg::Ic3 | EngineArg::Cegar => Some(Method::L2s(Engine::Ic3)),
        EngineArg::Kind => Some(Method::L2s(Engine::Kind)),
        EngineArg::Bmc => Some(Method::L2s(Engine::Bmc)),
    };
    let lim = limits(a.timeout, a.depth);
    let t = Instant::now();
    let (out, engine) = statecheck_verify::race_justice(aig, k, method, &lim);
    let time = t.elapsed().as_secs_f64();
    let (verdict, depth, reason) = match out {
        LiveOutcome::Lasso { trace, .. } => ("violated", trace.inputs.len(), None),
        LiveOutcome::Proved => ("proved", 0, None),
        LiveOutcome::Bounded(d) => ("bounded", d, None),
        LiveOutcome::Unknown(why) => ("unknown", 0, Some(why)),
    };
    (
        name.to_string(),
        verdict,
        engine,
        depth,
        time,
        reason,
        "justice",
    )
}
