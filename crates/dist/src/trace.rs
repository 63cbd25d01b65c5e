//! Counterexamples rebuilt across workers, and the results. Each stored state knows the
//! transition that found it (source worker, source index, input); from the source of a
//! deciding transition, the worker holding the current state tells every worker its parent
//! link, one exchange per tick, until the initial state. The inputs read backwards are a
//! shortest counterexample (the links follow breadth-first layers).

use crate::comm::{msg_bytes, Channel, Msg};
use crate::search::{End, Find};
use crate::store::{Store, ROOT};
use crate::{DistStats, Shared};
use statecheck_explicit::props::PropKind;
use statecheck_explicit::{PropResult, Verdict};
use statecheck_ir::assume::InputSpace;
use statecheck_ir::{Machine, RuntimeError};
use timely::worker::Worker;

/// Send `payload` to every worker (itself included); every worker's payload of this round.
pub(crate) fn to_all(
    worker: &mut Worker,
    ctrl: &mut Channel,
    payload: Vec<u64>,
    dist: &mut DistStats,
) -> Vec<Vec<u64>> {
    let peers = worker.peers();
    let me = worker.index();
    for t in 0..peers {
        if t != me {
            ctrl.send((t as u64, payload.clone(), Vec::new()));
        }
    }
    ctrl.send((me as u64, payload, Vec::new()));
    let inbox: Vec<Msg> = ctrl.finish_round(worker);
    dist.rounds += 1;
    // Everyone's payload went to the peers - 1 others.
    dist.control_bytes += inbox.iter().map(msg_bytes).sum::<u64>() * (peers as u64 - 1);
    inbox.into_iter().map(|m| m.1).collect()
}

/// A walk back: the inputs so far (last tick first), and the state (worker, index) reached.
type Walk = (Vec<u32>, Option<(u32, u32)>);

/// For each property: the input positions of the counterexample from the initial state, when
/// found. Every worker takes part (the same number of rounds) and gets the same answer.
pub(crate) fn walk_back(
    worker: &mut Worker,
    ctrl: &mut Channel,
    store: &Store,
    found: &[Option<Find>],
    dist: &mut DistStats,
) -> Vec<Option<Vec<u32>>> {
    let me = worker.index() as u32;
    let mut walks: Vec<Option<Walk>> = found
        .iter()
        .map(|f| f.map(|f| (vec![f.input], Some((f.worker, f.index)))))
        .collect();
    while walks.iter().flatten().any(|(_, at)| at.is_some()) {
        let mut payload = Vec::new();
        for (prop, w) in walks.iter().enumerate() {
            if let Some((_, Some((worker_at, index)))) = w {
                if *worker_at == me {
                    // A link missing would be a bug; it ends the walk (the trace then does
                    // not replay, which the caller's replay reports).
                    let [pw, pi, input] = store.parent(*index as usize).unwrap_or([ROOT; 3]);
                    payload.extend([prop as u64, u64::from(pw), u64::from(pi), u64::from(input)]);
                }
            }
        }
        let all = to_all(worker, ctrl, payload, dist);
        let mut moved = false;
        for v in &all {
            for c in v.chunks_exact(4) {
                let Some(Some((inputs, at))) = walks.get_mut(c[0] as usize) else {
                    continue;
                };
                moved = true;
                if c[1] == u64::from(ROOT) {
                    *at = None;
                } else {
                    inputs.push(c[3] as u32);
                    *at = Some((c[1] as u32, c[2] as u32));
                }
            }
        }
        if !moved {
            // Nobody holds a state being walked to: a bug; stop rather than loop.
            for (_, at) in walks.iter_mut().flatten() {
                *at = None;
            }
        }
    }
    walks
        .into_iter()
        .map(|w| {
            w.map(|(mut inputs, _)| {
                inputs.reverse();
                inputs
            })
        })
        .collect()
}

/// The run-time error of the last tick of `trace`, replayed from the initial state.
fn last_error(sh: &Shared, trace: &[Vec<i64>]) -> Option<RuntimeError> {
    let p = &sh.program;
    let mut m = Machine::new(p);
    let mut state = m.state()[..p.n_state].to_vec();
    for (k, v) in trace.iter().enumerate() {
        m.load(&state, v);
        match m.step() {
            Err(e) => return (k + 1 == trace.len()).then_some(e),
            Ok(()) => state.copy_from_slice(&m.state()[..p.n_state]),
        }
    }
    None
}

/// The result of every checked property.
pub(crate) fn results(
    sh: &Shared,
    space: &InputSpace,
    found: &[Option<Find>],
    traces: Vec<Option<Vec<u32>>>,
    end: &End,
    depth: u64,
) -> Vec<PropResult> {
    sh.specs
        .iter()
        .zip(found)
        .zip(traces)
        .map(|((spec, f), tr)| {
            let reach = spec.kind == PropKind::Reachable;
            let mut r = PropResult::unknown(&spec.name, spec.kind);
            match f {
                Some(f) => {
                    r.verdict = if reach {
                        Verdict::Reachable
                    } else {
                        Verdict::Violated
                    };
                    r.depth = f.layer + 1;
                    let trace: Option<Vec<Vec<i64>>> =
                        tr.map(|t| t.into_iter().map(|i| space.vector(u128::from(i))).collect());
                    if spec.builtin().is_some() {
                        r.error = trace.as_deref().and_then(|t| last_error(sh, t));
                    }
                    r.counterexample = trace;
                }
                None => {
                    r.verdict = match end {
                        End::Complete if reach => Verdict::Unreachable,
                        End::Complete => Verdict::Proved,
                        End::Depth => Verdict::Bounded,
                        End::AllDecided | End::Limit(_) => Verdict::Unknown,
                    };
                    r.depth = depth;
                }
            }
            r
        })
        .collect()
}
