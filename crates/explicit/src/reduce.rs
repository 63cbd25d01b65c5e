//! Input abstraction: from each state, step one input vector per combination of the inputs
//! the tick can read from that state ([`statecheck_ir::assume::InputReads`]), not every vector.
//!
//! Vectors that agree on the inputs a tick reads from a state give the same successor, the
//! same run-time error and the same coverage (see the IR module for why), and, since the
//! inputs read by the per-transition properties and assumes count as read in every state, the
//! same verdicts too. The vectors of a tick are grouped by their values on the read inputs;
//! each group is stepped once, through its first vector in enumeration order, and counts as
//! as many transitions as it has vectors. Taking the first keeps every choice the search
//! makes the same as without the reduction: the first transition (in enumeration order) that
//! reaches a successor or decides a property is always the first vector of its group.
//!
//! Groups depend only on the set of read inputs, so they are computed once per set and kept
//! (a bounded cache shared by the workers).

use statecheck_ir::assume::{InputReads, InputSpace};
use statecheck_ir::{ExprId, Program};
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, RwLock};
use std::time::Instant;

/// Most sets of read inputs whose groups are kept.
const MAX_CACHED: usize = 4096;

/// Most groups of an unlisted input space (beyond, that state is expanded without reduction).
const MAX_GROUPS: u128 = 1 << 16;

/// The groups of one set of read inputs.
pub(crate) struct Groups {
    /// Position (in the enumeration) of each group's first vector, increasing.
    pub first: Vec<u32>,
    /// Number of vectors of each group.
    pub size: Vec<u64>,
    /// The first vectors, flat (`slots.len()` values each).
    pub vectors: Vec<i64>,
}

/// The input abstraction of one run.
pub(crate) struct Reducer {
    /// Inputs read in every state: by the per-transition properties and assumes.
    extra: Vec<ExprId>,
    cache: RwLock<HashMap<Vec<u64>, Arc<Groups>>>,
    /// Whether walking pays.
    pub cost: Cost,
}

impl Reducer {
    /// The reducer of a run whose per-transition checks (properties and assumes evaluated on
    /// every transition) read `extra`.
    pub fn new(extra: Vec<ExprId>) -> Reducer {
        Reducer {
            extra,
            cache: RwLock::new(HashMap::new()),
            cost: Cost::default(),
        }
    }

    /// A walker for one worker.
    pub fn walker<'p>(&self, program: &'p Program) -> Walker<'p> {
        let reads = InputReads::new(program, &self.extra);
        let words = reads.words();
        Walker {
            reads,
            mask: vec![0; words],
            full: (0..words)
                .map(|i| {
                    let bits = program.inputs.len().saturating_sub(i * 64).min(64);
                    if bits == 64 {
                        u64::MAX
                    } else {
                        (1u64 << bits) - 1
                    }
                })
                .collect(),
            local: HashMap::new(),
        }
    }

    /// The groups of the vectors of a tick from `state` (persistent slots), or `None` when the
    /// tick may read every input (or there would be too many groups to list).
    pub fn groups(&self, w: &mut Walker, space: &InputSpace, state: &[i64]) -> Option<Arc<Groups>> {
        w.reads.from_state(state, &mut w.mask);
        if w.mask == w.full {
            return None;
        }
        if let Some(g) = w.local.get(&w.mask) {
            return Some(Arc::clone(g));
        }
        let cached = self.cache.read().ok()?.get(&w.mask).map(Arc::clone);
        let g = match cached {
            Some(g) => g,
            None => Arc::new(group(space, &w.mask)?),
        };
        if w.local.len() < MAX_CACHED {
            w.local.insert(w.mask.clone(), Arc::clone(&g));
        }
        if let Ok(mut c) = self.cache.write() {
            if c.len() < MAX_CACHED && !c.contains_key(&w.mask) {
                c.insert(w.mask.clone(), Arc::clone(&g));
            }
        }
        Some(g)
    }
}

/// Scratch space of one worker.
pub(crate) struct Walker<'p> {
    reads: InputReads<'p>,
    mask: Vec<u64>,
    full: Vec<u64>,
    /// The groups this worker used, without the shared cache's lock.
    local: HashMap<Vec<u64>, Arc<Groups>>,
}

fn bit(mask: &[u64], i: usize) -> bool {
    mask[i / 64] >> (i % 64) & 1 == 1
}

/// Group the vectors of `space` by their values on the inputs of `mask`.
fn group(space: &InputSpace, mask: &[u64]) -> Option<Groups> {
    let n = space.slots.len();
    let mut g = Groups {
        first: Vec::new(),
        size: Vec::new(),
        vectors: Vec::new(),
    };
    match space.listed() {
        Some((flat, count)) => {
            let mut seen: HashMap<Vec<i64>, usize> = HashMap::new();
            let mut key = Vec::with_capacity(n);
            for idx in 0..count {
                let v = &flat[idx * n..idx * n + n];
                key.clear();
                key.extend((0..n).filter(|&k| bit(mask, k)).map(|k| v[k]));
                match seen.get(&key) {
                    Some(&at) => g.size[at] += 1,
                    None => {
                        seen.insert(key.clone(), g.first.len());
                        g.first.push(u32::try_from(idx).ok()?);
                        g.size.push(1);
                        g.vectors.extend_from_slice(v);
                    }
                }
            }
        }
        None => {
            // The raw mixed-radix space (first input fastest): the group of a combination of
            // the read inputs starts with the other inputs at their lowest, and the read
            // inputs varied in enumeration order give increasing positions.
            let sizes: Vec<u128> = (0..n)
                .map(|k| {
                    let (lo, hi) = space.bounds(k);
                    (hi as i128 - lo as i128 + 1).max(1) as u128
                })
                .collect();
            let (mut groups, mut other) = (1u128, 1u128);
            for (k, s) in sizes.iter().enumerate() {
                if bit(mask, k) {
                    groups = groups.saturating_mul(*s);
                } else {
                    other = other.saturating_mul(*s);
                }
            }
            if groups > MAX_GROUPS {
                return None;
            }
            let mut v = vec![0i64; n];
            space.first(&mut v);
            for _ in 0..groups {
                let mut idx = 0u128;
                let mut radix = 1u128;
                for k in 0..n {
                    idx += (v[k] - space.bounds(k).0) as u128 * radix;
                    radix = radix.saturating_mul(sizes[k]);
                }
                g.first.push(u32::try_from(idx).ok()?);
                g.size.push(u64::try_from(other).ok()?);
                g.vectors.extend_from_slice(&v);
                // Advance the read inputs only.
                for k in (0..n).filter(|&k| bit(mask, k)) {
                    if v[k] < space.bounds(k).1 {
                        v[k] += 1;
                        break;
                    }
                    v[k] = space.bounds(k).0;
                }
            }
        }
    }
    Some(g)
}

/// Whether the input abstraction pays, measured as the search goes: a walk costs about as much
/// as a tick of the interpreter, far more than one of native code, so it is worth doing only
/// where it saves more ticks than it costs. Which states are walked changes only how many ticks
/// are run, never the states, verdicts or counterexamples (each group's first vector is
/// stepped either way), so the timing-based choice keeps the results deterministic.
#[derive(Default)]
pub(crate) struct Cost {
    walk_ns: AtomicU64,
    walks: AtomicU64,
    saved: AtomicU64,
    tick_ns: AtomicU64,
    ticks: AtomicU64,
    probes: AtomicU64,
}

/// Walks before the first decision.
const WARM_UP: u64 = 256;

/// While the walks do not pay, one chunk in this many still walks (to notice a change).
const PROBE: u64 = 32;

impl Cost {
    /// Should the next chunk walk its states?
    pub fn worth(&self) -> bool {
        let walks = self.walks.load(Relaxed);
        if walks < WARM_UP {
            return true;
        }
        let per_tick = self.tick_ns.load(Relaxed) as f64 / self.ticks.load(Relaxed).max(1) as f64;
        let per_walk = self.walk_ns.load(Relaxed) as f64 / walks as f64;
        let saved = self.saved.load(Relaxed) as f64 / walks as f64;
        saved * per_tick > per_walk || self.probes.fetch_add(1, Relaxed).is_multiple_of(PROBE)
    }

    /// Add a chunk's tally.
    pub fn record(&self, t: &Tally) {
        self.walk_ns.fetch_add(t.walk_ns, Relaxed);
        self.walks.fetch_add(t.walks, Relaxed);
        self.saved.fetch_add(t.saved, Relaxed);
        self.tick_ns.fetch_add(t.tick_ns, Relaxed);
        self.ticks.fetch_add(t.ticks, Relaxed);
    }
}

/// The time one chunk spent walking and stepping.
pub(crate) struct Tally {
    last: Instant,
    walk_ns: u64,
    walks: u64,
    saved: u64,
    tick_ns: u64,
    ticks: u64,
}

impl Tally {
    /// A tally starting now.
    pub fn new() -> Tally {
        Tally {
            last: Instant::now(),
            walk_ns: 0,
            walks: 0,
            saved: 0,
            tick_ns: 0,
            ticks: 0,
        }
    }

    fn lap(&mut self) -> u64 {
        let now = Instant::now();
        let ns = now.duration_since(self.last).as_nanos() as u64;
        self.last = now;
        ns
    }

    /// Start timing (what came before is not counted).
    pub fn begin(&mut self) {
        self.last = Instant::now();
    }

    /// A walk ended, sparing `saved` ticks.
    pub fn walked(&mut self, saved: u64) {
        self.walk_ns += self.lap();
        self.walks += 1;
        self.saved += saved;
    }

    /// `n` ticks ended.
    pub fn stepped(&mut self, n: u64) {
        self.tick_ns += self.lap();
        self.ticks += n;
    }
}
