//! The visited set: a fixed number of shards, each an open-addressing table of keys with
//! linear probing.
//!
//! No control bytes and no stored hashes: a slot is a key, [`Key::empty`] marks a free one.
//! Tables grow by 1.5× at a load of 0.8 and index by multiply-shift range reduction, so
//! capacities need not be powers of two; for 8-byte keys that keeps the set between 10 and 15
//! bytes per state. Shards let the threads insert in parallel (one shard per task); the shard of
//! a key depends only on its hash, so the order in which new states are found does not depend on
//! the number of threads.

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
        if (self.len + 1) * 5 > self.slots.len() * 4 {
            self.grow();
        }
        let start = index(hash, self.slots.len());
        // Linear probing: from the hash's slot to the end, then from the start (the table is
        // never full, so one of the two finds the key or a free slot).
        let hit = |s: &K| s.is_empty() || s == key;
        let (head, tail) = self.slots.split_at_mut(start);
        let Some(slot) = tail
            .iter_mut()
            .find(|s| hit(s))
            .or_else(|| head.iter_mut().find(|s| hit(s)))
        else {
            // Not reached: the load factor keeps free slots. Growing makes room anyway.
            self.grow();
            return self.insert(key, hash);
        };
        if !slot.is_empty() {
            return false;
        }
        *slot = key.clone();
        self.heap += key.heap_bytes();
        self.len += 1;
        true
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
    fn boxed_keys() {
        let mut v: Visited<Box<[u64]>> = Visited::new();
        for k in 0..1000u64 {
            assert!(v.insert(&vec![k, k * 3, 7].into()));
        }
        assert!(!v.insert(&vec![5, 15, 7].into()));
        assert_eq!(v.len(), 1000);
    }
}
