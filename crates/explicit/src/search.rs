//! Level-synchronous breadth-first search.
//!
//! Each layer is processed in blocks of a fixed size: the block's states are expanded in
//! parallel chunks (rayon), then every shard of the visited set inserts its successors in
//! parallel, in generation order, and checks the per-state properties on the states that are
//! new (the first violating one of a shard in generation order; the earliest over all shards
//! wins). Block, chunk and shard sizes depend only on the model, never on the thread count, so
//! the states found, their order, and every result are the same on any number of threads.

use crate::bitstate::{BitSet, Bitstate, BitstateStats};
use crate::collapse::Collapsed;
use crate::expand::{Cand, ChunkOut, Expander, Found, StateCheck, StateFind};
use crate::pack::Key;
use crate::table::{insert_retain, HashedSet, Shard, Visited, SHARDS};
use crate::{Collapse, Limit, Progress};
use rayon::prelude::*;
use statecheck_ir::Machine;
use std::time::{Duration, Instant};

/// Limits of one search.
#[derive(Clone, Debug, Default)]
pub(crate) struct Limits {
    pub depth: Option<u64>,
    pub max_memory: Option<u64>,
    pub max_states: Option<u64>,
    pub timeout: Option<Duration>,
    /// Raised by another thread: end with [`Limit::Stopped`] after the current block.
    pub stop: Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    /// When to store states collapse-compressed ([`crate::collapse`]; only states of more
    /// than two words are).
    pub collapse: Collapse,
    /// Bitstate hashing instead of an exact set ([`crate::bitstate`]); collapse compression is
    /// then off.
    pub bitstate: Option<Bitstate>,
}

/// Why a search stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum End {
    /// No new states: everything reachable was explored.
    Complete,
    /// The depth bound (or the tracking depth) was reached with states left to expand.
    Depth,
    /// Every property was decided; the rest of the state space was not explored.
    AllDecided,
    /// A resource limit.
    Limit(Limit),
}

/// A layer kept for counterexample reconstruction: states and (parent position, input index).
pub(crate) type Layer<K> = (Vec<K>, Vec<(u32, u32)>);

/// The outcome of one search.
pub(crate) struct Searched<K> {
    pub end: End,
    pub states: u64,
    pub transitions: u64,
    /// The deepest layer reached (ticks from the initial state).
    pub depth: u64,
    /// Per property: the layer of the source state and the deciding transition.
    pub found: Vec<Option<(u64, Found<K>)>>,
    /// Coverage items hit at least once (when enabled).
    pub covered: Option<Vec<bool>>,
    /// Bytes of the visited set at the end.
    pub table_bytes: u64,
    /// Largest estimate of the memory held (visited set, layers, successor buffers).
    pub peak_bytes: u64,
    /// Under collapse compression: the distinct values of each leaf.
    pub collapse_leaves: Option<Vec<u64>>,
    /// Under collapse compression: the states stored when it began.
    pub collapse_from: Option<u64>,
    /// With tracking: every layer.
    pub layers: Vec<Layer<K>>,
    /// Under bitstate hashing: its statistics.
    pub bitstate: Option<BitstateStats>,
    pub elapsed: Duration,
}

/// What inserting one block into one shard produced: the new states (per bucket, in
/// generation order) and the per-state properties they decide.
type Inserted<K> = (Vec<Vec<Cand<K>>>, Vec<StateFind>);

/// Insert one bucket's items into `shard` by `key`, in order, keeping the items whose key was
/// new and checking the per-state properties on their candidates (with a checker).
#[inline(always)]
fn retain_new<K: Key, S: Key, T>(
    shard: &mut impl HashedSet<S>,
    bucket: &mut Vec<T>,
    key: impl Fn(&T) -> &S,
    cand: impl Fn(&T) -> &Cand<K>,
    checker: Option<&mut StateCheck<'_, '_>>,
) {
    match checker {
        Some(ch) => insert_retain(shard, bucket, key, |t| ch.check(cand(t))),
        None => insert_retain(shard, bucket, key, |_| {}),
    }
}

/// Insert a block's successors of one shard (of the exact set or of a bitstate array), in
/// generation order; keep the new ones and check the per-state properties on them (with a
/// checker). Called once per shard and block, so kept out of line: profiles then show the
/// insertion phase on its own.
#[inline(never)]
fn insert_shard<K: Key>(
    shard: &mut impl HashedSet<K>,
    mut fresh: Vec<Vec<Cand<K>>>,
    mut checker: Option<&mut StateCheck<'_, '_>>,
) -> Inserted<K> {
    for bucket in &mut fresh {
        retain_new(shard, bucket, |c| &c.key, |c| c, checker.as_deref_mut());
    }
    let found = checker.map(|ch| std::mem::take(&mut ch.found));
    (fresh, found.unwrap_or_default())
}

/// [`insert_shard`] for a collapse-compressed set: the candidates' roots (in the same order)
/// are inserted, the candidates whose root was new are kept.
#[inline(never)]
fn insert_shard_collapsed<K: Key>(
    shard: &mut Shard<u64>,
    fresh: Vec<Vec<Cand<K>>>,
    roots: Vec<Vec<u64>>,
    mut checker: Option<&mut StateCheck<'_, '_>>,
) -> Inserted<K> {
    let mut kept = Vec::with_capacity(fresh.len());
    for (bucket, roots) in fresh.into_iter().zip(roots) {
        let mut pairs: Vec<(u64, Cand<K>)> = roots.into_iter().zip(bucket).collect();
        retain_new(
            shard,
            &mut pairs,
            |p| &p.0,
            |p| &p.1,
            checker.as_deref_mut(),
        );
        kept.push(pairs.into_iter().map(|(_, c)| c).collect());
    }
    let found = checker.map(|ch| std::mem::take(&mut ch.found));
    (kept, found.unwrap_or_default())
}

/// Insert a block's successors into every shard in parallel ([`insert_shard`]).
fn insert_block<K: Key, S: HashedSet<K> + Send>(
    shards: &mut [S],
    checkers: &mut [StateCheck<'_, '_>],
    per_shard: Vec<Vec<Vec<Cand<K>>>>,
    pend: &[bool],
    check_states: bool,
) -> Vec<Inserted<K>> {
    shards
        .par_iter_mut()
        .zip(checkers.par_iter_mut())
        .zip(per_shard)
        .map(|((shard, checker), fresh)| {
            checker.reset(pend);
            insert_shard(shard, fresh, check_states.then_some(checker))
        })
        .collect()
}

/// The visited set of a search: plain keys, collapse-compressed, or a bit array.
enum Store<K> {
    Plain(Visited<K>),
    Collapsed(Box<Collapsed>),
    Bits(Box<BitSet>),
}

impl<K: Key> Store<K> {
    fn bytes(&self) -> usize {
        match self {
            Store::Plain(v) => v.bytes(),
            Store::Collapsed(c) => c.bytes(),
            Store::Bits(b) => b.bytes(),
        }
    }
}

/// Run a search. With `track = Some(d)`, keep every layer with parent links and stop once
/// layer `d` is built (for counterexample reconstruction).
pub(crate) fn search<K: Key>(
    exp: &Expander,
    limits: Limits,
    track: Option<u64>,
    progress: Option<&(dyn Fn(&Progress) + Sync)>,
) -> Searched<K> {
    let start = Instant::now();
    let n_props = exp.specs.len();
    let mut pending = vec![true; n_props];
    let mut found: Vec<Option<(u64, Found<K>)>> = (0..n_props).map(|_| None).collect();
    let mut covered = exp.coverage.then(|| vec![false; exp.program.covers.len()]);
    let mut words = vec![0u64; exp.packer.words];
    let m0 = Machine::new(exp.program);
    let init: K = match exp.sym {
        Some(c) => c.pack(exp.packer, m0.state(), &mut words),
        None => exp.packer.pack(m0.state(), &mut words),
    };
    let wide = exp.packer.words > 2;
    let mut collapse_from = None;
    let mut visited: Store<K> = if let Some(b) = limits.bitstate.filter(|_| track.is_none()) {
        let mut bits = BitSet::new(b);
        bits.insert(&init);
        Store::Bits(Box::new(bits))
    } else if limits.collapse == Collapse::On && wide {
        let mut c = Collapsed::new(exp.packer.words);
        // An empty set has room for one state.
        let _ = c.insert(&init);
        collapse_from = Some(1);
        Store::Collapsed(Box::new(c))
    } else {
        let mut v = Visited::new();
        v.insert(&init);
        Store::Plain(v)
    };
    let mut frontier: Vec<K> = vec![init];
    let mut frontier_parents: Vec<(u32, u32)> = Vec::new();
    let mut layers: Vec<Layer<K>> = Vec::new();
    let mut layers_bytes = 0u64;
    let mut states = 1u64;
    let mut transitions = 0u64;
    let mut depth = 0u64;
    let mut peak = 0u64;
    let branching = u64::try_from(exp.space.per_tick())
        .unwrap_or(u64::MAX)
        .max(1);
    let chunk = (4096 / branching).clamp(1, 512) as usize;
    let block = chunk * 256;
    // Bytes per key outside a table: the key itself, plus the words of a boxed key.
    let key_bytes = (std::mem::size_of::<K>() + K::from_words(&words).heap_bytes()) as u64;
    let tracking = track.is_some();
    // One per-state checker per shard (a machine each), reset for every block.
    let mut checkers: Vec<StateCheck<'_, '_>> = (0..SHARDS)
        .map(|_| StateCheck::new(exp, &pending))
        .collect();
    let end = 'outer: loop {
        if limits.depth.is_some_and(|k| depth >= k) || track.is_some_and(|d| depth >= d) {
            break End::Depth;
        }
        let mut next: Vec<K> = Vec::new();
        let mut next_parents: Vec<(u32, u32)> = Vec::new();
        for (b, blk) in frontier.chunks(block).enumerate() {
            let base = b * block;
            let pend = &pending;
            let outs: Vec<ChunkOut<K>> = blk
                .par_chunks(chunk)
                .enumerate()
                .map(|(c, ch)| exp.chunk(ch, base + c * chunk, pend))
                .collect();
            let mut per_shard: Vec<Vec<Vec<Cand<K>>>> = (0..SHARDS)
                .map(|_| Vec::with_capacity(outs.len()))
                .collect();
            let mut cand_bytes = 0u64;
            for out in outs {
                transitions += out.transitions;
                for f in out.found {
                    if pending[f.prop] {
                        pending[f.prop] = false;
                        let i = f.prop;
                        found[i] = Some((depth, f));
                    }
                }
                if let (Some(cov), Some(counts)) = (covered.as_mut(), out.coverage) {
                    cov.iter_mut().zip(counts).for_each(|(c, n)| *c |= n > 0);
                }
                for (s, bucket) in out.buckets.into_iter().enumerate() {
                    cand_bytes += (bucket.capacity() * std::mem::size_of::<Cand<K>>()) as u64;
                    per_shard[s].push(bucket);
                }
            }
            let pend = &pending;
            let check_states = exp.checks_states(pend);
            let new: Vec<Inserted<K>> = match &mut visited {
                Store::Plain(v) => {
                    insert_block(&mut v.shards, &mut checkers, per_shard, pend, check_states)
                }
                Store::Collapsed(c) => {
                    let Ok(roots) = c.roots_of(&per_shard) else {
                        // More distinct halves than 2^32: memory would have run out first.
                        let held = c.bytes() as u64;
                        break 'outer End::Limit(Limit::Memory(limits.max_memory.unwrap_or(held)));
                    };
                    c.roots
                        .shards
                        .par_iter_mut()
                        .zip(checkers.par_iter_mut())
                        .zip(per_shard)
                        .zip(roots)
                        .map(|(((shard, checker), fresh), roots)| {
                            checker.reset(pend);
                            insert_shard_collapsed(
                                shard,
                                fresh,
                                roots,
                                check_states.then_some(checker),
                            )
                        })
                        .collect()
                }
                Store::Bits(b) => {
                    insert_block(&mut b.shards, &mut checkers, per_shard, pend, check_states)
                }
            };
            // Per-state findings: the first in generation order over all shards.
            let mut first: Vec<Option<(u32, u32)>> = vec![None; n_props];
            for (_, f) in &new {
                for &(i, parent, input) in f {
                    if first[i].is_none_or(|b| (parent, input) < b) {
                        first[i] = Some((parent, input));
                    }
                }
            }
            for (i, f) in first.into_iter().enumerate() {
                if let Some((parent, input)) = f.filter(|_| pending[i]) {
                    pending[i] = false;
                    found[i] = Some((
                        depth,
                        Found {
                            prop: i,
                            parent: frontier[parent as usize].clone(),
                            input,
                            error: None,
                        },
                    ));
                }
            }
            let n_new: usize = new.iter().flat_map(|(f, _)| f).map(Vec::len).sum();
            if let Store::Bits(b) = &mut visited {
                b.note_block(n_new as u64);
            }
            next.reserve(n_new);
            if tracking {
                next_parents.reserve(n_new);
            }
            for bucket in new.into_iter().flat_map(|(fresh, _)| fresh) {
                if tracking {
                    next_parents.extend(bucket.iter().map(|c| (c.parent, c.input)));
                }
                next.extend(bucket.into_iter().map(|c| c.key));
            }
            if let (Store::Plain(v), Collapse::Auto, true, Some(m)) =
                (&mut visited, limits.collapse, wide, limits.max_memory)
            {
                if v.bytes() as u64 > m / 5 * 2 {
                    let stored = v.len() as u64;
                    let Ok(c) = Collapsed::from_plain(exp.packer.words, std::mem::take(v)) else {
                        break 'outer End::Limit(Limit::Memory(m));
                    };
                    visited = Store::Collapsed(Box::new(c));
                    collapse_from = Some(stored);
                }
            }
            let table = visited.bytes() as u64;
            let held = table
                + layers_bytes
                + (frontier.capacity() + next.capacity()) as u64 * key_bytes
                + (frontier_parents.capacity() + next_parents.capacity()) as u64 * 8;
            peak = peak.max(held + cand_bytes);
            let total = states + next.len() as u64;
            let elapsed = start.elapsed();
            if let Some(f) = progress {
                f(&Progress {
                    depth,
                    states: total,
                    transitions,
                    frontier: frontier.len() as u64,
                    memory_bytes: held,
                    elapsed,
                });
            }
            let stopped = limits
                .stop
                .as_ref()
                .is_some_and(|s| s.load(std::sync::atomic::Ordering::Relaxed));
            let hit = if stopped {
                Some(Limit::Stopped)
            } else if limits.max_memory.is_some_and(|m| held > m) {
                limits.max_memory.map(Limit::Memory)
            } else if limits.max_states.is_some_and(|m| total > m) {
                limits.max_states.map(Limit::States)
            } else if limits.timeout.is_some_and(|t| elapsed > t) {
                limits.timeout.map(Limit::Time)
            } else {
                None
            };
            if let Some(l) = hit {
                states = total;
                break 'outer End::Limit(l);
            }
        }
        states += next.len() as u64;
        if next.is_empty() {
            break End::Complete;
        }
        if !tracking && pending.iter().all(|p| !p) {
            break End::AllDecided;
        }
        if tracking {
            layers_bytes +=
                frontier.capacity() as u64 * key_bytes + frontier_parents.capacity() as u64 * 8;
            layers.push((
                std::mem::take(&mut frontier),
                std::mem::take(&mut frontier_parents),
            ));
        }
        frontier = next;
        frontier_parents = next_parents;
        depth += 1;
    };
    if tracking {
        layers.push((frontier, frontier_parents));
    }
    Searched {
        end,
        states,
        transitions,
        depth,
        found,
        covered,
        table_bytes: visited.bytes() as u64,
        peak_bytes: peak,
        collapse_leaves: match &visited {
            Store::Collapsed(c) => Some(c.leaf_counts()),
            _ => None,
        },
        collapse_from,
        layers,
        bitstate: match &visited {
            Store::Bits(b) => Some(b.stats(states)),
            _ => None,
        },
        elapsed: start.elapsed(),
    }
}
