//! The explicit engine: the reachable synchronous product, then the classic fixpoint that
//! alternately removes blocking states and states from which an uncontrollable event leads
//! to a removed state.
//!
//! States are packed location vectors ([`Packing`]: one bit field per automaton, fields never
//! straddle a 64-bit word) kept in one flat `Vec<u64>`; the visited set is an open-addressing
//! table of state numbers into that store. The engine is memory-bound, so it is written
//! around cache misses: a state's successors are computed first and their table slots read
//! together, so that the misses overlap; the table grows by re-inserting in slot order.
//! Successors are recorded in the order of exploration, which makes them a compact successor
//! list (CSR) for free; the predecessor lists (4 bytes an edge, the event's controllability in
//! the top bit) are built from it once by counting. Exploration is software-pipelined: a
//! state's successors are looked up one state later, when their slots are in the cache. Per
//! state the fixpoint keeps one byte of flags. Its first nonblocking step is a breadth-first
//! backward search that reads ahead in its queue; each later one recomputes only the states
//! that reach a state removed since.
//! Guards are derived afterwards, only when asked ([`crate::guards`]).
//!
//! With two threads, exploration is a pipeline ([`pipeline`]): one thread computes
//! successors, the other numbers them.

mod pipeline;

use crate::error::Error;
use crate::limits::Budget;
use crate::problem::{EventId, Kind, Problem, NONE};

/// Bit fields of a packed location vector.
#[derive(Clone, Debug)]
pub struct Packing {
    /// Per automaton: word index, shift and mask of its field.
    fields: Vec<(usize, u32, u64)>,
    /// 64-bit words per state.
    pub words: usize,
}

impl Packing {
    /// The packing of `p`'s location vectors.
    pub fn new(p: &Problem) -> Packing {
        let mut fields = Vec::new();
        let (mut word, mut bit) = (0usize, 0u32);
        for a in &p.automata {
            let w = (usize::BITS - (a.locs.len().max(2) - 1).leading_zeros()).max(1);
            if bit + w > 64 {
                word += 1;
                bit = 0;
            }
            let mask = if w == 64 { u64::MAX } else { (1u64 << w) - 1 };
            fields.push((word, bit, mask));
            bit += w;
        }
        Packing {
            fields,
            words: word + 1,
        }
    }

    /// Location of automaton `a` in `key`.
    #[inline]
    pub fn get(&self, key: &[u64], a: usize) -> u32 {
        let (w, s, m) = self.fields[a];
        ((key[w] >> s) & m) as u32
    }

    /// Set automaton `a`'s location in `key`.
    #[inline]
    pub fn set(&self, key: &mut [u64], a: usize, l: u32) {
        let (w, s, m) = self.fields[a];
        key[w] = (key[w] & !(m << s)) | ((l as u64) << s);
    }

    /// Pack a location vector.
    pub fn pack(&self, locs: &[u32], key: &mut [u64]) {
        key.fill(0);
        for (a, &l) in locs.iter().enumerate() {
            self.set(key, a, l);
        }
    }

    /// Unpack into `locs`.
    pub fn unpack(&self, key: &[u64], locs: &mut [u32]) {
        for (a, l) in locs.iter_mut().enumerate() {
            *l = self.get(key, a);
        }
    }
}

/// The result of the explicit fixpoint, before guards are derived.
pub struct Explicit {
    /// How states are packed.
    pub packing: Packing,
    /// Packed reachable product states, `packing.words` words each; state 0 is initial.
    pub store: Vec<u64>,
    /// `succ[succ_off[i]..succ_off[i + 1]]`: state `i`'s requirement-allowed transitions
    /// `(event, target)`.
    pub succ_off: Vec<u64>,
    /// See `succ_off`.
    pub succ: Vec<(EventId, u32)>,
    /// Kept states after the fixpoint, restricted to those reachable from the initial one
    /// through kept states.
    pub kept: Vec<bool>,
    /// Reachable states of the unrestricted product (plant × requirements).
    pub product_states: usize,
    /// Fixpoint rounds.
    pub rounds: usize,
}

/// Open-addressing set of state numbers, keyed by the packed words in the store. Each slot
/// also keeps a tag: the key itself when it is one word (no look into the store at all), else
/// its hash (the store is read only when the tags agree). Tag and number share a slot, so a
/// probe touches one cache line. A slot holds the state number plus one, so that a free slot
/// is all zeros and a new table is zeroed memory.
struct Visited {
    slots: Vec<[u64; 2]>,
    mask: usize,
}

#[inline]
fn hash(key: &[u64]) -> u64 {
    // MurmurHash3's 64-bit finaliser over the words: every input bit reaches the low bits
    // that pick the slot.
    let mut h = 0x9e37_79b9_7f4a_7c15u64;
    for &w in key {
        h ^= w;
        h ^= h >> 33;
        h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
        h ^= h >> 33;
        h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^= h >> 33;
    }
    h
}

#[inline]
fn tag(key: &[u64], h: u64) -> u64 {
    if key.len() == 1 {
        key[0]
    } else {
        h
    }
}

impl Visited {
    fn new() -> Visited {
        Visited {
            slots: vec![[0; 2]; 1 << 12],
            mask: (1 << 12) - 1,
        }
    }

    /// Read the first slot of each hash in `hs`: a prefetch written as plain loads.
    #[inline]
    fn touch(&self, hs: &[u64]) {
        let mut acc = 0u64;
        for &h in hs {
            acc ^= self.slots[h as usize & self.mask][1];
        }
        std::hint::black_box(acc);
    }

    /// The number of `key` (whose hash is `h`), inserting it as `next` if new;
    /// `(number, inserted)`.
    #[inline]
    fn insert(
        &mut self,
        store: &[u64],
        words: usize,
        key: &[u64],
        h: u64,
        next: u32,
    ) -> (u32, bool) {
        let t = tag(key, h);
        let mut i = h as usize & self.mask;
        loop {
            let [st, sid] = self.slots[i];
            if sid == 0 {
                self.slots[i] = [t, next as u64 + 1];
                return (next, true);
            }
            if st == t {
                let id = sid as usize - 1;
                if words == 1 || store[id * words..(id + 1) * words] == *key {
                    return (id as u32, false);
                }
            }
            i = (i + 1) & self.mask;
        }
    }

    /// Double the table when it is more than half full (`count` states in it). The old
    /// slots are re-inserted in slot order, so the writes go to two runs of the new table
    /// (near `i` and `i` plus the old size) instead of everywhere; the hash comes from the
    /// tag (`words` is the key length).
    fn grow_if_needed(&mut self, words: usize, count: usize) {
        if count * 2 < self.slots.len() {
            return;
        }
        let n = self.slots.len() * 2;
        let old = std::mem::replace(&mut self.slots, vec![[0; 2]; n]);
        self.mask = n - 1;
        for [t, id] in old {
            if id == 0 {
                continue;
            }
            let h = if words == 1 { hash(&[t]) } else { t };
            let mut i = h as usize & self.mask;
            while self.slots[i][1] != 0 {
                i = (i + 1) & self.mask;
            }
            self.slots[i] = [t, id];
        }
    }

    fn bytes(&self) -> u64 {
        self.slots.len() as u64 * 16
    }
}

/// Per event, the automata that have it: `(automaton, is plant)`.
pub(crate) fn participants(p: &Problem) -> Vec<Vec<(usize, bool)>> {
    let mut parts = vec![Vec::new(); p.events.len()];
    for (ai, a) in p.automata.iter().enumerate() {
        for &e in &a.alphabet {
            parts[e as usize].push((ai, a.kind == Kind::Plant));
        }
    }
    parts
}

/// Per plant automaton `a`, a bit set over the events per location (`ew` words each):
/// the events `a` allows there, and every event outside its alphabet. `(masks, ew)`.
fn plant_masks(p: &Problem) -> (Vec<(usize, Vec<u64>)>, usize) {
    let n_ev = p.events.len();
    let ew = n_ev.div_ceil(64).max(1);
    let masks = p
        .automata
        .iter()
        .enumerate()
        .filter(|(_, a)| a.kind == Kind::Plant)
        .map(|(ai, a)| {
            let mut m = vec![0u64; a.locs.len() * ew];
            for l in 0..a.locs.len() {
                for e in 0..n_ev {
                    if !a.has(e as EventId) || a.next[l * n_ev + e] != NONE {
                        m[l * ew + e / 64] |= 1 << (e % 64);
                    }
                }
            }
            (ai, m)
        })
        .collect();
    (masks, ew)
}

/// What a state's successors depend on besides the state, computed once per run and shared
/// by the exploring threads.
struct Rules {
    /// Per event, the automata that have it ([`participants`]).
    parts: Vec<Vec<(usize, bool)>>,
    /// Per event: uncontrollable.
    uncontrollable: Vec<bool>,
    /// Per event, the `needs` requirements on it.
    needs_of: Vec<Vec<usize>>,
    /// [`plant_masks`].
    masks: Vec<(usize, Vec<u64>)>,
    ew: usize,
}

impl Rules {
    fn new(p: &Problem) -> Rules {
        let (masks, ew) = plant_masks(p);
        Rules {
            parts: participants(p),
            uncontrollable: p.events.iter().map(|e| !e.controllable).collect(),
            needs_of: (0..p.events.len())
                .map(|e| {
                    (0..p.needs.len())
                        .filter(|&i| p.needs[i].event as usize == e)
                        .collect()
                })
                .collect(),
            masks,
            ew,
        }
    }
}

/// Computes the successors of product states (one per exploring thread: it owns its
/// scratch space).
struct Expander<'a> {
    p: &'a Problem,
    pk: &'a Packing,
    rules: &'a Rules,
    locs: Vec<u32>,
    en: Vec<u64>,
}

impl<'a> Expander<'a> {
    fn new(p: &'a Problem, pk: &'a Packing, rules: &'a Rules) -> Expander<'a> {
        Expander {
            p,
            pk,
            rules,
            locs: vec![0; p.automata.len()],
            en: vec![0; rules.ew],
        }
    }

    /// Append the requirement-allowed successors of the packed state `key` to `out` (keys,
    /// events, hashes), then its end and its flags: [`MARKED`], and [`BAD`] when it is
    /// forbidden or a requirement blocks an uncontrollable event the plant allows there. A
    /// forbidden state is not expanded.
    fn expand(&mut self, key: &[u64], out: &mut Batch) {
        let (p, pk, r) = (self.p, self.pk, self.rules);
        let n_ev = p.events.len();
        let ew = r.ew;
        let locs = &mut self.locs;
        pk.unpack(key, locs);
        let mut is_bad = p.is_forbidden(locs);
        let mut f = if p.is_marked(locs) { MARKED } else { 0 };
        if !is_bad {
            // The events every plant allows here (one AND per plant and mask word), then
            // only those are tried.
            self.en.fill(u64::MAX);
            for (a, m) in &r.masks {
                let row = &m[locs[*a] as usize * ew..(locs[*a] as usize + 1) * ew];
                for (x, y) in self.en.iter_mut().zip(row) {
                    *x &= y;
                }
            }
            for e in EventBits::new(&self.en, n_ev) {
                let (mut plant_ok, mut req_ok) = (true, true);
                let at = out.keys.len();
                out.keys.extend_from_slice(key);
                let next = &mut out.keys[at..];
                for &(a, is_plant) in &r.parts[e] {
                    let aut = &p.automata[a];
                    let t = aut.next[locs[a] as usize * n_ev + e];
                    if t == NONE {
                        if is_plant {
                            plant_ok = false;
                            break;
                        }
                        req_ok = false;
                    } else {
                        pk.set(next, a, t);
                    }
                }
                if plant_ok && req_ok {
                    req_ok = r.needs_of[e].iter().all(|&k| p.needs[k].cond.eval(locs));
                }
                if !plant_ok || !req_ok {
                    out.keys.truncate(at);
                    if plant_ok && r.uncontrollable[e] {
                        is_bad = true;
                    }
                    continue;
                }
                out.hashes.push(hash(&out.keys[at..]));
                out.events.push(e as EventId);
            }
        }
        if is_bad {
            f |= BAD;
        }
        out.ends.push(out.events.len() as u32);
        out.flags.push(f);
    }
}

/// The set bits below `n` of a bit set, ascending.
struct EventBits<'a> {
    words: &'a [u64],
    w: usize,
    cur: u64,
    n: usize,
}

impl<'a> EventBits<'a> {
    fn new(words: &'a [u64], n: usize) -> EventBits<'a> {
        EventBits {
            words,
            w: 0,
            cur: words.first().copied().unwrap_or(0),
            n,
        }
    }
}

impl Iterator for EventBits<'_> {
    type Item = usize;
    #[inline]
    fn next(&mut self) -> Option<usize> {
        loop {
            if self.cur != 0 {
                let b = self.cur.trailing_zeros() as usize;
                self.cur &= self.cur - 1;
                let e = self.w * 64 + b;
                return (e < self.n).then_some(e);
            }
            self.w += 1;
            self.cur = *self.words.get(self.w)?;
        }
    }
}

/// Flags per state of the fixpoint, one byte each so that a look-up touches one byte.
const BAD: u8 = 1;
const MARKED: u8 = 2;
/// Not (yet) removed by the fixpoint.
const ALIVE: u8 = 4;
/// Reaches a marked state through alive states (as of the last nonblocking step).
const CO: u8 = 8;
/// In the region the incremental nonblocking step recomputes.
const REGION: u8 = 16;
/// Kept in the supervisor: alive and reachable from the initial state through alive states.
const KEPT: u8 = 32;

/// The top bit of a predecessor entry: the edge's event is uncontrollable.
const UNC: u32 = 1 << 31;

/// Largest number of states: state numbers are 31-bit (the predecessor lists keep a flag in
/// the top bit).
const MAX_STATES: usize = (1 << 31) - 2;

/// Successors of one or more states before they are looked up: packed keys, events and
/// hashes, with each state's end in `events` and its flags ([`BAD`], [`MARKED`]).
#[derive(Default)]
struct Batch {
    keys: Vec<u64>,
    events: Vec<EventId>,
    hashes: Vec<u64>,
    ends: Vec<u32>,
    flags: Vec<u8>,
}

impl Batch {
    fn clear(&mut self) {
        self.keys.clear();
        self.events.clear();
        self.hashes.clear();
        self.ends.clear();
        self.flags.clear();
    }

    /// The successors of the `k`th state of the batch: a range of `events`.
    fn state(&self, k: usize) -> std::ops::Range<usize> {
        let start = if k == 0 { 0 } else { self.ends[k - 1] as usize };
        start..self.ends[k] as usize
    }
}

/// The reachable product as it is explored: the store of packed states, the visited table
/// and the successor lists so far.
struct Explored {
    words: usize,
    store: Vec<u64>,
    visited: Visited,
    succ_off: Vec<u64>,
    succ: Vec<(EventId, u32)>,
    count: usize,
}

impl Explored {
    /// Look up (and add) the successors of the next state in order, `b`'s successors in
    /// `range`; they become its successor list.
    fn add(
        &mut self,
        b: &Batch,
        range: std::ops::Range<usize>,
        budget: &Budget,
    ) -> Result<(), Error> {
        let words = self.words;
        for j in range {
            let (e, h) = (b.events[j], b.hashes[j]);
            if self.count >= MAX_STATES {
                return Err(self.too_many(budget));
            }
            let next = &b.keys[j * words..(j + 1) * words];
            let (id, new) = self
                .visited
                .insert(&self.store, words, next, h, self.count as u32);
            if new {
                self.store.extend_from_slice(next);
                self.count += 1;
                self.visited.grow_if_needed(words, self.count);
            }
            self.succ.push((e, id));
        }
        self.succ_off.push(self.succ.len() as u64);
        Ok(())
    }

    /// The engine's data so far: the store, the edges twice (successors of 8 bytes, then
    /// predecessors of 4), the visited table and per state two offsets and a byte of flags.
    fn bytes(&self) -> u64 {
        self.store.len() as u64 * 8
            + self.succ.len() as u64 * 12
            + self.visited.bytes()
            + self.count as u64 * 17
    }

    fn check(&self, budget: &Budget, phase: &'static str) -> Result<(), Error> {
        budget.check(phase, self.count as f64, self.bytes())
    }

    /// State numbers are 31-bit: past that the engine stops as at a state limit.
    fn too_many(&self, budget: &Budget) -> Error {
        let partial = crate::error::Partial {
            phase: "reachability",
            states: self.count as f64,
            seconds: budget.seconds(),
            bytes: self.bytes(),
        };
        let limit = crate::error::Limit::States(self.count as u64);
        Error::new(crate::error::ErrorKind::Limit { limit, partial })
    }
}

/// Run the explicit engine within `budget`, in this thread.
pub fn run(p: &Problem, budget: &Budget) -> Result<Explicit, Error> {
    run_on(p, budget, 1)
}

/// Run the explicit engine within `budget`, exploring on `threads` threads (one: in this
/// thread; two or more: the two-thread pipeline of [`pipeline`], which numbers the states
/// exactly as one thread does, so the result is the same).
pub fn run_on(p: &Problem, budget: &Budget, threads: usize) -> Result<Explicit, Error> {
    let pk = Packing::new(p);
    let words = pk.words;
    let uncontrollable: Vec<bool> = p.events.iter().map(|e| !e.controllable).collect();
    let rules = Rules::new(p);
    let mut x = Explored {
        words,
        store: vec![0; words],
        visited: Visited::new(),
        succ_off: vec![0],
        succ: Vec::new(),
        count: 1,
    };
    pk.pack(&p.initial(), &mut x.store[..words]);
    let h0 = hash(&x.store[..words]);
    x.visited.insert(&x.store, words, &x.store[..words], h0, 0);
    let mut flags: Vec<u8> = Vec::new();
    if threads >= 2 {
        pipeline::explore(p, &pk, &rules, &mut x, &mut flags, budget)?;
    } else {
        explore(
            &mut Expander::new(p, &pk, &rules),
            &mut x,
            &mut flags,
            budget,
        )?;
    }
    x.check(budget, "reachability")?;
    let n = x.count;
    // The estimate counts the predecessor lists already; the table goes before they come.
    x.check(budget, "fixpoint")?;
    let Explored {
        store,
        succ_off,
        succ,
        visited,
        ..
    } = x;
    drop(visited);
    let g = Graph::new(n, &succ_off, &succ, &uncontrollable);
    let rounds = g.fixpoint(&mut flags, budget)?;
    g.restrict_to_reachable(&mut flags);
    drop(g);
    Ok(Explicit {
        packing: pk,
        store,
        succ_off,
        succ,
        kept: flags.iter().map(|f| f & KEPT != 0).collect(),
        product_states: n,
        rounds,
    })
}

/// Explore the reachable product in this thread, software-pipelined: state i's successors
/// are computed and their slots read while state i - 1's wait in `pending`; they are looked
/// up one state later, when the slots are in the cache. A state not yet discovered first
/// needs the pending look-ups.
fn explore(
    ex: &mut Expander<'_>,
    x: &mut Explored,
    flags: &mut Vec<u8>,
    budget: &Budget,
) -> Result<(), Error> {
    let words = x.words;
    let (mut cur, mut pending) = (Batch::default(), Batch::default());
    let mut has_pending = false;
    let mut i = 0usize;
    loop {
        if i >= x.count {
            if has_pending {
                x.add(&pending, pending.state(0), budget)?;
                has_pending = false;
                continue;
            }
            return Ok(());
        }
        cur.clear();
        ex.expand(&x.store[i * words..(i + 1) * words], &mut cur);
        flags.push(cur.flags[0]);
        x.visited.touch(&cur.hashes);
        if has_pending {
            x.add(&pending, pending.state(0), budget)?;
        }
        std::mem::swap(&mut cur, &mut pending);
        has_pending = true;
        i += 1;
        if i.is_multiple_of(4096) {
            x.check(budget, "reachability")?;
        }
    }
}

/// The transition graph of the reachable product: successor lists as explored, predecessor
/// lists built from them once by counting (31-bit state numbers with the [`UNC`] flag).
struct Graph<'a> {
    succ_off: &'a [u64],
    succ: &'a [(EventId, u32)],
    pred_off: Vec<u64>,
    pred: Vec<u32>,
}

impl<'a> Graph<'a> {
    fn new(
        n: usize,
        succ_off: &'a [u64],
        succ: &'a [(EventId, u32)],
        uncontrollable: &[bool],
    ) -> Graph<'a> {
        let mut pred_off = vec![0u64; n + 1];
        for &(_, t) in succ {
            pred_off[t as usize + 1] += 1;
        }
        for k in 0..n {
            pred_off[k + 1] += pred_off[k];
        }
        let mut fill = pred_off.clone();
        let mut pred: Vec<u32> = vec![0; succ.len()];
        for s in 0..n {
            for &(e, t) in &succ[succ_off[s] as usize..succ_off[s + 1] as usize] {
                let at = &mut fill[t as usize];
                pred[*at as usize] = s as u32 | if uncontrollable[e as usize] { UNC } else { 0 };
                *at += 1;
            }
        }
        Graph {
            succ_off,
            succ,
            pred_off,
            pred,
        }
    }

    #[inline]
    fn preds(&self, t: usize) -> &[u32] {
        &self.pred[self.pred_off[t] as usize..self.pred_off[t + 1] as usize]
    }

    #[inline]
    fn succs(&self, s: usize) -> &[(EventId, u32)] {
        &self.succ[self.succ_off[s] as usize..self.succ_off[s + 1] as usize]
    }

    /// The classic fixpoint over `flags` (sets [`ALIVE`] on the states it keeps); the number
    /// of rounds. The first nonblocking step is a backward search from every marked state;
    /// each later one recomputes only the region that reaches a state removed since (the
    /// others keep their path to a marked state), which is empty when controllability
    /// removed nothing.
    fn fixpoint(&self, flags: &mut [u8], budget: &Budget) -> Result<usize, Error> {
        let n = flags.len();
        let mut work: Vec<u32> = Vec::new();
        for (s, f) in flags.iter_mut().enumerate() {
            if *f & BAD != 0 {
                work.push(s as u32);
            } else {
                *f |= ALIVE;
            }
        }
        let mut stack: Vec<u32> = Vec::new();
        let mut removed: Vec<u32> = Vec::new();
        let mut rounds = 0;
        loop {
            rounds += 1;
            // Controllability: a state with an uncontrollable edge into a removed state goes
            // too.
            removed.clear();
            while let Some(t) = work.pop() {
                for &ps in self.preds(t as usize) {
                    let s = (ps & !UNC) as usize;
                    if ps & UNC != 0 && flags[s] & ALIVE != 0 {
                        flags[s] &= !(ALIVE | CO);
                        work.push(s as u32);
                        removed.push(s as u32);
                    }
                }
            }
            // Nonblocking: keep only states that reach a marked state through kept states.
            // (Sweeps in state order, as for reachability below, do not settle here: on the
            // philosophers a path back to the marked initial state first goes deeper.)
            if rounds == 1 {
                stack.clear();
                for (s, f) in flags.iter_mut().enumerate() {
                    if *f & (ALIVE | MARKED) == ALIVE | MARKED {
                        *f |= CO;
                        stack.push(s as u32);
                    }
                }
                self.backward(flags, &mut stack, ALIVE);
                for (s, f) in flags.iter_mut().enumerate() {
                    if *f & (ALIVE | CO) == ALIVE {
                        *f &= !ALIVE;
                        work.push(s as u32);
                    }
                }
            } else if !removed.is_empty() {
                self.recompute(flags, &removed, &mut stack, &mut work);
            }
            budget.check("fixpoint", n as f64, 0)?;
            if work.is_empty() {
                break;
            }
        }
        Ok(rounds)
    }

    /// Breadth-first backward search from `queue` over predecessors whose flags contain
    /// `within`, setting [`CO`]; empties `queue`. The entries a few places ahead in the queue
    /// have their offsets and first predecessors read early (a prefetch written as plain
    /// loads), so the cache misses of several states overlap.
    fn backward(&self, flags: &mut [u8], queue: &mut Vec<u32>, within: u8) {
        let mut head = 0;
        let mut acc = 0u64;
        while head < queue.len() {
            if let Some(&a) = queue.get(head + 16) {
                acc ^= self.pred_off[a as usize];
            }
            if let Some(&b) = queue.get(head + 8) {
                let at = self.pred_off[b as usize] as usize;
                acc ^= self.pred.get(at).copied().unwrap_or(0) as u64;
            }
            let t = queue[head] as usize;
            head += 1;
            for &ps in self.preds(t) {
                let s = (ps & !UNC) as usize;
                if flags[s] & (within | CO) == within {
                    flags[s] |= CO;
                    queue.push(s as u32);
                }
            }
        }
        std::hint::black_box(acc);
        queue.clear();
    }

    /// A later nonblocking step: the alive states that reach a state of `removed` through
    /// alive states lose [`CO`]; among them, the marked ones and those with an edge to a
    /// state that kept it get it back, and so does every state of the region that reaches
    /// those; the rest are removed (pushed on `work`). Every other alive state kept its
    /// path to a marked state: a path through a removed state would put it in the region.
    fn recompute(
        &self,
        flags: &mut [u8],
        removed: &[u32],
        stack: &mut Vec<u32>,
        work: &mut Vec<u32>,
    ) {
        let mut region: Vec<u32> = Vec::new();
        stack.clear();
        stack.extend_from_slice(removed);
        while let Some(t) = stack.pop() {
            for &ps in self.preds(t as usize) {
                let s = (ps & !UNC) as usize;
                if flags[s] & (ALIVE | REGION) == ALIVE {
                    flags[s] = (flags[s] | REGION) & !CO;
                    region.push(s as u32);
                    stack.push(s as u32);
                }
            }
        }
        for &s in &region {
            let s = s as usize;
            let seed = flags[s] & MARKED != 0
                || self
                    .succs(s)
                    .iter()
                    .any(|&(_, t)| flags[t as usize] & (ALIVE | CO) == ALIVE | CO);
            if seed {
                flags[s] |= CO;
                stack.push(s as u32);
            }
        }
        self.backward(flags, stack, ALIVE | REGION);
        for &s in &region {
            let f = &mut flags[s as usize];
            *f &= !REGION;
            if *f & CO == 0 {
                *f &= !ALIVE;
                work.push(s);
            }
        }
    }

    /// Set [`KEPT`] on the alive states reachable from the initial one through alive states:
    /// one sweep in state order (exploration order, so most edges lead forward, to a state
    /// the sweep has not passed yet), then a search from the states an edge back reached.
    fn restrict_to_reachable(&self, flags: &mut [u8]) {
        if flags.first().is_none_or(|f| f & ALIVE == 0) {
            return;
        }
        flags[0] |= KEPT;
        let mut stack: Vec<u32> = Vec::new();
        for s in 0..flags.len() {
            if flags[s] & KEPT == 0 {
                continue;
            }
            for &(_, t) in self.succs(s) {
                let ft = &mut flags[t as usize];
                if *ft & (ALIVE | KEPT) == ALIVE {
                    *ft |= KEPT;
                    if (t as usize) < s {
                        stack.push(t);
                    }
                }
            }
        }
        while let Some(s) = stack.pop() {
            for &(_, t) in self.succs(s as usize) {
                let ft = &mut flags[t as usize];
                if *ft & (ALIVE | KEPT) == ALIVE {
                    *ft |= KEPT;
                    stack.push(t);
                }
            }
        }
    }
}

impl Explicit {
    /// Number of supervisor states (kept and reachable).
    pub fn size(&self) -> usize {
        self.kept.iter().filter(|k| **k).count()
    }

    /// Number of supervisor transitions (between kept states).
    pub fn transitions(&self) -> usize {
        (0..self.kept.len())
            .filter(|&s| self.kept[s])
            .map(|s| {
                self.edges(s)
                    .iter()
                    .filter(|(_, t)| self.kept[*t as usize])
                    .count()
            })
            .sum()
    }

    /// State `s`'s transitions `(event, target)`.
    pub fn edges(&self, s: usize) -> &[(EventId, u32)] {
        &self.succ[self.succ_off[s] as usize..self.succ_off[s + 1] as usize]
    }

    /// The location vector of state `s`.
    pub fn locs(&self, s: usize, out: &mut [u32]) {
        let w = self.packing.words;
        self.packing.unpack(&self.store[s * w..(s + 1) * w], out);
    }
}
