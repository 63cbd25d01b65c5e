//! The runner: a target's inputs executed by worker processes (one per core by default).
//!
//! A worker ([`worker`]) runs inputs `start, start + stride, …` in order and catches panics
//! itself (`p I message`); an `Err` of the target is a broken promise (`v I message`). A *fast*
//! worker reports progress in checkpoints, `c I` (every input before `I` is done), after every
//! [`CHECKPOINT_INPUTS`] inputs or [`CHECKPOINT_MS`] of work, so that the pipe costs nothing per
//! input; a *precise* worker prints `s I` before each input. The parent ([`run`]) reads these
//! lines. When a fast worker dies (an abort, a stack overflow) or falls silent for longer than
//! the timeout, the parent kills it and replays the inputs since its last checkpoint in a
//! precise worker: the input that kills that one (or hangs it) is the culprit, charged as an
//! abort or a timeout, rebuilt from its index and saved under `OUT/crashes/` or
//! `OUT/timeouts/`; a fast worker then continues after it.

use crate::corpus::{self, Seed};
use crate::mutate;
use crate::targets::{self, Context, Target};
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// What a run found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Inputs started.
    pub executions: u64,
    /// Panics caught in a worker.
    pub panics: u64,
    /// Workers that died on an input (abort, stack overflow, signal).
    pub aborts: u64,
    /// Inputs that ran longer than the timeout.
    pub timeouts: u64,
    /// Broken promises of the target (`Err`).
    pub violations: u64,
    /// The indices of the failing inputs, with what happened.
    pub failures: Vec<(u64, String)>,
}

impl Summary {
    /// Panics, aborts, timeouts and violations together.
    pub fn failed(&self) -> u64 {
        self.panics + self.aborts + self.timeouts + self.violations
    }
}

/// A run's settings.
#[derive(Clone, Debug)]
pub struct Config {
    /// The target.
    pub target: Target,
    /// The run's seed (input `i` depends on it and `i` only).
    pub seed: u64,
    /// Run at most this many inputs.
    pub executions: u64,
    /// Stop after this long (whichever comes first).
    pub duration: Option<Duration>,
    /// Worker processes.
    pub jobs: usize,
    /// An input running longer than this is a timeout.
    pub timeout: Duration,
    /// Where failing inputs are saved (`crashes/`, `timeouts/`).
    pub out: PathBuf,
    /// The repository (the seed corpus).
    pub root: PathBuf,
    /// The fuzz binary (the workers run `EXE worker …`).
    pub exe: PathBuf,
}

fn panic_message(e: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = e.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = e.downcast_ref::<String>() {
        s.clone()
    } else {
        "panic".into()
    }
}

/// Run one input, catching a panic: `Ok` or what went wrong (`p`anic or `v`iolation).
pub fn execute(
    target: Target,
    ctx: &Context,
    which: usize,
    bytes: &[u8],
) -> Result<(), (char, String)> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        targets::run(target, bytes, ctx, which)
    })) {
        Ok(Ok(())) => Ok(()),
        Ok(Err(m)) => Err(('v', m)),
        Err(e) => Err(('p', panic_message(&*e))),
    }
}

/// A fast worker checkpoints after this many inputs at most.
pub const CHECKPOINT_INPUTS: u64 = 256;
/// … or after this much work (milliseconds), whichever comes first.
pub const CHECKPOINT_MS: u64 = 200;

/// Run `count` inputs of `target` in this process (panics caught; no protection against
/// aborts or hangs): the short run of the test suite.
pub fn run_in_process(target: Target, root: &Path, seed: u64, count: u64) -> Summary {
    let (ctx, seeds) = corpus::load(target, root);
    let prev = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut s = Summary::default();
    for i in 0..count {
        let (which, bytes) = mutate::input(target, &seeds, seed, i);
        s.executions += 1;
        if let Err((k, m)) = execute(target, &ctx, which, &bytes) {
            if k == 'p' {
                s.panics += 1;
            } else {
                s.violations += 1;
            }
            s.failures.push((i, m));
        }
    }
    std::panic::set_hook(prev);
    s
}

/// The worker: inputs `start, start + stride, … < end`, reported on stdout; `precise` announces
/// every input before running it (`s I`), otherwise progress is reported in checkpoints
/// (`c I`). Both end with `c NEXT` and `d`.
pub fn worker(
    target: Target,
    root: &Path,
    seed: u64,
    start: u64,
    stride: u64,
    end: u64,
    precise: bool,
) {
    let (ctx, seeds) = corpus::load(target, root);
    std::panic::set_hook(Box::new(|_| {}));
    let out = std::io::stdout();
    let mut out = out.lock();
    let mut i = start;
    let mut since = Instant::now();
    let mut count = 0u64;
    // Ready (the corpus is loaded): the parent's clock for timeouts starts now.
    if writeln!(out, "c {i}").and_then(|_| out.flush()).is_err() {
        return;
    }
    while i < end {
        let (which, bytes) = mutate::input(target, &seeds, seed, i);
        if precise && writeln!(out, "s {i}").and_then(|_| out.flush()).is_err() {
            return;
        }
        if let Err((k, m)) = execute(target, &ctx, which, &bytes) {
            let m = m.replace('\n', " ");
            if writeln!(out, "{k} {i} {m}")
                .and_then(|_| out.flush())
                .is_err()
            {
                return;
            }
        }
        i = i.saturating_add(stride.max(1));
        count += 1;
        if !precise
            && (count >= CHECKPOINT_INPUTS
                || since.elapsed() >= Duration::from_millis(CHECKPOINT_MS))
        {
            if writeln!(out, "c {i}").and_then(|_| out.flush()).is_err() {
                return;
            }
            count = 0;
            since = Instant::now();
        }
    }
    let _ = writeln!(out, "c {i}\nd");
    let _ = out.flush();
}

enum Msg {
    Line(usize, u32, String),
    Eof(usize, u32),
}

struct Slot {
    child: Option<Child>,
    generation: u32,
    /// Every input of this slot before `next` is done (and counted).
    next: u64,
    /// A precise worker replaying the inputs before this index (after a fast worker died).
    precise_until: Option<u64>,
    /// The input a precise worker announced last.
    last: Option<u64>,
    since: Instant,
    /// The worker has loaded its corpus (said anything).
    ready: bool,
    done: bool,
    killed_for_timeout: bool,
}

fn ext(t: Target) -> &'static str {
    match t {
        Target::Check | Target::Fmt => "sc",
        Target::Scenario => "scn",
        Target::Aiger => "aig",
        Target::SelfTest => "input",
    }
}

fn save(cfg: &Config, seeds: &[Seed], kind: &str, index: u64, why: &str) {
    let dir = cfg.out.join(kind);
    let _ = std::fs::create_dir_all(&dir);
    let (ctx, bytes) = mutate::input(cfg.target, seeds, cfg.seed, index);
    let stem = format!("{}-{}-{index}", cfg.target.name(), cfg.seed);
    let _ = std::fs::write(dir.join(format!("{stem}.{}", ext(cfg.target))), bytes);
    let _ = std::fs::write(
        dir.join(format!("{stem}.txt")),
        format!("{why}\ncontext program {ctx}\nrebuild: statecheck-fuzz show --target {} --seed {} --index {index}\n", cfg.target.name(), cfg.seed),
    );
}

#[allow(clippy::too_many_arguments)] // reason: one call site per mode, all values differ
fn spawn(
    cfg: &Config,
    w: usize,
    gen: u32,
    start: u64,
    end: u64,
    precise: bool,
    tx: &mpsc::Sender<Msg>,
) -> Option<Child> {
    let mut cmd = Command::new(&cfg.exe);
    cmd.arg("worker")
        .args(["--target", cfg.target.name()])
        .arg("--root")
        .arg(&cfg.root)
        .args(["--seed", &cfg.seed.to_string()])
        .args(["--start", &start.to_string()])
        .args(["--stride", &cfg.jobs.max(1).to_string()])
        .args(["--end", &end.to_string()]);
    if precise {
        cmd.arg("--precise");
    }
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let stdout = child.stdout.take()?;
    let tx = tx.clone();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            let Ok(line) = line else { break };
            if tx.send(Msg::Line(w, gen, line)).is_err() {
                return;
            }
        }
        let _ = tx.send(Msg::Eof(w, gen));
    });
    Some(child)
}

/// Run `cfg.target` in `cfg.jobs` worker processes; failing inputs are saved under `cfg.out`.
pub fn run(cfg: &Config) -> Summary {
    let (_, seeds) = corpus::load(cfg.target, &cfg.root);
    let jobs = cfg.jobs.max(1);
    let stride = jobs as u64;
    let end = cfg.executions;
    let (tx, rx) = mpsc::channel();
    let mut slots: Vec<Slot> = (0..jobs)
        .map(|w| Slot {
            child: spawn(cfg, w, 0, w as u64, end, false, &tx),
            generation: 0,
            next: w as u64,
            precise_until: None,
            last: None,
            since: Instant::now(),
            ready: false,
            done: false,
            killed_for_timeout: false,
        })
        .collect();
    let mut s = Summary::default();
    // Inputs already charged (a precise replay meets again the panics its fast worker reported).
    let mut charged = std::collections::HashSet::new();
    let began = Instant::now();
    let mut stopping = false;
    loop {
        if slots.iter().all(|x| x.child.is_none()) {
            break;
        }
        let msg = rx.recv_timeout(Duration::from_millis(100));
        match msg {
            Ok(Msg::Line(w, g, line)) if g == slots[w].generation => {
                let slot = &mut slots[w];
                slot.since = Instant::now();
                slot.ready = true;
                let mut parts = line.splitn(3, ' ');
                let k = parts.next().unwrap_or("");
                let i: u64 = parts.next().and_then(|x| x.parse().ok()).unwrap_or(0);
                let m = parts.next().unwrap_or("").to_string();
                match k {
                    "s" => {
                        // Precise: input `i` starts; everything before it is done.
                        s.executions += 1;
                        slot.last = Some(i);
                        slot.next = i;
                    }
                    "c" => {
                        if slot.precise_until.is_none() {
                            s.executions += i.saturating_sub(slot.next) / stride;
                        }
                        slot.next = i;
                    }
                    "p" | "v" if charged.insert(i) => {
                        if k == "p" {
                            s.panics += 1;
                        } else {
                            s.violations += 1;
                        }
                        let kind = if k == "p" { "panic" } else { "violation" };
                        save(cfg, &seeds, "crashes", i, &format!("{kind}: {m}"));
                        s.failures.push((i, format!("{kind}: {m}")));
                    }
                    "d" => slot.done = true,
                    _ => {}
                }
            }
            Ok(Msg::Eof(w, g)) if g == slots[w].generation => {
                let slot = &mut slots[w];
                let status = slot.child.take().and_then(|mut c| c.wait().ok());
                if stopping {
                    continue;
                }
                let resume = if slot.done {
                    match slot.precise_until {
                        // A precise replay that found nothing (a hang under load that did not
                        // come back): the fast worker goes on after it.
                        Some(_) => Some(slot.next),
                        None => None,
                    }
                } else if slot.precise_until.is_none() {
                    // A fast worker died or hung: replay since its checkpoint, input by input.
                    let until = slot
                        .next
                        .saturating_add(stride.saturating_mul(CHECKPOINT_INPUTS + 1))
                        .min(end);
                    slot.generation += 1;
                    slot.precise_until = Some(until);
                    slot.last = None;
                    slot.done = false;
                    slot.since = Instant::now();
                    slot.ready = false;
                    slot.killed_for_timeout = false;
                    slot.child = spawn(cfg, w, slot.generation, slot.next, until, true, &tx);
                    continue;
                } else if let Some(i) = slot.last {
                    let why = if slot.killed_for_timeout {
                        s.timeouts += 1;
                        save(cfg, &seeds, "timeouts", i, "timeout");
                        "timeout".to_string()
                    } else {
                        s.aborts += 1;
                        let why = format!("abort: worker ended with {status:?}");
                        save(cfg, &seeds, "crashes", i, &why);
                        why
                    };
                    charged.insert(i);
                    s.failures.push((i, why));
                    Some(i.saturating_add(stride))
                } else {
                    // Died before its first input: nothing to blame, do not respawn forever.
                    None
                };
                let Some(next) = resume else { continue };
                slot.generation += 1;
                slot.precise_until = None;
                slot.last = None;
                slot.next = next;
                slot.done = false;
                slot.since = Instant::now();
                slot.ready = false;
                slot.killed_for_timeout = false;
                if next < end {
                    slot.child = spawn(cfg, w, slot.generation, next, end, false, &tx);
                }
            }
            _ => {}
        }
        let now = Instant::now();
        if !stopping && cfg.duration.is_some_and(|d| now.duration_since(began) >= d) {
            stopping = true;
            for slot in &mut slots {
                if let Some(c) = slot.child.as_mut() {
                    let _ = c.kill();
                }
            }
        }
        for slot in &mut slots {
            if !stopping
                && slot.ready
                && !slot.killed_for_timeout
                && now.duration_since(slot.since) > cfg.timeout
            {
                if let Some(c) = slot.child.as_mut() {
                    slot.killed_for_timeout = true;
                    let _ = c.kill();
                }
            }
        }
    }
    s
}
