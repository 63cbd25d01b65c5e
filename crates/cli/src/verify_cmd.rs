//! `statecheck verify`: exhaustive verification of a system's properties with the portfolio
//! (`statecheck-verify`); each verdict printed as it is decided, counterexamples written as
//! scenarios and replayed through the simulator; Ctrl-C and the limits end the run with the
//! verdicts decided so far.
//!
//! Exit codes: 0 every property holds (`proved`, `bounded`, or `reachable` as asked), 1 some
//! property is `violated` or a `reachable` target is `unreachable`, 3 some verdict is `unknown`
//! (a limit was hit), 2 usage errors.

mod cex;
mod dist;
mod live;
mod matrix;
mod report;
mod symbolic;
mod watch;

use crate::load;
use anyhow::{bail, Result};
use clap::Args;
use statecheck_explicit::{Backend, Collapse, Options, Verdict};
use std::io::IsTerminal;
use std::time::Duration;

/// Arguments of `statecheck verify`.
#[derive(Args)]
pub struct VerifyArgs {
    /// The `.sc` model file, or an AIGER file (`.aag` ASCII, `.aig` binary) of a hardware model
    /// checking problem.
    model: String,
    /// The engine: `auto` (the default) runs the explicit engine, BMC, IC3, k-induction and
    /// IC3 on localization abstractions side by side; or explicit-state search alone, or one
    /// SAT engine: BMC, k-induction, IC3, cegar (see docs/verification.md).
    #[arg(long, value_enum, default_value = "auto")]
    engine: symbolic::EngineArg,
    /// Write the inductive invariant IC3 found for the (single) property to FILE.
    #[arg(long, value_name = "FILE")]
    certificate: Option<String>,
    /// Check the inductive invariant in FILE for the (single) property instead of verifying.
    #[arg(long, value_name = "FILE", conflicts_with = "certificate")]
    check_certificate: Option<String>,
    /// The system (or chart) to verify.
    #[arg(long)]
    system: Option<String>,
    /// Verify the system in this configuration (`configuration NAME { … }`, docs/components.md).
    #[arg(long, value_name = "NAME", conflicts_with = "all_configs")]
    config: Option<String>,
    /// Verify the system in every configuration it declares and print a matrix of
    /// configurations × properties (with `--json`: one JSON object).
    #[arg(long, conflicts_with_all = ["cex_dir", "json_lines", "certificate", "check_certificate"])]
    all_configs: bool,
    /// Check only this property (repeatable; built-ins may be named too).
    #[arg(long = "property", value_name = "NAME")]
    properties: Vec<String>,
    /// Explore at most K ticks; undecided properties are then `bounded`.
    #[arg(long, value_name = "K")]
    depth: Option<u64>,
    /// Stop with `unknown` when memory would exceed SIZE (e.g. 512M, 2G); default: 80% of the
    /// available memory.
    #[arg(long, value_name = "SIZE")]
    max_memory: Option<String>,
    /// Stop with `unknown` after N states.
    #[arg(long, value_name = "N")]
    max_states: Option<u64>,
    /// Stop after this many seconds in total: the verdicts decided so far are kept, the rest
    /// are `unknown` (reason "time limit").
    #[arg(long, value_name = "SECONDS")]
    timeout: Option<f64>,
    /// The most each SAT engine spends on one property (with `auto`, `bmc`, `kind`, `ic3`);
    /// a property that exhausts it is `unknown` (reason "property time limit").
    #[arg(long, value_name = "SECONDS")]
    property_timeout: Option<f64>,
    /// Worker threads (default: one per core).
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Distribute the explicit search over N worker threads in this process (timely
    /// dataflow, docs/distributed.md); with --hosts, N per process. Temporal properties are
    /// then reported `unknown`.
    #[arg(long, value_name = "N", conflicts_with_all = ["all_configs", "certificate", "check_certificate"])]
    workers: Option<usize>,
    /// With --workers: the host file, one `host:port` per process in process order (timely's
    /// convention); every process runs the same command with its own --process.
    #[arg(long, value_name = "FILE", requires = "workers")]
    hosts: Option<String>,
    /// With --hosts: this process's line in the host file, counted from 0.
    #[arg(long, value_name = "I", requires = "hosts")]
    process: Option<usize>,
    /// Explore even when there are more than a million input vectors per tick.
    #[arg(long)]
    force: bool,
    /// Symmetry reduction: the elements of instance arrays that nothing tells apart are
    /// interchangeable; the explicit engine stores one state per orbit, and the SAT engines
    /// check one member of each family of element properties (`a[0].p`) and give the others
    /// its verdict (docs/verification.md, "Symmetry reduction"); what breaks an array's
    /// symmetry is reported (W0316–W0318). Off by default: state counts are then those of
    /// every other engine and of SPIN.
    #[arg(long, overrides_with = "no_symmetry")]
    symmetry: bool,
    /// No symmetry reduction (the default).
    #[arg(long)]
    no_symmetry: bool,
    /// Step every input vector the assumes allow from each state, without the explicit
    /// engine's input abstraction (docs/verification.md, "Input abstraction"): the same
    /// states, verdicts, counterexamples and transition counts, more ticks run; for comparing.
    #[arg(long)]
    no_input_reduction: bool,
    /// Collapse compression of the explicit engine's visited set from the start (as SPIN's
    /// COLLAPSE): a state of more than 128 bits is stored as the numbers of its two halves'
    /// distinct values, less than half the memory on closed loops, the same states and
    /// verdicts (docs/verification.md, "Collapse compression"). Without this flag or
    /// --no-collapse, the engine switches to it once its visited set holds two fifths of
    /// --max-memory.
    #[arg(long, overrides_with = "no_collapse")]
    collapse: bool,
    /// Never collapse-compress the visited set (see --collapse).
    #[arg(long)]
    no_collapse: bool,
    /// Bitstate hashing, as SPIN's supertrace: the explicit engine keeps a bit array of SIZE
    /// (e.g. 4G) instead of its visited set, so a search of any length fits. A violation found
    /// is real; a search that runs out of states proves nothing: the other safety verdicts are
    /// `unknown`, with the expected number of omitted states (docs/verification.md, "Bitstate
    /// hashing"). Temporal properties are checked without it.
    #[arg(long, value_name = "SIZE", conflicts_with_all = ["collapse", "workers", "all_configs"])]
    bitstate: Option<String>,
    /// With --bitstate: bits set per state (SPIN's -k).
    #[arg(long, value_name = "K", default_value_t = statecheck_explicit::bitstate::DEFAULT_HASHES, requires = "bitstate")]
    bitstate_hashes: u32,
    /// How the explicit engine computes successors: `interpreter` (the IR's register code),
    /// `native` (the C step function compiled by the system's C compiler, cross-checked
    /// against the interpreter), or `auto` (native once a search runs longer than 0.3 s).
    #[arg(long, value_enum, default_value = "auto")]
    backend: BackendArg,
    /// Print one JSON object at the end.
    #[arg(long, conflicts_with = "json_lines")]
    json: bool,
    /// Print one JSON object per line for each verdict as it is decided, then one with the
    /// statistics.
    #[arg(long)]
    json_lines: bool,
    /// Print only the verdict table (no statistics, counterexample tables or progress).
    #[arg(long, short)]
    quiet: bool,
    /// Show only these variables and events in counterexample tables: globs over
    /// `instance.name` (`*` any characters, `?` one), comma-separated or repeated.
    #[arg(long, value_name = "PATTERN")]
    show: Vec<String>,
    /// Write each counterexample or witness as a scenario file `DIR/PROPERTY.scn`.
    #[arg(long, value_name = "DIR")]
    cex_dir: Option<String>,
    /// Also write each counterexample as a VCD waveform `DIR/PROPERTY.vcd` (needs --cex-dir).
    #[arg(long, requires = "cex_dir")]
    vcd: bool,
    /// Write counterexamples and witnesses as the engines found them, without minimising
    /// (by default inputs that do not matter are kept at their previous value).
    #[arg(long)]
    no_minimise: bool,
    // --- supervisor check (issue 7, docs/synthesis.md; implemented in synth_cmd) ---
    /// Check MODEL as a supervisor of the plant in this file: controllability, nonblocking and
    /// the requirements, in the closed loop (see docs/synthesis.md).
    #[arg(long, value_name = "PLANT.sc")]
    plant: Option<String>,
    /// The plant file's system of plants and requirements (with --plant).
    #[arg(long, value_name = "NAME", requires = "plant")]
    plant_system: Option<String>,
}

/// `--backend`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum BackendArg {
    Auto,
    Interpreter,
    Native,
}

impl From<BackendArg> for Backend {
    fn from(b: BackendArg) -> Backend {
        match b {
            BackendArg::Auto => Backend::Auto,
            BackendArg::Interpreter => Backend::Interpreter,
            BackendArg::Native => Backend::Native,
        }
    }
}

/// Run the command; returns the exit code.
pub fn run(a: VerifyArgs) -> Result<u8> {
    // `--timeout` counts from here: reading, checking and lowering the model are inside it.
    let started = std::time::Instant::now();
    if let Some(plant) = &a.plant {
        let (sys, psys) = (a.system.as_deref(), a.plant_system.as_deref());
        return crate::supervisor::verify_supervisor(&a.model, sys, plant, psys, a.quiet);
    }
    // --- end supervisor check ---
    let max_memory = match &a.max_memory {
        Some(s) => Some(parse_size(s)?),
        None => default_memory_limit(),
    };
    if a.threads == Some(0) {
        bail!("--threads must be at least 1");
    }
    let timeout = seconds(a.timeout, "--timeout")?;
    let property_timeout = seconds(a.property_timeout, "--property-timeout")?;
    if a.model.ends_with(".aag") || a.model.ends_with(".aig") {
        return symbolic::run_aiger(&symbolic::AigerRun {
            path: &a.model,
            properties: &a.properties,
            engine: a.engine,
            timeout,
            depth: a.depth,
            json: a.json,
            certificate: a.certificate.as_deref(),
            check_certificate: a.check_certificate.as_deref(),
        });
    }
    let loaded = load::load(&a.model, false)?;
    let sys = loaded.system_in(a.system.as_deref(), a.config.as_deref())?;
    if a.all_configs {
        let base = sys.name.clone();
        let check = options(&a, max_memory, remaining(timeout, started));
        let cancel = statecheck_verify::Cancel::new();
        watch::on_interrupt(&cancel);
        let _memory = max_memory.map(|m| watch::memory(&cancel, m));
        let vopts = statecheck_verify::Options {
            engine: a.engine.into(),
            check,
            property_timeout,
            cancel: Some(cancel),
        };
        let how = matrix::Matrix {
            opts: &vopts,
            symmetry: a.symmetry && !a.no_symmetry,
            warn: !a.quiet,
            json: a.json,
        };
        return matrix::run(&loaded, &base, &how);
    }
    let program = loaded.lower(sys)?;
    crate::output::table::show(
        &mut statecheck_ir::view::TraceView::new(&loaded.model, &program),
        &a.show,
    )?;
    if let Some(cf) = &a.check_certificate {
        let (aig, name) = symbolic::model_problem(&program, &a.properties)?;
        return symbolic::check_certificate(&aig, &name, cf);
    }
    if a.certificate.is_some()
        && !matches!(
            a.engine,
            symbolic::EngineArg::Ic3 | symbolic::EngineArg::Cegar
        )
    {
        bail!("--certificate needs --engine ic3 or cegar");
    }
    let mut opts = options(&a, max_memory, remaining(timeout, started));
    if let Some(size) = &a.bitstate {
        opts.bitstate = Some(bitstate(size, a.bitstate_hashes, max_memory)?);
    }
    if a.symmetry && !a.no_symmetry {
        let found = statecheck_ir::symmetry::detect(sys, &program);
        if !a.quiet {
            crate::diag::eprint_sources(&loaded.sources, &found.diagnostics);
        }
        opts.symmetry = Some(std::sync::Arc::new(found.symmetry));
    }
    let engine: statecheck_verify::Engine = a.engine.into();
    if opts.bitstate.is_some()
        && !matches!(
            engine,
            statecheck_verify::Engine::Auto | statecheck_verify::Engine::Explicit
        )
    {
        bail!(
            "--bitstate is a mode of the explicit engine; it cannot be combined with --engine {}",
            engine.as_str()
        );
    }
    if a.workers.is_some() {
        if !matches!(
            engine,
            statecheck_verify::Engine::Auto | statecheck_verify::Engine::Explicit
        ) {
            bail!(
                "--workers distributes the explicit engine; it cannot be combined with --engine {}",
                engine.as_str()
            );
        }
        if opts.symmetry.is_some() && !a.quiet {
            // Said, not silently dropped: the counts are then the full search's.
            eprintln!(
                "warning: --workers explores without symmetry reduction: its state counts are those of the full search (docs/distributed.md)"
            );
        }
        return dist::run(&a, &loaded, &program, opts);
    }
    let explicit = engine == statecheck_verify::Engine::Explicit;
    if explicit {
        report::announce_branching(&program, &opts, a.json || a.json_lines || a.quiet);
    }
    let names: Vec<String> = statecheck_verify::row_names(&program, &a.properties);
    let format = if a.json {
        live::Format::Json
    } else if a.json_lines {
        live::Format::JsonLines
    } else {
        live::Format::Table
    };
    let engines: &[&'static str] = match engine {
        statecheck_verify::Engine::Auto => &["explicit", "bmc", "ic3", "kind"],
        e => &[e.as_str()][..],
    };
    let engines: Vec<&'static str> = engines.to_vec();
    let show = format == live::Format::Table && !a.quiet && std::io::stderr().is_terminal();
    cex::create_dir(a.cex_dir.as_deref())?;
    let columns = report::Columns::new(names.iter().map(String::as_str), !explicit);
    let live = live::Live::new(
        &loaded,
        &program,
        names,
        &engines,
        columns,
        format,
        a.cex_dir.as_deref(),
        cex::Write {
            vcd: a.vcd,
            minimise: !a.no_minimise,
            deadline: timeout.map(|t| started + t),
        },
        show,
    );
    let cancel = statecheck_verify::Cancel::new();
    watch::on_interrupt(&cancel);
    let _memory = max_memory.map(|m| watch::memory(&cancel, m));
    let vopts = statecheck_verify::Options {
        engine,
        check: opts,
        property_timeout,
        cancel: Some(cancel),
    };
    live.start();
    let outcome = statecheck_verify::verify(&program, &vopts, &|e| live.event(e));
    live.finish();
    let run = match outcome {
        Ok(r) => r,
        Err(e) => bail!("{e}"),
    };
    if let Some(cf) = &a.certificate {
        symbolic::write_certificate(&run, cf)?;
    }
    let rep = &run.report;
    let cexs = live.counterexamples(&rep.results)?;
    match format {
        live::Format::Json => {
            let v = report::json(&program, &loaded.sources, rep, &cexs, &run.meta);
            crate::write_out(None, &format!("{}\n", serde_json::to_string(&v)?))?;
        }
        live::Format::JsonLines => {
            let v = serde_json::json!({"stats": report::stats_json(&program, &loaded.sources, &rep.stats)});
            crate::write_out(None, &format!("{v}\n"))?;
        }
        live::Format::Table => {
            let t = report::tail(&loaded, &program, rep, &cexs, a.quiet, explicit, &a.show);
            crate::write_out(None, &t)?;
        }
    }
    Ok(exit_code(&rep.results))
}

/// The engines' options from the flags.
/// What is left of `timeout` since `started` (zero when it has passed: the engines then answer
/// `unknown` at once).
fn remaining(timeout: Option<Duration>, started: std::time::Instant) -> Option<Duration> {
    timeout.map(|t| t.saturating_sub(started.elapsed()))
}

fn options(a: &VerifyArgs, max_memory: Option<u64>, timeout: Option<Duration>) -> Options {
    Options {
        properties: a.properties.clone(),
        depth: a.depth,
        max_memory,
        max_states: a.max_states,
        timeout,
        threads: a.threads.unwrap_or(0),
        force: a.force,
        backend: a.backend.into(),
        compiler: Some(std::sync::Arc::new(statecheck_native::CCompiler)),
        reduce_inputs: !a.no_input_reduction,
        collapse: match (a.collapse, a.no_collapse) {
            (true, _) => Collapse::On,
            (false, true) => Collapse::Off,
            (false, false) => Collapse::Auto,
        },
        ..Options::default()
    }
}

/// The bitstate options of `--bitstate SIZE --bitstate-hashes K`: the array must leave room
/// under the memory limit for the layers being expanded.
fn bitstate(
    size: &str,
    hashes: u32,
    max_memory: Option<u64>,
) -> Result<statecheck_explicit::bitstate::Bitstate> {
    let bytes = parse_size(size)?;
    let most = statecheck_explicit::bitstate::MAX_HASHES;
    if !(1..=most).contains(&hashes) {
        bail!("--bitstate-hashes must be between 1 and {most}");
    }
    if let Some(m) = max_memory.filter(|&m| bytes >= m / 10 * 9) {
        bail!(
            "--bitstate {size} leaves no room under the memory limit of {} for the states being expanded: give a smaller array or a larger --max-memory",
            statecheck_explicit::human_bytes(m)
        );
    }
    Ok(statecheck_explicit::bitstate::Bitstate { bytes, hashes })
}

/// A positive number of seconds.
fn seconds(v: Option<f64>, flag: &str) -> Result<Option<Duration>> {
    match v {
        Some(t) if !(t > 0.0 && t.is_finite()) => {
            bail!("{flag} must be a positive number of seconds")
        }
        Some(t) => Ok(Some(Duration::from_secs_f64(t))),
        None => Ok(None),
    }
}

/// 1 when something is violated or unreachable, else 3 when something is unknown, else 0.
fn exit_code(results: &[statecheck_explicit::PropResult]) -> u8 {
    if results
        .iter()
        .any(|r| matches!(r.verdict, Verdict::Violated | Verdict::Unreachable))
    {
        1
    } else if results.iter().any(|r| r.verdict == Verdict::Unknown) {
        3
    } else {
        0
    }
}

/// Parse a size such as `512M`, `2G`, `1.5GiB`, `1000000` (bytes).
fn parse_size(s: &str) -> Result<u64> {
    let t = s.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let n: f64 = match num.parse() {
        Ok(n) => n,
        Err(_) => bail!("bad size `{s}`: write a number with an optional unit, e.g. 512M or 2G"),
    };
    let mult: f64 = match unit
        .trim()
        .to_ascii_uppercase()
        .trim_end_matches("IB")
        .trim_end_matches('B')
    {
        "" => 1.0,
        "K" => 1024.0,
        "M" => 1024.0 * 1024.0,
        "G" => 1024.0 * 1024.0 * 1024.0,
        "T" => 1024.0 * 1024.0 * 1024.0 * 1024.0,
        _ => bail!("bad size unit in `{s}`: use K, M, G or T"),
    };
    let bytes = n * mult;
    if !(bytes >= 1.0 && bytes.is_finite()) {
        bail!("bad size `{s}`: must be at least one byte");
    }
    Ok(bytes as u64)
}

/// 80% of the memory available now (Linux), so that a run ends with `unknown` instead of being
/// killed.
fn default_memory_limit() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024 / 5 * 4)
}

#[cfg(test)]
mod tests {
    use super::parse_size;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("512M").ok(), Some(512 << 20));
        assert_eq!(parse_size("2G").ok(), Some(2 << 30));
        assert_eq!(parse_size("2GiB").ok(), Some(2 << 30));
        assert_eq!(parse_size("1000").ok(), Some(1000));
        assert!(parse_size("12Q").is_err());
        assert!(parse_size("").is_err());
    }
}
