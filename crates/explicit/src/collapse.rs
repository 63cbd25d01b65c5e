//! Collapse compression of the visited set (`verify --collapse`), after SPIN's COLLAPSE mode
//! and the two-level case of LTSmin's tree database.
//!
//! A packed state of more than two words is cut into two leaves of whole words (the low
//! half and the high half of its bits). Each leaf table numbers the distinct values of its
//! half, from 1 in the order they are first seen, and the visited set stores the pair of
//! numbers as one `u64` root instead of the state (the numbers from 1 keep a root from being
//! 0, the empty slot). Two states are equal exactly when both halves are, so the set holds the
//! same states as the plain one; it pays when far fewer distinct halves than states occur,
//! which is the rule for closed loops, where a half (say the plant and the bus) combines with
//! many values of the other (the controller). On master + 1 FAM, about a fifth as many
//! distinct halves as states within 70 ticks, and fewer the deeper the search goes.
//!
//! A root goes to the shard of its state's full key (known before the leaves are numbered),
//! whichever way the state is inserted.
//!
//! The two leaf tables are filled in parallel (one thread each), each in a fixed order of the
//! block's successors, so their numbering, and hence every result, does not depend on the
//! thread count.

use crate::expand::Cand;
use crate::pack::Key;
use crate::table::{shard_of, Visited};

/// Leaf numbers are `u32`; a table this full is refused (a memory limit in practice: it
/// would take tens of gigabytes first).
const MAX_LEAVES: u32 = u32::MAX - 1;

/// The visited set of a collapse-compressed search.
pub(crate) struct Collapsed {
    /// Roots: a state's two leaf numbers, `low | high << 32`.
    pub roots: Visited<u64>,
    /// The low and the high leaf table.
    leaves: [Leaves; 2],
    /// Words of a packed state.
    words: usize,
    /// Words of the low leaf (the high leaf has the rest).
    split: usize,
}

/// More distinct leaf values than a `u32` numbers.
#[derive(Debug)]
pub(crate) struct Full;

impl Collapsed {
    /// A set for packed states of `words` words (at least 2).
    pub fn new(words: usize) -> Collapsed {
        let split = words.div_ceil(2);
        Collapsed {
            roots: Visited::new(),
            leaves: [Leaves::new(split), Leaves::new(words - split)],
            words,
            split,
        }
    }

    /// Insert one state (single-threaded use); true when it is new.
    pub fn insert<K: Key>(&mut self, key: &K) -> Result<bool, Full> {
        let mut w = vec![0u64; self.words];
        self.insert_with(key, &mut w)
    }

    /// [`Collapsed::insert`] with a scratch vector of `words` words.
    fn insert_with<K: Key>(&mut self, key: &K, w: &mut [u64]) -> Result<bool, Full> {
        key.to_words(w);
        let lo = self.leaves[0].intern(&w[..self.split])?;
        let hi = self.leaves[1].intern(&w[self.split..])?;
        // The shard of the full key, as for a block's candidates (`search.rs`).
        let r = root(lo, hi);
        Ok(self.roots.shards[shard_of(key.hash64())].insert(&r, r.hash64()))
    }

    /// The compressed set of the states of a plain one, which is consumed shard by shard (so
    /// that at most one plain shard is held beside the compressed set).
    pub fn from_plain<K: Key>(words: usize, mut plain: Visited<K>) -> Result<Collapsed, Full> {
        let mut c = Collapsed::new(words);
        let mut w = vec![0u64; words];
        for shard in &mut plain.shards {
            for key in std::mem::take(shard).keys() {
                c.insert_with(key, &mut w)?;
            }
        }
        Ok(c)
    }

    /// The root of every candidate of a block, in the same nesting (shard, bucket, position).
    /// New leaf values are numbered as they are met in that order, the two leaves in parallel.
    pub fn roots_of<K: Key>(
        &mut self,
        per_shard: &[Vec<Vec<Cand<K>>>],
    ) -> Result<Vec<Vec<Vec<u64>>>, Full> {
        let (words, split) = (self.words, self.split);
        let [low, high] = &mut self.leaves;
        let number = |leaf: &mut Leaves, part: std::ops::Range<usize>| {
            let mut w = vec![0u64; words];
            let mut out = Vec::new();
            for c in per_shard.iter().flatten().flatten() {
                c.key.to_words(&mut w);
                out.push(leaf.intern(&w[part.clone()])?);
            }
            Ok::<_, Full>(out)
        };
        let (lo, hi) = rayon::join(|| number(low, 0..split), || number(high, split..words));
        let (lo, hi) = (lo?, hi?);
        let mut at = 0;
        Ok(per_shard
            .iter()
            .map(|buckets| {
                buckets
                    .iter()
                    .map(|b| {
                        let r = (at..at + b.len()).map(|i| root(lo[i], hi[i])).collect();
                        at += b.len();
                        r
                    })
                    .collect()
            })
            .collect())
    }

    /// Bytes held: the roots and both leaf tables.
    pub fn bytes(&self) -> usize {
        self.roots.bytes() + self.leaves.iter().map(Leaves::bytes).sum::<usize>()
    }

    /// Distinct values of the low and the high leaf.
    pub fn leaf_counts(&self) -> Vec<u64> {
        self.leaves.iter().map(|l| u64::from(l.len)).collect()
    }
}

/// A root: two leaf numbers (both from 1, so never 0).
fn root(lo: u32, hi: u32) -> u64 {
    u64::from(lo) | (u64::from(hi) << 32)
}

/// One leaf table: open addressing with linear probing over `width`-word values, each with
/// its number (0 marks a free slot).
struct Leaves {
    width: usize,
    values: Vec<u64>,
    numbers: Vec<u32>,
    len: u32,
}

impl Leaves {
    fn new(width: usize) -> Leaves {
        Leaves {
            width,
            values: Vec::new(),
            numbers: Vec::new(),
            len: 0,
        }
    }

    /// The number of `v`, given the next one when `v` is new.
    #[inline]
    fn intern(&mut self, v: &[u64]) -> Result<u32, Full> {
        if (self.len as usize + 1) * 5 > self.numbers.len() * 4 {
            self.grow();
        }
        let cap = self.numbers.len();
        let w = self.width;
        let mut i = slot(hash(v), cap);
        loop {
            let n = self.numbers[i];
            if n == 0 {
                if self.len >= MAX_LEAVES {
                    return Err(Full);
                }
                self.len += 1;
                self.numbers[i] = self.len;
                self.values[i * w..(i + 1) * w].copy_from_slice(v);
                return Ok(self.len);
            }
            if &self.values[i * w..(i + 1) * w] == v {
                return Ok(n);
            }
            i += 1;
            if i == cap {
                i = 0;
            }
        }
    }

    /// Grow the table by half and place every value again (by half, not double: a large
    /// table then sits between loads 0.53 and 0.8, and growing holds 2.5 times the old size
    /// at once, not 3).
    #[cold]
    fn grow(&mut self) {
        let cap = (self.numbers.len() * 3 / 2).max(1024);
        let w = self.width;
        let values = std::mem::replace(&mut self.values, vec![0; cap * w]);
        let numbers = std::mem::replace(&mut self.numbers, vec![0; cap]);
        for (k, &n) in numbers.iter().enumerate() {
            if n == 0 {
                continue;
            }
            let v = &values[k * w..(k + 1) * w];
            let mut i = slot(hash(v), cap);
            while self.numbers[i] != 0 {
                i += 1;
                if i == cap {
                    i = 0;
                }
            }
            self.numbers[i] = n;
            self.values[i * w..(i + 1) * w].copy_from_slice(v);
        }
    }

    fn bytes(&self) -> usize {
        self.values.len() * 8 + self.numbers.len() * 4
    }
}

/// A well-mixed hash of a leaf value (the packed words of a state part).
fn hash(v: &[u64]) -> u64 {
    v.iter()
        .fold(0x243f_6a88_85a3_08d3, |h, &w| crate::pack::fmix(h ^ w))
}

/// Slot of a hash in a table of `cap` slots (multiply-shift range reduction).
fn slot(h: u64, cap: usize) -> usize {
    ((u128::from(h) * cap as u128) >> 64) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_states_get_equal_roots_and_distinct_states_distinct_ones() {
        // Every 3-word state (a, b, c) with a, c in 0..20 and b in 0..3: 1 200 states, 60
        // distinct low halves (a, b) and 20 high ones (c).
        let mut set = Collapsed::new(3);
        for round in 0..2 {
            for a in 0..20u64 {
                for b in 0..3u64 {
                    for c in 0..20u64 {
                        let new = set.insert(&[a, b, c]).map_err(|_| "full");
                        assert_eq!(new, Ok(round == 0), "({a}, {b}, {c}) in round {round}");
                    }
                }
            }
        }
        assert_eq!(set.roots.len(), 1200);
        assert_eq!(set.leaf_counts(), vec![60, 20]);
    }

    #[test]
    fn a_plain_set_converts_to_the_same_states() {
        let key = |k: u64| [k % 70, 0, k / 70, 9];
        let mut plain: Visited<[u64; 4]> = Visited::new();
        for k in 0..5_000u64 {
            plain.insert(&key(k));
        }
        let Ok(mut c) = Collapsed::from_plain(4, plain) else {
            panic!("5 000 states fit")
        };
        assert_eq!(c.roots.len(), 5_000);
        // Low halves (k % 70, 0): 70 of them; high ones (k / 70, 9): k / 70 in 0..=71.
        assert_eq!(c.leaf_counts(), vec![70, 72]);
        for k in 0..5_000u64 {
            assert_eq!(c.insert(&key(k)).ok(), Some(false));
        }
        assert_eq!(c.insert(&key(5_000)).ok(), Some(true));
    }

    #[test]
    fn leaf_tables_grow_and_keep_their_numbers() {
        let mut l = Leaves::new(2);
        let numbers: Vec<u32> = (0..50_000u64)
            .map(|k| l.intern(&[k, k * 7]).unwrap_or(0))
            .collect();
        assert_eq!(numbers, (1..=50_000).collect::<Vec<u32>>());
        for k in (0..50_000u64).rev() {
            assert_eq!(l.intern(&[k, k * 7]).ok(), Some(k as u32 + 1));
        }
    }
}
