//! BMC on all of a program's own properties in one unrolling of the circuit they share, for
//! `auto` and for BMC alone: shortest counterexamples and witnesses as they are found, the
//! properties still open `bounded` at the depth bound, and the depth cleared per property.

use crate::schedule::Work;
use crate::Event;
use statecheck_ir::verdict::{PropKind, PropResult, Verdict};
use statecheck_symbolic::bmc::ManyEnd;
use statecheck_symbolic::check::{bmc_shared, Engine, SymResult};
use statecheck_symbolic::engine::Limits;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Instant;

/// BMC on every own property in one unrolling (`check::bmc_shared`): each
/// counterexample or witness goes to `record` as it is found, and at the depth bound every
/// property still open in it is `bounded` there. `cleared[i]` follows the depth it cleared
/// property `i` to. The built-ins (their own constraints) and any property it gave up are
/// left to the schedule. Returns the time it took.
pub(crate) fn bmc_all(
    w: &Work,
    cleared: &[AtomicU64],
    events: &(dyn Fn(Event) + Sync),
    record: &mut dyn FnMut(usize, SymResult),
) -> std::time::Duration {
    let Some(first) = (0..w.idx.len()).find(|&i| !w.flags[i].load(Ordering::Relaxed)) else {
        return std::time::Duration::ZERO;
    };
    // BMC works on every open own property at once (the built-ins are not in the shared
    // circuit); the first is named last (a display shows the latest).
    for i in (first..w.idx.len()).rev() {
        if !w.flags[i].load(Ordering::Relaxed) && w.idx[i].1 != PropKind::Builtin {
            events(Event::Working {
                engine: Engine::Bmc.as_str(),
                index: i,
                budget: None,
            });
        }
    }
    let start = Instant::now();
    let lim = Limits {
        deadline: w.deadline,
        attempt_deadline: None,
        max_depth: w.max_depth,
        stop: Some(Arc::new(AtomicBool::new(false))),
    };
    let open = |i: usize| !w.flags[i].load(Ordering::Relaxed) && !w.stop.load(Ordering::Relaxed);
    let end = bmc_shared(
        w.program,
        w.blasted,
        w.reductions,
        w.idx,
        &lim,
        &open,
        &|i| Some(Arc::clone(&w.flags[i])),
        &|i, k| {
            cleared[i].fetch_max(k as u64, Ordering::Relaxed);
        },
        record,
    );
    if let ManyEnd::Bounded(k) = end {
        // The outputs still open when the bound stopped the unrolling cleared every frame.
        for (i, c) in cleared.iter().enumerate() {
            if open(i) && c.load(Ordering::Relaxed) == k as u64 {
                let (pi, kind) = w.idx[i];
                let result = PropResult {
                    verdict: Verdict::Bounded,
                    depth: k as u64,
                    ..PropResult::unknown(&w.blasted.props[pi].name, kind)
                };
                record(
                    i,
                    SymResult {
                        result,
                        invariant: None,
                        time: start.elapsed(),
                        reason: None,
                    },
                );
            }
        }
    }
    start.elapsed()
}
