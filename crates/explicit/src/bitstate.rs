//! Bitstate hashing of the visited set (`verify --bitstate SIZE`), after SPIN's supertrace
//! (Holzmann's bitstate hashing, `pan -DBITSTATE -k3`).
//!
//! A state is not stored: its 64-bit hash sets `k` bits of a fixed bit array (a Bloom
//! filter), and a state counts as visited when all its `k` bits are already set. The array's
//! size is chosen up front, so a search of any length fits in it; in exchange a state whose
//! bits were all set by other states is taken for visited and not explored (an *omission*),
//! and so may be states reachable only through it. So:
//!
//! - every state counted is a distinct reachable state (a state counted once has all its bits
//!   set and is never counted again), so the count is a lower bound of the reachable states;
//! - a violation found is real (its counterexample is rebuilt by the exact search of
//!   `trace.rs`);
//! - a search that runs out of states proves nothing: the properties it did not refute are
//!   `unknown`, with the estimated number of omitted states.
//!
//! The bit positions come from the state's hash by double hashing (Kirsch and Mitzenmacher):
//! `a + i·b` for `i < k`, with `a` the hash's bits below the shard bits and `b` an odd second
//! hash of it, each reduced to the shard's size by a multiply-shift. The array is cut into the
//! same shards as the exact set ([`crate::table::SHARDS`], chosen by the same top bits), so
//! that the threads set bits in parallel and the states found, their order and every result
//! do not depend on the thread count.

use crate::pack::{fmix, Key};
use crate::table::{prefetch, shard_of, HashedSet, SHARDS, SHARD_BITS};

/// The options of a bitstate search.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bitstate {
    /// Bytes of the bit array, all shards together.
    pub bytes: u64,
    /// Bits set per state (SPIN's `-k`; 3 by default).
    pub hashes: u32,
}

/// The default number of bits per state, as SPIN's.
pub const DEFAULT_HASHES: u32 = 3;

/// The most bits per state accepted (more only fills the array faster).
pub const MAX_HASHES: u32 = 32;

/// The statistics of a bitstate search.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BitstateStats {
    /// Bytes of the bit array.
    pub bytes: u64,
    /// Bits set per state.
    pub hashes: u32,
    /// Bits of the array set at the end.
    pub set_bits: u64,
    /// Fraction of the array set at the end.
    pub fill: f64,
    /// Bits of the array per state counted (SPIN's "hash factor"; above about 100 the
    /// omissions are few).
    pub bits_per_state: f64,
    /// Expected number of reachable states taken for visited without being so (each new state
    /// was missed with probability `fillᵏ` at the fill of its block), not counting the
    /// states reachable only through them.
    pub expected_omitted: f64,
}

/// An expected number of omitted states in words: `about 12.3`, `fewer than 0.01`.
pub fn about(expected: f64) -> String {
    if expected < 0.01 {
        "fewer than 0.01".to_string()
    } else {
        format!("about {expected:.1}")
    }
}

/// One shard of the bit array.
pub(crate) struct BitShard {
    words: Vec<u64>,
    bits: u64,
    set: u64,
    /// Bits set per state.
    hashes: u32,
}

impl BitShard {
    fn new(bits: u64, hashes: u32) -> BitShard {
        let bits = bits.max(64);
        BitShard {
            // Zeroed by the allocator (fresh pages): untouched parts cost no memory.
            words: vec![0; bits.div_ceil(64) as usize],
            bits,
            set: 0,
            hashes,
        }
    }

    /// The first position of `hash`'s bits, before reduction to the shard's size.
    #[inline(always)]
    fn first(hash: u64) -> u64 {
        hash << SHARD_BITS
    }

    /// The stride between `hash`'s bits: an odd second hash of it.
    #[inline(always)]
    fn stride(hash: u64) -> u64 {
        fmix(hash ^ 0x9e37_79b9_7f4a_7c15) | 1
    }

    /// Bit `x` reduced to the shard's size.
    #[inline(always)]
    fn reduce(&self, x: u64) -> u64 {
        ((u128::from(x) * u128::from(self.bits)) >> 64) as u64
    }

    /// Set the bits of `hash`; true when one of them was clear (the state is new).
    #[inline]
    fn insert(&mut self, hash: u64) -> bool {
        let (mut a, b) = (Self::first(hash), Self::stride(hash));
        let mut new = false;
        for _ in 0..self.hashes {
            let bit = self.reduce(a);
            let (w, m) = ((bit / 64) as usize, 1u64 << (bit % 64));
            if self.words[w] & m == 0 {
                self.words[w] |= m;
                self.set += 1;
                new = true;
            }
            a = a.wrapping_add(b);
        }
        new
    }
}

impl<K: Key> HashedSet<K> for BitShard {
    #[inline(always)]
    fn prefetch_hash(&self, hash: u64) {
        // The word of the first bit (the stride's hash is left to the insertion).
        let bit = self.reduce(Self::first(hash));
        prefetch(&self.words, (bit / 64) as usize);
    }
    #[inline(always)]
    fn batch_fits(&self, _: usize) -> bool {
        true
    }
    #[inline(always)]
    fn insert_hashed(&mut self, _: &K, hash: u64, _: bool) -> bool {
        self.insert(hash)
    }
}

/// The visited set of a bitstate search.
pub(crate) struct BitSet {
    /// The shards, indexed by [`shard_of`].
    pub shards: Vec<BitShard>,
    /// Bits set per state.
    pub hashes: u32,
    /// Expected omissions so far ([`BitstateStats::expected_omitted`]).
    omitted: f64,
}

impl BitSet {
    /// An empty array of `b.bytes` bytes (at least 8 per shard).
    pub fn new(b: Bitstate) -> BitSet {
        let per_shard = (b.bytes.saturating_mul(8) / SHARDS as u64).max(64);
        let hashes = b.hashes.clamp(1, MAX_HASHES);
        BitSet {
            shards: (0..SHARDS)
                .map(|_| BitShard::new(per_shard, hashes))
                .collect(),
            hashes,
            omitted: 0.0,
        }
    }

    /// Insert one key (single-threaded use); true when it is taken for new.
    pub fn insert<K: Key>(&mut self, key: &K) -> bool {
        let h = key.hash64();
        self.shards[shard_of(h)].insert(h)
    }

    /// Bits of the array.
    pub fn bits(&self) -> u64 {
        self.shards.iter().map(|s| s.bits).sum()
    }

    /// Bytes of the array.
    pub fn bytes(&self) -> usize {
        self.shards.iter().map(|s| s.words.len() * 8).sum()
    }

    /// Account for `fresh` states just taken for new: each truly new state was missed with
    /// probability `fillᵏ`, so about `fresh · fillᵏ / (1 − fillᵏ)` were.
    pub fn note_block(&mut self, fresh: u64) {
        let p = self.fill().powi(self.hashes as i32);
        if p < 1.0 {
            self.omitted += fresh as f64 * p / (1.0 - p);
        } else if fresh > 0 {
            self.omitted = f64::INFINITY;
        }
    }

    /// Fraction of the array set.
    pub fn fill(&self) -> f64 {
        let set: u64 = self.shards.iter().map(|s| s.set).sum();
        set as f64 / self.bits().max(1) as f64
    }

    /// The statistics at the end of a search that counted `states` states.
    pub fn stats(&self, states: u64) -> BitstateStats {
        let set_bits = self.shards.iter().map(|s| s.set).sum();
        BitstateStats {
            bytes: self.bytes() as u64,
            hashes: self.hashes,
            set_bits,
            fill: self.fill(),
            bits_per_state: self.bits() as f64 / states.max(1) as f64,
            expected_omitted: self.omitted,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_state_is_new_once_and_a_full_array_takes_everything_for_visited() {
        let mut b = BitSet::new(Bitstate {
            bytes: 1 << 16,
            hashes: 3,
        });
        // 1000 distinct keys in an array of 2^19 bits: at most 3000 bits set, so a key's
        // three bits are all set by others with probability below (3000/2^19)^3 ≈ 2e-7.
        let news = (1u64..=1000).filter(|k| b.insert(k)).count();
        assert_eq!(news, 1000);
        assert!((1u64..=1000).all(|k| !b.insert(&k)), "inserted twice");
        let s = b.stats(1000);
        assert!(s.set_bits <= 3000 && s.set_bits > 2900, "{s:?}");
        // The smallest array: 64 bits per shard, 4096 bits; 100 000 keys fill it, and then
        // every key reads as visited.
        let mut tiny = BitSet::new(Bitstate {
            bytes: 1,
            hashes: 3,
        });
        let counted = (1u64..=100_000).filter(|k| tiny.insert(k)).count();
        assert!(counted < 100_000, "a full array must omit keys");
        assert_eq!(tiny.fill(), 1.0);
        assert!(!tiny.insert(&200_000u64));
        tiny.note_block(1);
        assert_eq!(tiny.stats(1).expected_omitted, f64::INFINITY);
    }
}
