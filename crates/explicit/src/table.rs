//! The visited set: a fixed number of shards, each an open-addressing table of keys with
//! linear probing.
//!
//! No control bytes and no stored hashes: a slot is a key, [`Key::empty`] marks a free one.
//! Tables grow at a load of 0.8, by 2× for 4-byte keys and 1.5× for larger ones, and index by
//! multiply-shift range reduction, so capacities need not be powers of two; that keeps the set
//! between 5 and 10 bytes per state for 4-byte keys, and between 10 and 15 for 8-byte keys. Large tables grow in place (a reallocation, then every key moved to its new
//! place), so that growing does not touch fresh memory for the part already in use.
//!
//! Shards let the threads insert in parallel (one shard per task); the shard of a key depends
//! only on its hash, so the order in which new states are found does not depend on the number
//! of threads. Keys are inserted in batches ([`insert_retain`]) that prefetch the slot of
//! a key a few places ahead, so that the cache misses of a large table overlap.

use crate::pack::Key;

/// Bits of a hash that choose its shard (the top ones).
pub(crate) const SHARD_BITS: u32 = 6;

/// Number of shards (a fixed constant so that results do not depend on the thread count).
/// 64 shards keep the table of each small enough to stay in a core's cache while a batch of
/// keys is inserted into it.
pub const SHARDS: usize = 1 << SHARD_BITS;

/// The shard of a hash.
pub fn shard_of(hash: u64) -> usize {
    (hash >> (64 - SHARD_BITS)) as usize
}

/// One open-addressing table.
pub struct Shard<K> {
    slots: Vec<K>,
    len: usize,
    heap: usize,
    /// Whether the key equal to [`Key::empty`] is stored: a real key only for 64-bit vectors
    /// of all ones in `u64` keys (see `pack.rs`), kept here since a slot holding it would read
    /// as free.
    holds_empty: bool,
}

impl<K: Key> Default for Shard<K> {
    fn default() -> Self {
        Shard {
            slots: Vec::new(),
            len: 0,
            heap: 0,
            holds_empty: false,
        }
    }
}

impl<K: Key> Shard<K> {
    /// Insert a key with its hash; true when it was not there before (the key is cloned
    /// only then).
    #[inline]
    pub fn insert(&mut self, key: &K, hash: u64) -> bool {
        if self.over_load(1) {
            self.grow();
        }
        self.place(key, hash)
    }

    /// True when `n` more keys would take the load past 0.8.
    #[inline]
    fn over_load(&self, n: usize) -> bool {
        (self.len + n) * 5 > self.slots.len() * 4
    }

    /// Insert the key equal to [`Key::empty`] (out of the slots).
    #[cold]
    fn place_empty(&mut self) -> bool {
        if self.holds_empty {
            return false;
        }
        self.holds_empty = true;
        self.len += 1;
        true
    }

    /// Insert without checking the load (there must be a free slot).
    #[inline]
    fn place(&mut self, key: &K, hash: u64) -> bool {
        if key.is_empty() {
            return self.place_empty();
        }
        let cap = self.slots.len();
        let mut i = index(hash, cap);
        // Linear probing, wrapping at the end; the load factor keeps free slots, so the loop
        // ends at the key or at a free slot.
        loop {
            let slot = &mut self.slots[i];
            if slot.is_empty() {
                *slot = key.clone();
                self.heap += key.heap_bytes();
                self.len += 1;
                return true;
            }
            if slot == key {
                return false;
            }
            i += 1;
            if i == cap {
                i = 0;
            }
        }
    }

    /// Grow by 1.5×: small tables into a fresh one, large ones in place.
    #[cold]
    #[inline(never)]
    fn grow(&mut self) {
        // Small keys can afford doubling (fewer rehashes) within 16 bytes per state.
        let cap = if std::mem::size_of::<K>() <= 4 {
            self.slots.len() * 2
        } else {
            self.slots.len() * 3 / 2
        }
        .max(64);
        if self.slots.len() * std::mem::size_of::<K>() < IN_PLACE_BYTES {
            self.grow_by_copy(cap);
        } else {
            self.grow_in_place(cap);
        }
    }

    /// Move every key into a fresh table of `cap` slots.
    fn grow_by_copy(&mut self, cap: usize) {
        let old = std::mem::replace(&mut self.slots, vec![K::empty(); cap]);
        for k in old {
            if k.is_empty() {
                continue;
            }
            let mut i = index(k.hash64(), cap);
            while !self.slots[i].is_empty() {
                i += 1;
                if i == cap {
                    i = 0;
                }
            }
            self.slots[i] = k;
        }
    }

    /// Grow to `cap` slots in place: the slots are reallocated (which keeps the pages already
    /// in use, where a fresh table would take a page fault on every page again) and every key
    /// is moved to its place in the larger table.
    fn grow_in_place(&mut self, cap: usize) {
        let old_cap = self.slots.len();
        self.slots.reserve_exact(cap - old_cap);
        self.slots.resize(cap, K::empty());
        // Keys are moved from the end backwards. When the key at `p` moves, every key above
        // `p` is at its final place (a key's new place is about 1.5× its old one), so there a
        // slot is free when empty; at `p` and below, `done` marks the final places taken
        // (rare: wrapping around, or far from home) and a key not yet moved is displaced to
        // move on in turn.
        let mut done = Bits::new(old_cap);
        let mut low = false;
        for p in (0..old_cap).rev() {
            if self.slots[p].is_empty() || (low && done.get(p)) {
                continue;
            }
            let mut k = std::mem::replace(&mut self.slots[p], K::empty());
            loop {
                let mut i = index(k.hash64(), cap);
                while taken(&self.slots, &done, p, i) {
                    i += 1;
                    if i == cap {
                        i = 0;
                    }
                }
                if i <= p {
                    done.set(i);
                    low = true;
                }
                k = std::mem::replace(&mut self.slots[i], k);
                if k.is_empty() {
                    break;
                }
            }
        }
    }

    /// The keys stored in the slots (the key equal to [`Key::empty`], if stored, is not
    /// among them: it can only be a 64-bit key, which collapse compression never converts).
    pub fn keys(&self) -> impl Iterator<Item = &K> {
        self.slots.iter().filter(|k| !k.is_empty())
    }

    /// Bytes held by this shard.
    pub fn bytes(&self) -> usize {
        self.slots.len() * std::mem::size_of::<K>() + self.heap
    }

    /// Keys stored.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when nothing is stored.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

/// While [`Shard::grow_in_place`] moves the key from `p`: true when slot `i` holds a key at
/// its final place.
#[inline]
fn taken<K: Key>(slots: &[K], done: &Bits, p: usize, i: usize) -> bool {
    if i > p {
        !slots[i].is_empty()
    } else {
        done.get(i)
    }
}

/// A fixed-size bit set.
struct Bits(Vec<u64>);

impl Bits {
    fn new(n: usize) -> Bits {
        Bits(vec![0; n.div_ceil(64)])
    }

    #[inline]
    fn get(&self, i: usize) -> bool {
        (self.0[i / 64] >> (i % 64)) & 1 != 0
    }

    #[inline]
    fn set(&mut self, i: usize) {
        self.0[i / 64] |= 1 << (i % 64);
    }
}

/// Tables of at least this many bytes grow in place ([`Shard::grow_in_place`]); smaller ones,
/// which the allocator serves from memory it already holds, are copied (fewer instructions).
const IN_PLACE_BYTES: usize = 128 << 10;

/// How far ahead [`insert_retain`] prefetches.
const AHEAD: usize = 8;

/// A set that stores keys by their hash: the exact [`Shard`], or a shard of a bitstate array
/// (`bitstate.rs`). What [`insert_retain`] needs of it.
pub(crate) trait HashedSet<K> {
    /// Hint the processor to fetch the memory where `hash` goes.
    fn prefetch_hash(&self, hash: u64);
    /// True when `n` more keys fit without the set growing (none of them then checks).
    fn batch_fits(&self, n: usize) -> bool;
    /// Insert `key` with its `hash`, growing first if needed unless the batch `fits`; true
    /// when it was new.
    fn insert_hashed(&mut self, key: &K, hash: u64, fits: bool) -> bool;
}

impl<K: Key> HashedSet<K> for Shard<K> {
    #[inline(always)]
    fn prefetch_hash(&self, hash: u64) {
        prefetch(&self.slots, index(hash, self.slots.len()));
    }
    #[inline(always)]
    fn batch_fits(&self, n: usize) -> bool {
        !self.over_load(n)
    }
    #[inline(always)]
    fn insert_hashed(&mut self, key: &K, hash: u64, fits: bool) -> bool {
        if !fits && self.over_load(1) {
            self.grow();
        }
        self.place(key, hash)
    }
}

/// Insert the keys of `items` into `set` in order and keep only the items whose key was new
/// (in their order), calling `on_new` on each of them as it is found. While inserting one
/// key, the place of the key [`AHEAD`] places later is prefetched, so that the cache misses
/// of a large set overlap instead of following each other.
#[inline(always)]
pub(crate) fn insert_retain<K: Key, S: HashedSet<K>, T>(
    set: &mut S,
    items: &mut Vec<T>,
    key: impl Fn(&T) -> &K,
    mut on_new: impl FnMut(&T),
) {
    let n = items.len();
    // Hashes of the next `AHEAD` items, by position modulo `AHEAD`.
    let mut ring = [0u64; AHEAD];
    for (h, it) in ring.iter_mut().zip(items.iter()) {
        *h = key(it).hash64();
        set.prefetch_hash(*h);
    }
    let fits = set.batch_fits(n);
    let mut kept = 0;
    for r in 0..n {
        let h = ring[r % AHEAD];
        if let Some(ahead) = items.get(r + AHEAD) {
            let ha = key(ahead).hash64();
            ring[r % AHEAD] = ha;
            set.prefetch_hash(ha);
        }
        if set.insert_hashed(key(&items[r]), h, fits) {
            on_new(&items[r]);
            items.swap(kept, r);
            kept += 1;
        }
    }
    items.truncate(kept);
}

/// Hint the processor to fetch `slots[i]` into the cache (nothing when out of range or not
/// on x86-64).
#[inline(always)]
pub(crate) fn prefetch<K>(slots: &[K], i: usize) {
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (slots, i);
    #[cfg(target_arch = "x86_64")]
    if let Some(s) = slots.get(i) {
        let p: *const K = s;
        // The prefetch intrinsic is `unsafe` only because it is a `target_feature` function
        // (SSE, always present on x86-64); it never faults, whatever the address, and here
        // the address is that of an element of `slots`.
        #[allow(unsafe_code)]
        unsafe {
            core::arch::x86_64::_mm_prefetch::<{ core::arch::x86_64::_MM_HINT_T0 }>(p.cast());
        }
    }
}

/// Slot of a hash in a table of `cap` slots; the top bits choose the shard, so use the rest.
fn index(hash: u64, cap: usize) -> usize {
    ((u128::from(hash << SHARD_BITS) * cap as u128) >> 64) as usize
}

/// The sharded visited set.
pub struct Visited<K> {
    /// The shards, indexed by [`shard_of`].
    pub shards: Vec<Shard<K>>,
}

impl<K: Key> Default for Visited<K> {
    fn default() -> Self {
        Self::new()
    }
}

impl<K: Key> Visited<K> {
    /// An empty set.
    pub fn new() -> Self {
        Visited {
            shards: (0..SHARDS).map(|_| Shard::default()).collect(),
        }
    }

    /// Insert a key (single-threaded use).
    pub fn insert(&mut self, key: &K) -> bool {
        let h = key.hash64();
        self.shards[shard_of(h)].insert(key, h)
    }

    /// Keys stored.
    pub fn len(&self) -> usize {
        self.shards.iter().map(Shard::len).sum()
    }

    /// True when nothing is stored.
    pub fn is_empty(&self) -> bool {
        self.shards.iter().all(Shard::is_empty)
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.shards.iter().map(Shard::bytes).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inserts_and_deduplicates() {
        let mut v: Visited<u64> = Visited::new();
        for k in 1..=100_000u64 {
            assert!(v.insert(&k));
        }
        for k in 1..=100_000u64 {
            assert!(!v.insert(&k));
        }
        assert_eq!(v.len(), 100_000);
        let per = v.bytes() as f64 / v.len() as f64;
        assert!(per <= 16.0, "{per} bytes per key");
    }

    #[test]
    fn insert_retain_keeps_the_new_items_in_order() {
        let mut s: Shard<u64> = Shard::default();
        let mut first: Vec<u64> = (1..=300).rev().collect();
        let mut seen = Vec::new();
        insert_retain(&mut s, &mut first, |k| k, |k| seen.push(*k));
        assert_eq!(first, (1..=300).rev().collect::<Vec<_>>());
        assert_eq!(seen, first);
        // Duplicates within the batch and of earlier keys are dropped; the rest keep their order.
        let mut second: Vec<u64> = vec![5, 400, 7, 401, 400, 299, 402, 401];
        seen.clear();
        insert_retain(&mut s, &mut second, |k| k, |k| seen.push(*k));
        assert_eq!(second, [400, 401, 402]);
        assert_eq!(seen, second);
        assert_eq!(s.len(), 303);
    }

    #[test]
    fn large_tables_grow_in_place() {
        // One shard, far past the size where growing switches to in place.
        let mut s: Shard<u64> = Shard::default();
        let n = 200_000u64;
        for k in 1..=n {
            assert!(s.insert(&k, k.hash64()));
        }
        assert!(s.bytes() > 4 * IN_PLACE_BYTES);
        for k in 1..=n {
            assert!(!s.insert(&k, k.hash64()));
        }
        assert_eq!(s.len(), n as usize);
        let mut b: Shard<Box<[u64]>> = Shard::default();
        for k in 0..30_000u64 {
            let key: Box<[u64]> = vec![k, !k].into();
            assert!(b.insert(&key, key.hash64()));
        }
        for k in 0..30_000u64 {
            let key: Box<[u64]> = vec![k, !k].into();
            assert!(!b.insert(&key, key.hash64()));
        }
        assert_eq!(b.len(), 30_000);
    }

    #[test]
    fn the_key_that_marks_free_slots_is_stored_too() {
        // `u64` keys of 64-bit vectors: the all-ones vector's key is 0, the free-slot mark.
        let mut v: Visited<u64> = Visited::new();
        assert!(v.insert(&0));
        assert!(v.insert(&5));
        assert!(!v.insert(&0));
        for k in 1..=1000u64 {
            v.insert(&k);
        }
        assert!(!v.insert(&0));
        assert_eq!(v.len(), 1001);
    }

    #[test]
    fn boxed_keys() {
        let mut v: Visited<Box<[u64]>> = Visited::new();
        for k in 0..1000u64 {
            assert!(v.insert(&vec![k, k * 3, 7].into()));
        }
        assert!(!v.insert(&vec![5, 15, 7].into()));
        assert_eq!(v.len(), 1000);
    }
}
