//! Expanding a chunk of states: every input vector that satisfies the `assume`s, one tick of
//! the IR each, the per-transition properties checked on every transition, successors packed
//! and bucketed by shard. Properties decided by the successor state alone are checked later,
//! once per new state ([`StateCheck`]).

use crate::native::NativeRun;
use crate::pack::{Key, Packer};
use crate::props::{Check, Spec};
use crate::reduce::{Reducer, Tally};
use crate::symmetry::Canon;
use crate::table::{shard_of, SHARDS};
use statecheck_ir::assume::InputSpace;
use statecheck_ir::{ExprId, Goal, Machine, Prepared, Program, RuntimeError};

/// A successor found while expanding: its key and how it was reached.
pub(crate) struct Cand<K> {
    pub key: K,
    /// Position of the parent in its layer.
    pub parent: u32,
    /// Position of the input vector in the enumeration.
    pub input: u32,
}

/// A transition that decides a property (a violation, a witness, a run-time error).
#[derive(Clone)]
pub(crate) struct Found<K> {
    /// Index into the checked properties.
    pub prop: usize,
    /// The source state.
    pub parent: K,
    /// Position of the input vector.
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
    /// The current state's successors so far ([`push_successor`]).
    dedup: Dedup,
}

/// Everything a worker needs to expand states; shared read-only by all threads.
pub(crate) struct Expander<'a> {
    pub program: &'a Program,
    pub packer: &'a Packer,
    pub space: &'a InputSpace,
    pub specs: &'a [Spec],
    pub coverage: bool,
    /// The native successor generator, used once it is ready (see [`crate::native`]).
    pub native: Option<&'a NativeRun>,
    /// The input abstraction, when enabled ([`crate::Options::reduce_inputs`]).
    pub reduce: Option<&'a Reducer>,
    /// Symmetry reduction: successors stored in canonical form ([`crate::symmetry`]).
    pub sym: Option<&'a Canon>,
}

impl Expander<'_> {
    /// True when some still-pending property is checked per state.
    pub fn checks_states(&self, pending: &[bool]) -> bool {
        self.specs
            .iter()
            .zip(pending)
            .any(|(s, p)| *p && s.per_state)
    }

    /// Expand `states`, the first of which sits at position `first_pos` of its layer;
    /// `pending[i]` tells whether property `i` is still undecided.
    pub fn chunk<K: Key>(&self, states: &[K], first_pos: usize, pending: &[bool]) -> ChunkOut<K> {
        let p = self.program;
        let sp = self.space;
        // Only the per-transition properties; the others are checked per new state.
        let mut open = Open::new(self.specs, pending);
        if open.watch.iter().all(|&i| self.specs[i].after_tick) {
            if let Some((native, run)) = self.native.and_then(|r| r.ready().map(|n| (n, r))) {
                return self.chunk_native(native, run, states, first_pos, open);
            }
        }
        let mut m = self.machine();
        let mut state = vec![0i64; p.n_state];
        let mut words = vec![0u64; self.packer.words];
        let mut inp = vec![0i64; sp.slots.len()];
        let mut out = ChunkOut::with_room(states.len(), sp.per_tick());
        let n = sp.slots.len();
        // Assumes evaluated on every transition: all of them when the vectors are not listed.
        let mut per_tick = self.prepared(&sp.mixed_assumes);
        if sp.listed().is_none() {
            per_tick.extend(self.prepared(&sp.input_assumes));
        }
        let state_assumes = self.prepared(&sp.state_assumes);
        let mut walker = self.reduce.filter(|r| r.cost.worth()).map(|r| r.walker(p));
        let mut tally = Tally::new();
        let all = u64::try_from(sp.per_tick()).unwrap_or(u64::MAX);
        for (j, key) in states.iter().enumerate() {
            let pos = (first_pos + j) as u32;
            self.packer.unpack(key, &mut words, &mut state);
            if !state_assumes.is_empty() {
                m.load_state(&state);
                if !state_assumes.iter().all(|a| m.holds(*a)) {
                    continue;
                }
            }
            tally.begin();
            let groups = match (self.reduce, walker.as_mut()) {
                (Some(r), Some(w)) => {
                    let g = r.groups(w, sp, &state);
                    tally.walked(g.as_ref().map_or(0, |g| all - g.first.len() as u64));
                    g
                }
                _ => None,
            };
            if let Some(g) = groups {
                for (k, &idx) in g.first.iter().enumerate() {
                    m.load(&state, &g.vectors[k * n..k * n + n]);
                    if per_tick.iter().all(|a| m.holds(*a)) {
                        let t = Tick {
                            key,
                            pos,
                            input: idx,
                        };
                        out.transitions += g.size[k] - 1;
                        self.transition(&mut m, t, &mut open, &mut words, &mut out);
                    }
                }
                tally.stepped(g.first.len() as u64);
                continue;
            }
            match sp.listed() {
                Some((flat, count)) => {
                    for idx in 0..count {
                        m.load(&state, &flat[idx * n..idx * n + n]);
                        if per_tick.iter().all(|a| m.holds(*a)) {
                            let t = Tick {
                                key,
                                pos,
                                input: idx as u32,
                            };
                            self.transition(&mut m, t, &mut open, &mut words, &mut out);
                        }
                    }
                }
                None => {
                    sp.first(&mut inp);
                    for idx in 0..sp.count as u64 {
                        m.load(&state, &inp);
                        sp.advance(&mut inp);
                        if per_tick.iter().all(|a| m.holds(*a)) {
                            let t = Tick {
                                key,
                                pos,
                                input: idx as u32,
                            };
                            self.transition(&mut m, t, &mut open, &mut words, &mut out);
                        }
                    }
                }
            }
            tally.stepped(all);
        }
        if let Some(r) = self.reduce {
            r.cost.record(&tally);
        }
        out.coverage = m.coverage().map(<[u64]>::to_vec);
        out
    }

    /// A machine for this expander (counting coverage when asked).
    pub(crate) fn machine(&self) -> Machine<'_> {
        let mut m = Machine::new(self.program);
        if self.coverage {
            m.enable_coverage();
        }
        m
    }

    /// Compiled forms of `assumes`.
    pub(crate) fn prepared(&self, assumes: &[ExprId]) -> Vec<Prepared> {
        assumes.iter().map(|&a| self.program.prepare(a)).collect()
    }

    /// One tick from the loaded state with the inputs set: record what it decides and the
    /// successor.
    #[inline(always)]
    fn transition<K: Key>(
        &self,
        m: &mut Machine,
        t: Tick<'_, K>,
        open: &mut Open,
        words: &mut [u64],
        out: &mut ChunkOut<K>,
    ) {
        out.transitions += 1;
        match m.step() {
            Err(e) => self.record_error(e, &t, open, out),
            Ok(()) => {
                self.watch(m, &t, open, out);
                let succ: K = match self.sym {
                    Some(c) => c.pack(self.packer, m.state(), words),
                    None => self.packer.pack(m.state(), words),
                };
                push_successor(succ, &t, out);
            }
        }
    }

    /// Check the per-transition properties still open on the machine as the tick left it.
    #[inline]
    pub(crate) fn watch<K: Key>(
        &self,
        m: &mut Machine,
        t: &Tick<'_, K>,
        open: &mut Open,
        out: &mut ChunkOut<K>,
    ) {
        if open.watch.is_empty() {
            return;
        }
        let specs = self.specs;
        open.watch.retain(|&i| {
            let hit = decides(m, specs[i].check);
            if hit {
                out.found.push(Found {
                    prop: i,
                    parent: t.key.clone(),
                    input: t.input,
                    error: None,
                });
            }
            !hit
        });
    }

    /// A tick stopped by a run-time error: it decides its built-in property if still pending.
    pub(crate) fn record_error<K: Key>(
        &self,
        e: RuntimeError,
        t: &Tick<'_, K>,
        open: &mut Open,
        out: &mut ChunkOut<K>,
    ) {
        let name = e.kind.builtin();
        let hit = self
            .specs
            .iter()
            .position(|s| matches!(s.check, Check::Builtin(b) if b == name));
        if let Some(i) = hit.filter(|i| open.builtin[*i]) {
            open.builtin[i] = false;
            out.found.push(Found {
                prop: i,
                parent: t.key.clone(),
                input: t.input,
                error: Some(e),
            });
        }
    }
}

/// Record the successor `succ` of a tick.
///
/// Successors of one state are deduplicated here, before the visited set sees them: on
/// models with wide input branching most input vectors of a state lead to a few successors
/// (the inputs the tick does not read), and a repeat costs a random access into the table.
/// Only a later duplicate from the same parent is dropped, and the visited set keeps the
/// first candidate of a key in generation order anyway, so the states stored, their parents
/// and inputs (hence counterexamples) are exactly those without the deduplication.
#[inline(always)]
pub(crate) fn push_successor<K: Key>(succ: K, t: &Tick<'_, K>, out: &mut ChunkOut<K>) {
    // A self-loop leads to a state already visited (the source): nothing to insert.
    if succ == *t.key {
        return;
    }
    let h = succ.hash64();
    let shard = shard_of(h);
    let d = &mut out.dedup;
    if d.parent != t.pos || d.pushed.len() >= DEDUP_MAX {
        d.parent = t.pos;
        d.pushed.clear();
    }
    for &(hh, at) in &d.pushed {
        if hh == h
            && out.buckets[shard]
                .get(at as usize)
                .is_some_and(|c| c.key == succ)
        {
            return;
        }
    }
    let bucket = &mut out.buckets[shard];
    if let Ok(at) = u32::try_from(bucket.len()) {
        d.pushed.push((h, at));
    }
    bucket.push(Cand {
        key: succ,
        parent: t.pos,
        input: t.input,
    });
}

/// Most successors of one state remembered for deduplication (a state with more still has
/// every successor inserted; later ones are compared against the first `DEDUP_MAX` only).
const DEDUP_MAX: usize = 64;

/// The successors pushed so far from the state being expanded: their hashes and positions
/// in their shard's bucket.
pub(crate) struct Dedup {
    parent: u32,
    pushed: Vec<(u64, u32)>,
}

impl<K> ChunkOut<K> {
    /// An empty output with room for the successors of `states` states of `per_tick`
    /// transitions each, spread evenly over the shards, plus some slack.
    pub(crate) fn with_room(states: usize, per_tick: u128) -> ChunkOut<K> {
        let per_shard = (states as u128 * per_tick / SHARDS as u128 * 5 / 4).min(1 << 16) as usize;
        ChunkOut {
            buckets: (0..SHARDS)
                .map(|_| Vec::with_capacity(per_shard + 4))
                .collect(),
            found: Vec::new(),
            transitions: 0,
            coverage: None,
            dedup: Dedup {
                parent: u32::MAX,
                pushed: Vec::with_capacity(DEDUP_MAX),
            },
        }
    }
}

/// The properties a chunk still checks on every transition.
pub(crate) struct Open {
    /// Per property: a still-pending built-in (decided by a run-time error of the tick).
    builtin: Vec<bool>,
    /// Still-pending properties evaluated after every tick, in declaration order.
    pub watch: Vec<usize>,
}

impl Open {
    fn new(specs: &[Spec], pending: &[bool]) -> Open {
        let tick = |(s, p): (&Spec, &bool)| *p && !s.per_state;
        Open {
            builtin: specs
                .iter()
                .zip(pending)
                .map(|sp| tick(sp) && matches!(sp.0.check, Check::Builtin(_)))
                .collect(),
            watch: specs
                .iter()
                .zip(pending)
                .enumerate()
                .filter(|(_, sp)| tick(*sp) && !matches!(sp.0.check, Check::Builtin(_)))
                .map(|(i, _)| i)
                .collect(),
        }
    }
}

/// The transition being taken: the source state, its position, the input position.
pub(crate) struct Tick<'k, K> {
    pub key: &'k K,
    pub pos: u32,
    pub input: u32,
}

/// A new state deciding a per-state property: the property, the parent's position in its
/// layer, and the input position of the transition that found the state.
pub(crate) type StateFind = (usize, u32, u32);

/// Checks the per-state properties on newly found states (one per shard, kept for the whole
/// search).
pub(crate) struct StateCheck<'a, 'p> {
    exp: &'a Expander<'p>,
    m: Machine<'p>,
    words: Vec<u64>,
    /// The still-open per-state properties, in declaration order.
    watch: Vec<usize>,
    /// The first new state (in generation order) deciding each property.
    pub found: Vec<StateFind>,
}

impl<'a, 'p> StateCheck<'a, 'p> {
    /// A checker for the still-pending per-state properties.
    pub fn new(exp: &'a Expander<'p>, pending: &[bool]) -> Self {
        let mut c = StateCheck {
            exp,
            m: Machine::new(exp.program),
            words: vec![0; exp.packer.words],
            watch: Vec::new(),
            found: Vec::new(),
        };
        exp.packer.set_constants(c.m.state_mut());
        c.reset(pending);
        c
    }

    /// Start over (no findings) with the per-state properties still pending.
    pub fn reset(&mut self, pending: &[bool]) {
        self.found.clear();
        self.watch.clear();
        self.watch.extend(
            pending
                .iter()
                .zip(self.exp.specs)
                .enumerate()
                .filter(|(_, (p, s))| **p && s.per_state)
                .map(|(i, _)| i),
        );
    }

    /// Check a new state reached by `c`.
    #[inline]
    pub fn check<K: Key>(&mut self, c: &Cand<K>) {
        if self.watch.is_empty() {
            return;
        }
        // Unpacked straight into the machine's state registers, whose constant slots are set
        // once and for all (nothing else writes the state: properties are pure).
        self.exp
            .packer
            .unpack_live(&c.key, &mut self.words, self.m.state_mut());
        let mut j = 0;
        while let Some(&i) = self.watch.get(j) {
            if decides(&mut self.m, self.exp.specs[i].check) {
                self.found.push((i, c.parent, c.input));
                self.watch.remove(j);
            } else {
                j += 1;
            }
        }
    }
}

/// True when the machine's state after a tick violates (or, for `reachable`, witnesses) the
/// property — exactly the simulator's reading: an expression whose evaluation fails is false.
pub(crate) fn decides(m: &mut Machine, check: Check) -> bool {
    match check {
        // The IR's reading of the goal, each expression through its compiled code.
        Check::Always { when, holds } => Goal::Always {
            when: when.map(|w| w.id),
            holds: holds.id,
        }
        .decided_by(|e| {
            let code = match when {
                Some(w) if e != holds.id => w.code,
                _ => holds.code,
            };
            m.holds(code)
        }),
        Check::Reach { target } => m.holds(target.code),
        Check::Builtin(_) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn push(out: &mut ChunkOut<u32>, source: u32, pos: u32, input: u32, succ: u32) {
        let t = Tick {
            key: &source,
            pos,
            input,
        };
        push_successor(succ, &t, out);
    }

    fn all(out: &ChunkOut<u32>) -> Vec<(u32, u32, u32)> {
        let mut v: Vec<_> = out
            .buckets
            .iter()
            .flatten()
            .map(|c| (c.key, c.parent, c.input))
            .collect();
        v.sort_unstable();
        v
    }

    /// A repeat from the same state is dropped (the first input that reached it is kept), a
    /// self-loop is never pushed, and the same successor from another state is kept (the
    /// visited set decides between states).
    #[test]
    fn successors_of_one_state_are_pushed_once() {
        let mut out = ChunkOut::with_room(2, 4);
        push(&mut out, 1, 0, 0, 7);
        push(&mut out, 1, 0, 1, 8);
        push(&mut out, 1, 0, 2, 7);
        push(&mut out, 1, 0, 3, 1);
        push(&mut out, 2, 1, 0, 7);
        push(&mut out, 2, 1, 1, 7);
        assert_eq!(all(&out), vec![(7, 0, 0), (7, 1, 0), (8, 0, 1)]);
    }
}
