//! The visited set: a fixed number of shards, each an open-addressing table of keys with
//! linear probing.
//!
//! No control bytes and no stored hashes: a slot is a key, [`Key::empty`] marks a free one.
//! Tables grow by 1.5× at a load of 0.8 and index by multiply-shift range reduction, so
//! capacities need not be powers of two; for 8-byte keys that keeps the set between 10 and 15
//! bytes per state. Shards let the threads insert in parallel (one shard per task); the shard of
//! a key depends only on its hash, so the order in which new states are found does not depend on
//! the number of threads. Keys are inserted in batches ([`Shard::insert_retain`]) that prefetch
//! the slot of a key a few places ahead, so that the cache misses of a large table overlap.

use crate::pack::Key;

/// Number of shards (a fixed constant so that results do not depend on the thread count).
pub const SHARDS: usize = 16;

/// The shard of a hash.
pub fn shard_of(hash: u64) -> usize {
    (hash >> 60) as usize
}

/// One open-addressing table.
pub struct Shard<K> {
    slots: Vec<K>,
    len: usize,
    heap: usize,
}

impl<K: Key> Default for Shard<K> {
    fn default() -> Self {
        Shard {
            slots: Vec::new(),
            len: 0,
            heap: 0,
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

    /// Insert the keys of `items` in order and keep only the items whose key was new (in
    /// their order), calling `on_new` on each of them as it is found. While inserting one
    /// key, the slot of the key [`AHEAD`] places later is prefetched, so that the cache misses
    /// of a large table overlap instead of following each other.
    pub fn insert_retain<T>(
        &mut self,
        items: &mut Vec<T>,
        key: impl Fn(&T) -> &K,
        mut on_new: impl FnMut(&T),
    ) {
        let n = items.len();
        // Hashes of the next `AHEAD` items, by position modulo `AHEAD`.
        let mut ring = [0u64; AHEAD];
        for (h, it) in ring.iter_mut().zip(items.iter()) {
            *h = key(it).hash64();
            prefetch(&self.slots, index(*h, self.slots.len()));
        }
        let mut kept = 0;
        for r in 0..n {
            let h = ring[r % AHEAD];
            if let Some(ahead) = items.get(r + AHEAD) {
                let ha = key(ahead).hash64();
                ring[r % AHEAD] = ha;
                prefetch(&self.slots, index(ha, self.slots.len()));
            }
            if self.insert(key(&items[r]), h) {
                on_new(&items[r]);
                items.swap(kept, r);
                kept += 1;
            }
        }
        items.truncate(kept);
    }

    /// True when `n` more keys would take the load past 0.8.
    #[inline]
    fn over_load(&self, n: usize) -> bool {
        (self.len + n) * 5 > self.slots.len() * 4
    }

    /// Insert without checking the load (there must be a free slot).
    #[inline]
    fn place(&mut self, key: &K, hash: u64) -> bool {
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

    fn grow(&mut self) {
        let cap = (self.slots.len() * 3 / 2).max(64);
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

/// How far ahead [`Shard::insert_retain`] prefetches.
const AHEAD: usize = 8;

/// Hint the processor to fetch `slots[i]` into the cache (nothing when out of range or not
/// on x86-64).
#[inline(always)]
fn prefetch<K>(slots: &[K], i: usize) {
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
    ((u128::from(hash << 4) * cap as u128) >> 64) as usize
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
        for k in (1..=100_000u64).step_by(7) {
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
        s.insert_retain(&mut first, |k| k, |k| seen.push(*k));
        assert_eq!(first, (1..=300).rev().collect::<Vec<_>>());
        assert_eq!(seen, first);
        // Duplicates within the batch and of earlier keys are dropped; the rest keep their order.
        let mut second: Vec<u64> = vec![5, 400, 7, 401, 400, 299, 402, 401];
        seen.clear();
        s.insert_retain(&mut second, |k| k, |k| seen.push(*k));
        assert_eq!(second, [400, 401, 402]);
        assert_eq!(seen, second);
        assert_eq!(s.len(), 303);
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
