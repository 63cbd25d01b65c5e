//! What ends a run from outside: Ctrl-C (SIGINT) and the memory watchdog. Both raise the
//! portfolio's cancellation flag; the engines stop cooperatively and the run ends with the
//! verdicts decided so far.

use statecheck_verify::{Cancel, CancelReason};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The first SIGINT cancels the run (the decided rows are kept, exit 3); a second one ends
/// the process at once with exit 3.
pub fn on_interrupt(cancel: &Cancel) {
    let cancel = cancel.clone();
    // A handler already installed (a second run in one process) keeps the first one.
    let _ = ctrlc::set_handler(move || {
        if cancel.reason().is_some() {
            statecheck_native::kill_compilers();
            std::process::exit(3);
        }
        cancel.raise(CancelReason::Interrupted);
    });
}

/// The share of `--max-memory` at which the watchdog stops the run: the engines finish the
/// unit of work in hand after the flag is raised, and the peak must stay within the limit
/// plus 10 %.
const TRIGGER: f64 = 0.92;

/// How often the watchdog reads the resident set size.
const PERIOD: Duration = Duration::from_millis(5);

/// How old a reading the SAT engines' memory probe may answer from.
const PROBE_EVERY: Duration = Duration::from_millis(1);

/// Stops the watchdog and removes the SAT engines' memory probe when dropped.
pub struct Watchdog(Arc<AtomicBool>);

impl Drop for Watchdog {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
        statecheck_symbolic::engine::set_memory_probe(None);
    }
}

/// The SAT engines' memory probe: the resident set read at most every [`PROBE_EVERY`], on
/// the engine's own thread, and the run cancelled (reason "memory limit") past `trigger`, or
/// when an allocation the engine announces (`extra` bytes: CaDiCaL's tables about to double)
/// would take it past.
/// CaDiCaL allocates in C++, out of sight of any Rust allocator, and grows in bursts (a
/// frame's clauses, arrays doubled when the variables pass a power of two: hundreds of MB/s);
/// the watchdog thread alone, which a loaded machine may schedule tens of milliseconds late,
/// and the 20 ms relay to the per-property flags would let it run on past the cap.
fn probe(cancel: &Cancel, trigger: u64) -> statecheck_symbolic::engine::MemoryProbe {
    let cancel = cancel.clone();
    let origin = Instant::now();
    // Microseconds since `origin` of the last reading.
    let last = AtomicU64::new(0);
    Arc::new(move |extra: u64| {
        if cancel.reason() == Some(CancelReason::Memory) {
            return true;
        }
        let now = u64::try_from(origin.elapsed().as_micros()).unwrap_or(u64::MAX);
        let prev = last.load(Ordering::Relaxed);
        // An announced allocation is always weighed against a fresh reading (they are rare).
        if extra == 0 && prev != 0 && now.saturating_sub(prev) < PROBE_EVERY.as_micros() as u64 {
            return false;
        }
        last.store(now.max(1), Ordering::Relaxed);
        if rss().is_some_and(|r| r.saturating_add(extra) > trigger) {
            cancel.raise(CancelReason::Memory);
            return true;
        }
        false
    })
}

/// Watch this process's resident set size and cancel the run (reason "memory limit") when it
/// passes [`TRIGGER`] × `limit` bytes. Where the size cannot be read (not Linux), the
/// engines' own estimates are the only limit.
pub fn memory(cancel: &Cancel, limit: u64) -> Watchdog {
    let done = Arc::new(AtomicBool::new(false));
    let d = Arc::clone(&done);
    let cancel = cancel.clone();
    let trigger = (limit as f64 * TRIGGER) as u64;
    statecheck_symbolic::engine::set_memory_probe(Some(probe(&cancel, trigger)));
    std::thread::spawn(move || {
        while !d.load(Ordering::Relaxed) {
            match rss() {
                Some(r) if r > trigger => {
                    cancel.raise(CancelReason::Memory);
                    return;
                }
                Some(_) => {}
                None => return,
            }
            std::thread::sleep(PERIOD);
        }
    });
    Watchdog(done)
}

/// The resident set size of this process in bytes (Linux).
pub fn rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}
