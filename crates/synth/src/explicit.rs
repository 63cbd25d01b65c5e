//! The explicit engine: the reachable synchronous product, then the classic fixpoint that
//! alternately removes blocking states and states from which an uncontrollable event leads
//! to a removed state.
//!
//! States are packed location vectors ([`Packing`]: one bit field per automaton, fields never
//! straddle a 64-bit word) kept in one flat `Vec<u64>`; the visited set is an open-addressing
//! table of 4-byte state numbers into that store. Successors are recorded in the order of
//! exploration, which makes them a compact successor list (CSR) for free; the predecessor
//! lists are built from it once by counting. The fixpoints are linear passes over those
//! lists, and guards are derived afterwards, only when asked ([`crate::guards`]).

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
/// probe touches one cache line.
struct Visited {
    slots: Vec<Slot>,
    mask: usize,
}

#[derive(Clone, Copy)]
struct Slot {
    tag: u64,
    id: u32,
}

const EMPTY: u32 = u32::MAX;
const FREE: Slot = Slot { tag: 0, id: EMPTY };

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
            slots: vec![FREE; 1 << 12],
            mask: (1 << 12) - 1,
        }
    }

    /// The number of `key`, inserting it as `next` if new; `(number, inserted)`.
    #[inline]
    fn insert(&mut self, store: &[u64], words: usize, key: &[u64], next: u32) -> (u32, bool) {
        let h = hash(key);
        let t = tag(key, h);
        let mut i = h as usize & self.mask;
        loop {
            let s = self.slots[i];
            if s.id == EMPTY {
                self.slots[i] = Slot { tag: t, id: next };
                return (next, true);
            }
            if s.tag == t {
                if words == 1 {
                    return (s.id, false);
                }
                let at = s.id as usize * words;
                if &store[at..at + words] == key {
                    return (s.id, false);
                }
            }
            i = (i + 1) & self.mask;
        }
    }

    /// Double the table when it is more than half full (`count` states in it).
    fn grow_if_needed(&mut self, store: &[u64], words: usize, count: usize) {
        if count * 2 < self.slots.len() {
            return;
        }
        let n = self.slots.len() * 2;
        self.slots = vec![FREE; n];
        self.mask = n - 1;
        for s in 0..count {
            let key = &store[s * words..(s + 1) * words];
            let h = hash(key);
            let mut i = h as usize & self.mask;
            while self.slots[i].id != EMPTY {
                i = (i + 1) & self.mask;
            }
            self.slots[i] = Slot {
                tag: tag(key, h),
                id: s as u32,
            };
        }
    }

    fn bytes(&self) -> u64 {
        self.slots.len() as u64 * std::mem::size_of::<Slot>() as u64
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

/// Run the explicit engine within `budget`.
pub fn run(p: &Problem, budget: &Budget) -> Result<Explicit, Error> {
    let pk = Packing::new(p);
    let words = pk.words;
    let n_ev = p.events.len();
    let parts = participants(p);
    let uncontrollable: Vec<bool> = p.events.iter().map(|e| !e.controllable).collect();
    let needs_of: Vec<Vec<usize>> = (0..n_ev)
        .map(|e| {
            (0..p.needs.len())
                .filter(|&i| p.needs[i].event as usize == e)
                .collect()
        })
        .collect();
    let mut store: Vec<u64> = vec![0; words];
    pk.pack(&p.initial(), &mut store[..words]);
    let mut visited = Visited::new();
    visited.insert(&store, words, &store[..words], 0);
    let mut count = 1usize;
    let mut bad: Vec<bool> = Vec::new();
    let mut marked: Vec<bool> = Vec::new();
    let mut succ_off: Vec<u64> = vec![0];
    let mut succ: Vec<(EventId, u32)> = Vec::new();
    let mut locs = vec![0u32; p.automata.len()];
    let mut key = vec![0u64; words];
    let mut next = vec![0u64; words];
    let (masks, ew) = plant_masks(p);
    let mut en = vec![0u64; ew];
    let mut i = 0usize;
    while i < count {
        key.copy_from_slice(&store[i * words..(i + 1) * words]);
        pk.unpack(&key, &mut locs);
        let mut is_bad = p.is_forbidden(&locs);
        marked.push(p.is_marked(&locs));
        if !is_bad {
            // The events every plant allows here (one AND per plant and mask word), then
            // only those are tried.
            en.fill(u64::MAX);
            for (a, m) in &masks {
                let row = &m[locs[*a] as usize * ew..(locs[*a] as usize + 1) * ew];
                for (x, y) in en.iter_mut().zip(row) {
                    *x &= y;
                }
            }
            for e in EventBits::new(&en, n_ev) {
                let (mut plant_ok, mut req_ok) = (true, true);
                next.copy_from_slice(&key);
                for &(a, is_plant) in &parts[e] {
                    let aut = &p.automata[a];
                    let t = aut.next[locs[a] as usize * n_ev + e];
                    if t == NONE {
                        if is_plant {
                            plant_ok = false;
                            break;
                        }
                        req_ok = false;
                    } else {
                        pk.set(&mut next, a, t);
                    }
                }
                if !plant_ok {
                    continue;
                }
                if req_ok {
                    req_ok = needs_of[e].iter().all(|&k| p.needs[k].cond.eval(&locs));
                }
                if !req_ok {
                    if uncontrollable[e] {
                        is_bad = true;
                    }
                    continue;
                }
                if count >= u32::MAX as usize - 1 {
                    return Err(too_many(budget, count, &store, &succ, &visited));
                }
                let (id, new) = visited.insert(&store, words, &next, count as u32);
                if new {
                    store.extend_from_slice(&next);
                    count += 1;
                    visited.grow_if_needed(&store, words, count);
                }
                succ.push((e as EventId, id));
            }
        }
        bad.push(is_bad);
        succ_off.push(succ.len() as u64);
        i += 1;
        if i.is_multiple_of(4096) {
            check(budget, "reachability", count, &store, &succ, &visited)?;
        }
    }
    check(budget, "reachability", count, &store, &succ, &visited)?;
    let n = count;
    // Predecessor lists by counting.
    let mut pred_off = vec![0u64; n + 1];
    for &(_, t) in &succ {
        pred_off[t as usize + 1] += 1;
    }
    for k in 0..n {
        pred_off[k + 1] += pred_off[k];
    }
    let mut fill = pred_off.clone();
    let mut pred: Vec<(EventId, u32)> = vec![(0, 0); succ.len()];
    for s in 0..n {
        for &(e, t) in &succ[succ_off[s] as usize..succ_off[s + 1] as usize] {
            let at = &mut fill[t as usize];
            pred[*at as usize] = (e, s as u32);
            *at += 1;
        }
    }
    drop(fill);
    check(budget, "fixpoint", n, &store, &succ, &visited)?;
    drop(visited);
    let preds = |t: usize| &pred[pred_off[t] as usize..pred_off[t + 1] as usize];
    let mut alive: Vec<bool> = bad.iter().map(|b| !b).collect();
    let mut work: Vec<u32> = (0..n as u32).filter(|&s| bad[s as usize]).collect();
    let mut rounds = 0;
    let mut stack: Vec<u32> = Vec::new();
    let mut coreach = vec![false; n];
    loop {
        rounds += 1;
        // Controllability: a state with an uncontrollable edge into a removed state goes too.
        while let Some(t) = work.pop() {
            for &(e, s) in preds(t as usize) {
                if alive[s as usize] && uncontrollable[e as usize] {
                    alive[s as usize] = false;
                    work.push(s);
                }
            }
        }
        // Nonblocking: keep only states that reach a marked state through kept states.
        coreach.fill(false);
        stack.clear();
        for s in 0..n {
            if alive[s] && marked[s] {
                coreach[s] = true;
                stack.push(s as u32);
            }
        }
        while let Some(t) = stack.pop() {
            for &(_, s) in preds(t as usize) {
                if alive[s as usize] && !coreach[s as usize] {
                    coreach[s as usize] = true;
                    stack.push(s);
                }
            }
        }
        for s in 0..n {
            if alive[s] && !coreach[s] {
                alive[s] = false;
                work.push(s as u32);
            }
        }
        budget.check("fixpoint", n as f64, 0)?;
        if work.is_empty() {
            break;
        }
    }
    // Restrict to what is reachable from the initial state through kept states.
    let mut kept = vec![false; n];
    if alive[0] {
        kept[0] = true;
        stack.clear();
        stack.push(0);
        while let Some(s) = stack.pop() {
            for &(_, t) in &succ[succ_off[s as usize] as usize..succ_off[s as usize + 1] as usize] {
                if alive[t as usize] && !kept[t as usize] {
                    kept[t as usize] = true;
                    stack.push(t);
                }
            }
        }
    }
    Ok(Explicit {
        packing: pk,
        store,
        succ_off,
        succ,
        kept,
        product_states: n,
        rounds,
    })
}

/// The engine's data so far: the store, the edges twice (successors, then predecessors),
/// the visited table and per state two offsets and five flags.
fn bytes(store: &[u64], succ: &[(EventId, u32)], visited: &Visited, count: usize) -> u64 {
    store.len() as u64 * 8 + succ.len() as u64 * 16 + visited.bytes() + count as u64 * 21
}

fn check(
    budget: &Budget,
    phase: &'static str,
    count: usize,
    store: &[u64],
    succ: &[(EventId, u32)],
    visited: &Visited,
) -> Result<(), Error> {
    budget.check(phase, count as f64, bytes(store, succ, visited, count))
}

/// State numbers are 32-bit: past that the engine stops as at a state limit.
fn too_many(
    budget: &Budget,
    count: usize,
    store: &[u64],
    succ: &[(EventId, u32)],
    visited: &Visited,
) -> Error {
    let partial = crate::error::Partial {
        phase: "reachability",
        states: count as f64,
        seconds: budget.seconds(),
        bytes: bytes(store, succ, visited, count),
    };
    let limit = crate::error::Limit::States(count as u64);
    Error::new(crate::error::ErrorKind::Limit { limit, partial })
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
