//! `statecheck-fuzz`: the fuzz runner and the differential fuzzer (`docs/reliability.md`).
//!
//! ```text
//! statecheck-fuzz run  [--target all|check|scenario|aiger|fmt] [--executions N] [--seconds T]
//!                      [--jobs J] [--timeout S] [--seed S] [--out DIR] [--root DIR]
//! statecheck-fuzz diff [--models N] [--first I] [--seconds T] [--jobs J] [--seed S] [--batch B]
//!                      [--rust-every K] [--out DIR] [--root DIR]
//! statecheck-fuzz show --target T --seed S --index I     (the input, on stdout)
//! ```
//! Exit code 0 when nothing failed, 1 otherwise, 2 for a usage error.

use statecheck_fuzz::runner::{self, Config};
use statecheck_fuzz::targets::{self, Target};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

struct Args(Vec<String>);

impl Args {
    fn get(&self, flag: &str) -> Option<&str> {
        self.0
            .iter()
            .position(|a| a == flag)
            .and_then(|i| self.0.get(i + 1))
            .map(String::as_str)
    }

    fn num<T: std::str::FromStr>(&self, flag: &str, default: T) -> Result<T, String> {
        match self.get(flag) {
            None => Ok(default),
            Some(v) => v
                .parse()
                .map_err(|_| format!("{flag}: not a number: `{v}`")),
        }
    }
}

fn usage(msg: &str) -> ExitCode {
    eprintln!("statecheck-fuzz: {msg}\nusage: statecheck-fuzz run|diff|show|worker [options] (see docs/reliability.md)");
    ExitCode::from(2)
}

fn root(a: &Args) -> PathBuf {
    a.get("--root")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("."))
}

/// The usage text (the module's documentation, without the comment markers).
const USAGE: &str = "\
statecheck-fuzz run  [--target all|check|scenario|aiger|fmt] [--executions N] [--seconds T]
                     [--jobs J] [--timeout S] [--seed S] [--out DIR] [--root DIR]
statecheck-fuzz diff [--models N] [--first I] [--seconds T] [--jobs J] [--seed S] [--batch B]
                     [--rust-every K] [--out DIR] [--root DIR]
statecheck-fuzz show --target T --seed S --index I     (the input, on stdout)
Exit code 0 when nothing failed, 1 otherwise, 2 for a usage error (docs/reliability.md).";

/// The flags each command reads (with a value, except `--precise`).
fn known_flags(cmd: &str) -> &'static [&'static str] {
    match cmd {
        "run" => &[
            "--target",
            "--executions",
            "--seconds",
            "--jobs",
            "--timeout",
            "--seed",
            "--out",
            "--root",
        ],
        "diff" => &[
            "--models",
            "--first",
            "--seconds",
            "--jobs",
            "--seed",
            "--batch",
            "--rust-every",
            "--out",
            "--root",
        ],
        "show" => &["--target", "--seed", "--index", "--root"],
        "worker" => &[
            "--target",
            "--root",
            "--seed",
            "--start",
            "--stride",
            "--end",
            "--precise",
        ],
        _ => &[],
    }
}

fn main() -> ExitCode {
    let raw: Vec<String> = std::env::args().skip(1).collect();
    if raw
        .iter()
        .any(|a| a == "--help" || a == "-h" || a == "help")
    {
        println!("{USAGE}");
        return ExitCode::SUCCESS;
    }
    let Some(cmd) = raw.first().cloned() else {
        return usage("missing command");
    };
    // A misspelt flag would otherwise start a long run with the defaults.
    let known = known_flags(&cmd);
    // A value may start with '-' (a negative number); an unknown command is refused below.
    let unknown = raw.iter().skip(1).find(|a| {
        a.starts_with('-')
            && !known.contains(&a.as_str())
            && a.parse::<f64>().is_err()
            && !known.is_empty()
    });
    if let Some(bad) = unknown {
        return usage(&format!("unknown option `{bad}` for `{cmd}`"));
    }
    let a = Args(raw);
    match main_cmd(&cmd, &a) {
        Ok(code) => code,
        Err(m) => usage(&m),
    }
}

fn main_cmd(cmd: &str, a: &Args) -> Result<ExitCode, String> {
    match cmd {
        "worker" => {
            let t = target(a.get("--target").unwrap_or(""))?;
            runner::worker(
                t,
                &root(a),
                a.num("--seed", 1)?,
                a.num("--start", 0)?,
                a.num("--stride", 1)?,
                a.num("--end", u64::MAX)?,
                a.0.iter().any(|x| x == "--precise"),
            );
            Ok(ExitCode::SUCCESS)
        }
        "show" => {
            let t = target(a.get("--target").unwrap_or(""))?;
            let (_, seeds) = statecheck_fuzz::corpus::load(t, &root(a));
            let (ctx, bytes) = statecheck_fuzz::mutate::input(
                t,
                &seeds,
                a.num("--seed", 1)?,
                a.num("--index", 0)?,
            );
            eprintln!("context program {ctx}");
            let _ = std::io::stdout().write_all(&bytes);
            Ok(ExitCode::SUCCESS)
        }
        "run" => run(a),
        "diff" => diff(a),
        _ => Err(format!("unknown command `{cmd}`")),
    }
}

fn target(name: &str) -> Result<Target, String> {
    Target::from_name(name).ok_or_else(|| format!("unknown target `{name}`"))
}

fn run(a: &Args) -> Result<ExitCode, String> {
    let which: Vec<Target> = match a.get("--target").unwrap_or("all") {
        "all" => targets::ALL.to_vec(),
        t => vec![target(t)?],
    };
    let seconds: Option<f64> = a
        .get("--seconds")
        .map(|s| s.parse().map_err(|_| format!("--seconds: `{s}`")))
        .transpose()?;
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let mut total = runner::Summary::default();
    let began = Instant::now();
    println!(
        "target      executions      panics  aborts  timeouts  violations   seconds   execs/s"
    );
    for t in which {
        let cfg = Config {
            target: t,
            seed: a.num("--seed", 1)?,
            executions: a.num("--executions", u64::MAX)?,
            duration: seconds.map(Duration::from_secs_f64),
            jobs: a.num("--jobs", 2)?,
            timeout: Duration::from_secs_f64(a.num("--timeout", 10.0)?),
            out: a
                .get("--out")
                .map(PathBuf::from)
                .unwrap_or_else(|| PathBuf::from("fuzz-out")),
            root: root(a),
            exe: exe.clone(),
        };
        if cfg.executions == u64::MAX && cfg.duration.is_none() {
            return Err("give --executions N or --seconds T".into());
        }
        let t0 = Instant::now();
        let s = runner::run(&cfg);
        let secs = t0.elapsed().as_secs_f64();
        println!(
            "{:<10} {:>11} {:>11} {:>7} {:>9} {:>11} {:>9.1} {:>9.0}",
            t.name(),
            s.executions,
            s.panics,
            s.aborts,
            s.timeouts,
            s.violations,
            secs,
            s.executions as f64 / secs.max(1e-9)
        );
        for (i, why) in s.failures.iter().take(20) {
            println!("  {} input {i}: {why}", t.name());
        }
        total.executions += s.executions;
        total.panics += s.panics;
        total.aborts += s.aborts;
        total.timeouts += s.timeouts;
        total.violations += s.violations;
    }
    let secs = began.elapsed().as_secs_f64();
    println!(
        "{:<10} {:>11} {:>11} {:>7} {:>9} {:>11} {:>9.1} {:>9.0}",
        "total",
        total.executions,
        total.panics,
        total.aborts,
        total.timeouts,
        total.violations,
        secs,
        total.executions as f64 / secs.max(1e-9)
    );
    Ok(if total.failed() == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn diff(a: &Args) -> Result<ExitCode, String> {
    use statecheck_fuzz::diff;
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::Mutex;
    let models: u64 = a.num("--models", 1000)?;
    // The index of the first model: `--first 150 --batch 50 --models 50` repeats batch 3.
    let first_model: u64 = a.num("--first", 0)?;
    let seconds: Option<f64> = a
        .get("--seconds")
        .map(|s| s.parse().map_err(|_| format!("--seconds: `{s}`")))
        .transpose()?;
    let seed: u64 = a.num("--seed", 1)?;
    let jobs: usize = a.num("--jobs", 2)?;
    let per: u64 = a.num("--batch", 50)?;
    let rust_every: u64 = a.num("--rust-every", 4)?;
    let out = a
        .get("--out")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("fuzz-out"));
    let spin = diff::spin_available();
    if !spin {
        eprintln!("note: spin not found; Promela is not checked");
    }
    let next = AtomicU64::new(0);
    let saved = AtomicU64::new(0);
    let total = Mutex::new(diff::Report::default());
    let began = Instant::now();
    let batches = models.div_ceil(per.max(1));
    std::thread::scope(|sc| {
        for _ in 0..jobs.max(1) {
            sc.spawn(|| loop {
                let b = next.fetch_add(1, Ordering::Relaxed);
                if b >= batches || seconds.is_some_and(|s| began.elapsed().as_secs_f64() >= s) {
                    break;
                }
                let first = b * per;
                let n = per.min(models - first);
                let rust = rust_every > 0 && b.is_multiple_of(rust_every);
                let r = diff::batch(
                    seed,
                    first_model + first,
                    n,
                    rust,
                    spin,
                    &diff::temp_dir(&format!("b{b}")),
                );
                let mut t = total.lock().unwrap_or_else(|e| e.into_inner());
                // Failures are saved as they come, so that a run stopped early keeps them.
                let _ = std::fs::create_dir_all(&out);
                for f in r.failures.iter().chain(&r.compile_failures) {
                    let k = saved.fetch_add(1, Ordering::Relaxed);
                    let _ = std::fs::write(out.join(format!("diff-{seed}-{k}.txt")), f);
                }
                let b_models = r.models;
                let (b_verdicts, b_replays) = (r.verdicts, r.replays);
                let (b_fail, b_cfail) = (r.failures.len(), r.compile_failures.len());
                t.add(r);
                // The batch and the run's totals so far (a run stopped early keeps its figures).
                eprintln!(
                    "batch {b}: {b_models} models, {b_verdicts} verdicts, {b_replays} replays, {b_fail} failures, {b_cfail} compile failures ({:.0} s); total {} models, {} rejected, {} explicit bounded, {} too wide, {} verdict pairs, {} replays, {} C / {} Rust models, {} failures, {} compile failures",
                    began.elapsed().as_secs_f64(),
                    t.models,
                    t.rejected,
                    t.incomplete,
                    t.too_wide,
                    t.verdicts,
                    t.replays,
                    t.c_models,
                    t.rust_models,
                    t.failures.len(),
                    t.compile_failures.len()
                );
            });
        }
    });
    let t = total.into_inner().unwrap_or_else(|e| e.into_inner());
    let secs = began.elapsed().as_secs_f64();
    println!("models            {}", t.models);
    println!("rejected (E0104)  {}", t.rejected);
    println!(
        "explicit bounded  {} (20,000 states or 10 s: undecided verdicts not compared)",
        t.incomplete
    );
    println!(
        "explicit skipped  {} (too wide: over 50,000 input vectors per tick; no verdicts compared)",
        t.too_wide
    );
    println!("verdict pairs     {}", t.verdicts);
    println!(
        "engine unknowns   bmc {}, kind {}, ic3 {}, cegar {} (a limit: not compared)",
        t.unknown[0], t.unknown[1], t.unknown[2], t.unknown[3]
    );
    println!("replays           {}", t.replays);
    println!("C traces equal    {} models", t.c_models);
    println!("Rust traces equal {} models", t.rust_models);
    println!("spin -a accepted  {}", t.spin_ok);
    println!("disagreements     {}", t.failures.len());
    println!("compile failures  {}", t.compile_failures.len());
    println!(
        "seconds           {secs:.1} ({:.1} models/s)",
        t.models as f64 / secs.max(1e-9)
    );
    let ph = &t.times;
    println!(
        "phase seconds     lower {:.1}, explicit {:.1}, sat {:.1} (bmc {:.1}, kind {:.1}, ic3 {:.1}, cegar {:.1}), spin {:.1}, codegen {:.1}, gcc {:.1}, rustc {:.1}, run {:.1}",
        ph.lower.as_secs_f64(),
        ph.explicit.as_secs_f64(),
        ph.sat.as_secs_f64(),
        ph.engines[0].as_secs_f64(),
        ph.engines[1].as_secs_f64(),
        ph.engines[2].as_secs_f64(),
        ph.engines[3].as_secs_f64(),
        ph.spin.as_secs_f64(),
        ph.codegen.as_secs_f64(),
        ph.gcc.as_secs_f64(),
        ph.rustc.as_secs_f64(),
        ph.run.as_secs_f64()
    );
    for f in t.failures.iter().chain(&t.compile_failures).take(3) {
        println!("---\n{}", f.chars().take(3000).collect::<String>());
    }
    Ok(if t.failures.is_empty() && t.compile_failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
