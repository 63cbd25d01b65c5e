//! Expanding a chunk of states: every input vector that satisfies the `assume`s, one tick of
//! the IR each, properties checked on every transition, successors packed and bucketed by
//! shard.

use crate::inputs::InputSpace;
use crate::pack::{Key, Packer};
use crate::props::{Check, Spec};
use crate::table::{shard_of, SHARDS};
use statecheck_ir::{ExprId, Machine, Program, RuntimeError};

/// A successor found while expanding: its key and hash, and how it was reached.
pub(crate) struct Cand<K> {
    pub key: K,
    pub hash: u64,
    /// Position of the parent in its layer.
    pub parent: u32,
    /// Index of the input vector.
    pub input: u32,
}

/// A transition that decides a property (a violation, a witness, a run-time error).
pub(crate) struct Found<K> {
    /// Index into the checked properties.
    pub prop: usize,
    /// The source state.
    pub parent: K,
    /// Index of the input vector.
    pub input: u32,
    /// The run-time error, for built-in properties.
    pub error: Option<RuntimeError>,
}

/// What expanding one chunk produced.
pub(crate) struct ChunkOut<K> {
    /// Successors per shard, in the order they were generated.
    pub buckets: Vec<Vec<Cand<K>>>,
    /// The first deciding transition of each still-pending property in this chunk.
    pub found: Vec<Found<K>>,
    /// Transitions taken (input vectors that satisfied the assumes).
    pub transitions: u64,
    /// Coverage counters, when enabled.
    pub coverage: Option<Vec<u64>>,
}

/// Everything a worker needs to expand states; shared read-only by all threads.
pub(crate) struct Expander<'a> {
    pub program: &'a Program,
    pub packer: &'a Packer,
    pub space: &'a InputSpace,
    pub specs: &'a [Spec],
    pub coverage: bool,
}

impl Expander<'_> {
    /// Expand `states`, the first of which sits at position `first_pos` of its layer;
    /// `pending[i]` tells whether property `i` is still undecided.
    pub fn chunk<K: Key>(&self, states: &[K], first_pos: usize, pending: &[bool]) -> ChunkOut<K> {
        let p = self.program;
        let mut m = Machine::new(p);
        if self.coverage {
            m.enable_coverage();
        }
        let mut state = vec![0i64; p.n_state];
        let mut words = vec![0u64; self.packer.words];
        let mut inp = vec![0i64; self.space.slots.len()];
        let mut open: Vec<bool> = pending.to_vec();
        let mut out = ChunkOut {
            buckets: (0..SHARDS).map(|_| Vec::new()).collect(),
            found: Vec::new(),
            transitions: 0,
            coverage: None,
        };
        let count = self.space.count as u64;
        for (j, key) in states.iter().enumerate() {
            let pos = first_pos + j;
            self.packer.unpack(key, &mut words, &mut state);
            match &self.space.allowed {
                Some(allowed) => {
                    for (idx, v) in allowed {
                        m.load_state(&state);
                        for (k, &s) in self.space.slots.iter().enumerate() {
                            m.set(s, v[k]);
                        }
                        self.transition(&mut m, key, pos, *idx, &mut open, &mut words, &mut out);
                    }
                }
                None => {
                    self.space.first(&mut inp);
                    for idx in 0..count {
                        m.load_state(&state);
                        for (k, &s) in self.space.slots.iter().enumerate() {
                            m.set(s, inp[k]);
                        }
                        self.space.advance(&mut inp);
                        if p.assumes.iter().all(|a| holds(&mut m, *a)) {
                            self.transition(
                                &mut m, key, pos, idx as u32, &mut open, &mut words, &mut out,
                            );
                        }
                    }
                }
            }
        }
        out.coverage = m.coverage().map(<[u64]>::to_vec);
        out
    }

    /// One tick from the loaded state with the inputs set: record what it decides and the
    /// successor.
    #[allow(clippy::too_many_arguments)] // reason: the per-chunk scratch buffers of the hot loop
    fn transition<K: Key>(
        &self,
        m: &mut Machine,
        key: &K,
        pos: usize,
        idx: u32,
        open: &mut [bool],
        words: &mut [u64],
        out: &mut ChunkOut<K>,
    ) {
        out.transitions += 1;
        match m.step() {
            Err(e) => {
                let name = e.kind.builtin_property();
                let hit = self
                    .specs
                    .iter()
                    .position(|s| matches!(s.check, Check::Builtin(b) if b == name));
                if let Some(i) = hit.filter(|i| open[*i]) {
                    open[i] = false;
                    out.found.push(Found {
                        prop: i,
                        parent: key.clone(),
                        input: idx,
                        error: Some(e),
                    });
                }
            }
            Ok(()) => {
                for (i, spec) in self.specs.iter().enumerate() {
                    if open[i] && decides(m, spec.check) {
                        open[i] = false;
                        out.found.push(Found {
                            prop: i,
                            parent: key.clone(),
                            input: idx,
                            error: None,
                        });
                    }
                }
                let succ: K = self.packer.pack(m.state(), words);
                let hash = succ.hash64();
                out.buckets[shard_of(hash)].push(Cand {
                    key: succ,
                    hash,
                    parent: pos as u32,
                    input: idx,
                });
            }
        }
    }
}

/// True when the machine's state after a tick violates (or, for `reachable`, witnesses) the
/// property — exactly the simulator's reading: an expression whose evaluation fails is false.
fn decides(m: &mut Machine, check: Check) -> bool {
    match check {
        Check::Invariant { expr, assuming } => {
            assuming.is_none_or(|a| holds(m, a)) && !holds(m, expr)
        }
        Check::Reachable { expr } => holds(m, expr),
        Check::Ok { ok } => !holds(m, ok),
        Check::Builtin(_) => false,
    }
}

/// True when `e` evaluates to non-zero (false when its evaluation fails).
fn holds(m: &mut Machine, e: ExprId) -> bool {
    matches!(m.eval(e), Ok(v) if v != 0)
}
