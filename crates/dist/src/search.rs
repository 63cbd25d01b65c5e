//! One worker's part of the search: expand the states it found in the last layer, send each
//! successor to its owner, store the new ones it owns; then the layer's figures and findings
//! go to every worker, so that all of them decide alike whether and how the search goes on.

use crate::comm::{msg_bytes, Channel, Msg};
use crate::expand::Expander;
use crate::store::{hash, owner, Store, ROOT};
use crate::{DistReport, DistStats, Shared};
use statecheck_explicit::pack::Packer;
use statecheck_explicit::{Limit, Stats};
use statecheck_ir::assume::InputSpace;
use statecheck_ir::Machine;
use std::sync::atomic::Ordering;
use timely::worker::Worker;

/// Flush a worker's buffer for one addressee at this many words.
const FLUSH_WORDS: usize = 1 << 14;

/// Check the limits every this many expanded states.
const CHECK_EVERY: usize = 256;

/// How the search ended (as the explicit engine's).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum End {
    Complete,
    Depth,
    AllDecided,
    Limit(Limit),
}

/// The first transition found deciding a property: the layer of its source, the source's
/// worker and index there, and the input's position.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Find {
    pub layer: u64,
    pub worker: u32,
    pub index: u32,
    pub input: u32,
}

/// A limit as a number in the layer's figures (0: none).
fn limit_code(l: &Limit) -> u64 {
    match l {
        Limit::Memory(_) => 1,
        Limit::Time(_) => 2,
        Limit::Stopped => 3,
        _ => 4,
    }
}

/// A worker's figures of one layer, as sent to every worker.
struct Figures {
    worker: u64,
    new: u64,
    transitions: u64,
    limit: u64,
    exchange: u64,
    stored: u64,
    bytes: u64,
    finds: Vec<(u64, u64, u64)>,
}

impl Figures {
    fn encode(&self) -> Vec<u64> {
        let mut v = vec![
            self.worker,
            self.new,
            self.transitions,
            self.limit,
            self.exchange,
            self.stored,
            self.bytes,
        ];
        for &(p, i, x) in &self.finds {
            v.extend([p, i, x]);
        }
        v
    }

    fn decode(v: &[u64]) -> Option<Figures> {
        let head = v.get(..7)?;
        let rest = &v[7..];
        Some(Figures {
            worker: head[0],
            new: head[1],
            transitions: head[2],
            limit: head[3],
            exchange: head[4],
            stored: head[5],
            bytes: head[6],
            finds: rest.chunks_exact(3).map(|c| (c[0], c[1], c[2])).collect(),
        })
    }
}

/// Run one worker; every worker returns the same report.
pub(crate) fn run(worker: &mut Worker, sh: &Shared) -> DistReport {
    let me = worker.index();
    let peers = worker.peers();
    let local = me % sh.per_process;
    let p = &sh.program;
    let opts = &sh.opts;
    let mut succ_ch = Channel::new(worker);
    let mut ctrl = Channel::new(worker);
    let packer = Packer::new(p);
    let mut space = InputSpace::new(p);
    space.solve_static(p);
    let mut stats = Stats {
        branching: space.count,
        branching_after_assumes: space.effective(),
        threads: peers,
        state_bits: packer.bits,
        backend: "interpreter",
        ..Stats::default()
    };
    let mut dist = DistStats {
        workers: peers,
        processes: peers / sh.per_process,
        ..DistStats::default()
    };
    let n_props = sh.specs.len();
    let branching = space.per_tick();
    let too_wide =
        branching > u128::from(u32::MAX) || (branching > opts.max_branching && !opts.force);
    if too_wide {
        stats.limit = Some(Limit::Branching {
            branching,
            max: if opts.force {
                u128::from(u32::MAX)
            } else {
                opts.max_branching
            },
        });
        let results = sh
            .specs
            .iter()
            .map(|s| statecheck_explicit::PropResult::unknown(&s.name, s.kind))
            .collect();
        return DistReport {
            report: statecheck_explicit::Report { results, stats },
            dist,
        };
    }
    let mut exp = Expander::new(p, &packer, &space, &sh.specs);
    let words = packer.words;
    let mut store = Store::new(words);
    let mut init = vec![0u64; words];
    packer.pack_words(Machine::new(p).state(), &mut init);
    let h = hash(&init);
    if owner(h, peers) == me {
        store.insert(&init, h, [ROOT; 3]);
    }
    let mut pending = vec![true; n_props];
    let mut found: Vec<Option<Find>> = vec![None; n_props];
    let (mut states, mut transitions, mut depth) = (1u64, 0u64, 0u64);
    let mut process_peak = vec![0u64; dist.processes];
    let mut lo = 0usize;
    // The successors this worker already sent in the layer: each is sent once (wide-branching
    // models reach the same few successors by many input vectors).
    let mut sent = Store::new(words);
    let meter = &sh.meter[local];
    let process_bytes = || {
        sh.meter
            .iter()
            .map(|m| m.load(Ordering::Relaxed))
            .sum::<u64>()
    };
    let end = loop {
        if opts.depth.is_some_and(|k| depth >= k) {
            break End::Depth;
        }
        let hi = store.len();
        let mut open = pending.clone();
        sent.clear();
        let mut finds: Vec<(u64, u64, u64)> = Vec::new();
        let mut bufs: Vec<(Vec<u64>, Vec<u32>)> = (0..peers).map(|_| Default::default()).collect();
        let mut layer_transitions = 0u64;
        let mut exchange = 0u64;
        let mut limit: Option<Limit> = None;
        for i in lo..hi {
            if (i - lo).is_multiple_of(CHECK_EVERY) {
                let held = store.bytes() + sent.bytes() + buf_bytes(&bufs) + succ_ch.inbox_bytes();
                meter.store(held, Ordering::Relaxed);
                limit = local_limit(sh, process_bytes());
                if limit.is_some() {
                    break;
                }
            }
            let src = store.state(i);
            let pos = i as u32;
            layer_transitions += exp.expand(
                src,
                &mut open,
                &mut |prop, input| finds.push((prop as u64, u64::from(pos), u64::from(input))),
                &mut |s, input| {
                    let h = hash(s);
                    // (A full cache sends everything rather than lose a state.)
                    if !sent.full() && !sent.insert(s, h, [0; 3]) {
                        return;
                    }
                    let b = &mut bufs[owner(h, peers)];
                    b.0.extend_from_slice(s);
                    b.1.extend([me as u32, pos, input]);
                },
            );
            for (t, b) in bufs.iter_mut().enumerate() {
                if b.0.len() >= FLUSH_WORDS {
                    let m: Msg = (t as u64, std::mem::take(&mut b.0), std::mem::take(&mut b.1));
                    if t != me {
                        exchange += msg_bytes(&m);
                    }
                    succ_ch.send(m);
                }
            }
            if (i - lo) % CHECK_EVERY == CHECK_EVERY - 1 {
                succ_ch.flush(worker);
            }
        }
        for (t, b) in bufs.into_iter().enumerate() {
            if !b.0.is_empty() {
                let m: Msg = (t as u64, b.0, b.1);
                if t != me {
                    exchange += msg_bytes(&m);
                }
                succ_ch.send(m);
            }
        }
        let mut inbox = succ_ch.finish_round(worker);
        dist.rounds += 1;
        // In the senders' order, so that which parent a state keeps does not depend on timing.
        inbox.sort_by_key(|m| m.2.first().copied());
        for (ws, meta) in inbox.iter().map(|m| (&m.1, &m.2)) {
            for (s, par) in ws.chunks_exact(words).zip(meta.chunks_exact(3)) {
                store.insert(s, hash(s), [par[0], par[1], par[2]]);
            }
        }
        drop(inbox);
        if store.full() && limit.is_none() {
            limit = opts.max_memory.map(Limit::Memory).or(Some(Limit::Stopped));
        }
        let held = store.bytes() + sent.bytes();
        meter.store(held, Ordering::Relaxed);
        if limit.is_none() {
            limit = local_limit(sh, process_bytes());
        }
        let figures = Figures {
            worker: me as u64,
            new: (store.len() - hi) as u64,
            transitions: layer_transitions,
            limit: limit.as_ref().map_or(0, limit_code),
            exchange,
            stored: store.len() as u64,
            bytes: held,
            finds,
        };
        let all = exchange_figures(worker, &mut ctrl, &figures, &mut dist);
        let mut new = 0u64;
        let mut first_limit = 0u64;
        let mut per_process = vec![0u64; dist.processes];
        dist.worker_states = all.iter().map(|f| f.stored).collect();
        for f in &all {
            new += f.new;
            transitions += f.transitions;
            dist.exchange_bytes += f.exchange;
            if first_limit == 0 {
                first_limit = f.limit;
            }
            if let Some(b) = per_process.get_mut(f.worker as usize / sh.per_process) {
                *b += f.bytes;
            }
            for &(prop, index, input) in &f.finds {
                let prop = prop as usize;
                if pending.get(prop) == Some(&true) {
                    pending[prop] = false;
                    found[prop] = Some(Find {
                        layer: depth,
                        worker: f.worker as u32,
                        index: index as u32,
                        input: input as u32,
                    });
                }
            }
        }
        stats.table_bytes = per_process.iter().sum();
        for (pk, b) in process_peak.iter_mut().zip(&per_process) {
            *pk = (*pk).max(*b);
        }
        states += new;
        let hit = match first_limit {
            0 if opts.max_states.is_some_and(|m| states > m) => opts.max_states.map(Limit::States),
            0 => None,
            1 => Some(Limit::Memory(opts.max_memory.unwrap_or(0))),
            2 => Some(Limit::Time(opts.timeout.unwrap_or_default())),
            _ => Some(Limit::Stopped),
        };
        if let Some(l) = hit {
            break End::Limit(l);
        }
        if new == 0 {
            break End::Complete;
        }
        if pending.iter().all(|p| !p) {
            break End::AllDecided;
        }
        lo = hi;
        depth += 1;
    };
    stats.time = sh.start.elapsed();
    stats.states = states;
    stats.transitions = transitions;
    stats.depth = depth;
    stats.peak_memory_bytes = process_peak.iter().copied().max().unwrap_or(0);
    dist.process_peak_bytes = process_peak;
    stats.complete = end == End::Complete;
    stats.all_decided = end == End::AllDecided;
    if let End::Limit(l) = &end {
        stats.limit = Some(l.clone());
    }
    let cex_start = std::time::Instant::now();
    let traces = crate::trace::walk_back(worker, &mut ctrl, &store, &found, &mut dist);
    stats.cex_time = cex_start.elapsed();
    let results = crate::trace::results(sh, &space, &found, traces, &end, depth);
    DistReport {
        report: statecheck_explicit::Report { results, stats },
        dist,
    }
}

/// Bytes of the outgoing buffers.
fn buf_bytes(bufs: &[(Vec<u64>, Vec<u32>)]) -> u64 {
    bufs.iter()
        .map(|b| (b.0.capacity() * 8 + b.1.capacity() * 4) as u64)
        .sum()
}

/// A limit this process hit: the stop flag, the time, its memory (`held` bytes).
fn local_limit(sh: &Shared, held: u64) -> Option<Limit> {
    let o = &sh.opts;
    if o.stop.as_ref().is_some_and(|s| s.load(Ordering::Relaxed)) {
        Some(Limit::Stopped)
    } else if o.max_memory.is_some_and(|m| held > m) {
        o.max_memory.map(Limit::Memory)
    } else if o.timeout.is_some_and(|t| sh.start.elapsed() > t) {
        o.timeout.map(Limit::Time)
    } else {
        None
    }
}

/// Send this worker's figures to every worker; every worker's figures, in worker order.
fn exchange_figures(
    worker: &mut Worker,
    ctrl: &mut Channel,
    mine: &Figures,
    dist: &mut DistStats,
) -> Vec<Figures> {
    let payload = mine.encode();
    let inbox = crate::trace::to_all(worker, ctrl, payload, dist);
    let mut all: Vec<Figures> = inbox.iter().filter_map(|v| Figures::decode(v)).collect();
    all.sort_by_key(|f| f.worker);
    all
}
