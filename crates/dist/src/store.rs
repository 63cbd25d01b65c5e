//! One worker's visited set: its packed states in one arena, in the order found (so a layer is
//! a range of indices), each with the transition that found it, and a hash table of indices.

use hashbrown::HashTable;

/// The parent link of the initial state (no transition found it).
pub(crate) const ROOT: u32 = u32::MAX;

/// The transition that first found a state: the worker and index of its source, the position
/// of the input vector.
pub(crate) type Parent = [u32; 3];

/// A worker's stored states.
pub(crate) struct Store {
    words: usize,
    arena: Vec<u64>,
    parents: Vec<Parent>,
    table: HashTable<u32>,
}

/// The hash of a packed state, the same in every process (it decides the owner).
pub(crate) fn hash(words: &[u64]) -> u64 {
    let mut h = 0x243f_6a88_85a3_08d3u64;
    for &w in words {
        h = (h ^ w).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        h ^= h >> 29;
    }
    // splitmix64's finaliser.
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^ (h >> 31)
}

/// The worker owning a state of hash `h`, among `peers` (from the high half of the hash; the
/// table uses a remix, so a worker's states do not share their high bits there).
pub(crate) fn owner(h: u64, peers: usize) -> usize {
    (((h >> 32) * peers as u64) >> 32) as usize
}

/// The table's hash: `h` remixed.
fn table_hash(h: u64) -> u64 {
    h.wrapping_mul(0xd6e8_feb8_6659_fd93).rotate_left(32)
}

impl Store {
    /// An empty store for states of `words` words.
    pub fn new(words: usize) -> Store {
        Store {
            words,
            arena: Vec::new(),
            parents: Vec::new(),
            table: HashTable::new(),
        }
    }

    /// States stored.
    pub fn len(&self) -> usize {
        self.parents.len()
    }

    /// The state at `i`.
    pub fn state(&self, i: usize) -> &[u64] {
        &self.arena[i * self.words..(i + 1) * self.words]
    }

    /// The parent link of the state at `i`.
    pub fn parent(&self, i: usize) -> Option<Parent> {
        self.parents.get(i).copied()
    }

    /// Store `s` (with its hash `h`) found by `parent`, unless it is there already; true when
    /// it was new. False too when the store is full (`u32` indices): see [`Store::full`].
    pub fn insert(&mut self, s: &[u64], h: u64, parent: Parent) -> bool {
        let (arena, words) = (&self.arena, self.words);
        let at = |i: u32| &arena[i as usize * words..(i as usize + 1) * words];
        if self.table.find(table_hash(h), |&i| at(i) == s).is_some() || self.full() {
            return false;
        }
        let i = self.parents.len() as u32;
        self.arena.extend_from_slice(s);
        self.parents.push(parent);
        let (arena, words) = (&self.arena, self.words);
        self.table.insert_unique(table_hash(h), i, |&j| {
            let k = j as usize * words;
            table_hash(hash(&arena[k..k + words]))
        });
        true
    }

    /// Forget every state (keeping the memory).
    pub fn clear(&mut self) {
        self.arena.clear();
        self.parents.clear();
        self.table.clear();
    }

    /// True when no more states fit (indices are `u32`, the last one reserved).
    pub fn full(&self) -> bool {
        self.parents.len() >= (ROOT - 1) as usize
    }

    /// Bytes held: the arena, the parent links and the table (4-byte slots and a control byte).
    pub fn bytes(&self) -> u64 {
        (self.arena.capacity() * 8 + self.parents.capacity() * 12 + self.table.capacity() * 5)
            as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stores_each_state_once_in_order() {
        let mut s = Store::new(2);
        let (a, b) = ([1u64, 2], [2u64, 1]);
        assert!(s.insert(&a, hash(&a), [ROOT; 3]));
        assert!(s.insert(&b, hash(&b), [0, 0, 7]));
        assert!(!s.insert(&a, hash(&a), [0, 1, 3]));
        assert_eq!(s.len(), 2);
        assert_eq!(s.state(1), &b);
        assert_eq!(s.parent(1), Some([0, 0, 7]));
        // Many states: the table grows and finds every one again.
        for i in 0..10_000u64 {
            let x = [i, i * 3];
            s.insert(&x, hash(&x), [0, 0, 0]);
        }
        for i in 0..10_000u64 {
            let x = [i, i * 3];
            assert!(!s.insert(&x, hash(&x), [0, 0, 0]));
        }
        // [i, 3i] is never a = [1, 2] nor b = [2, 1]: 2 + 10,000 states.
        assert_eq!(s.len(), 10_002);
    }

    #[test]
    fn owners_spread_over_peers() {
        let mut count = [0usize; 3];
        for i in 0..3000u64 {
            count[owner(hash(&[i]), 3)] += 1;
        }
        // Each of 3 workers gets a third, give or take 10%.
        assert!(
            count.iter().all(|&c| (900..=1100).contains(&c)),
            "{count:?}"
        );
    }
}
