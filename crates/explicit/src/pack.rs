//! Bit-packed state vectors: every state slot stored as `value - lo` in `width()` bits.
//!
//! A packed vector is a little sequence of 64-bit words; [`Key`] turns it into the value the
//! visited set stores: a `u64` for vectors of up to 63 bits, a `u128` up to 127 bits, a boxed
//! word slice beyond. The two integer keys store `packed + 1` so that 0 can mark an empty slot
//! of the hash table.

use statecheck_ir::Program;

/// Where one state slot lives in a packed vector.
#[derive(Clone, Copy, Debug)]
struct Field {
    lo: i64,
    width: u32,
    offset: u32,
}

/// Packs and unpacks the persistent state of a program.
#[derive(Clone, Debug)]
pub struct Packer {
    fields: Vec<Field>,
    /// Total bits of a packed vector.
    pub bits: u32,
    /// 64-bit words of a packed vector.
    pub words: usize,
}

impl Packer {
    /// The packing of `program`'s state slots, in slot order.
    pub fn new(program: &Program) -> Packer {
        let mut offset = 0u32;
        let fields = program
            .state_slots()
            .iter()
            .map(|s| {
                let f = Field {
                    lo: s.lo,
                    width: s.width(),
                    offset,
                };
                offset += f.width;
                f
            })
            .collect();
        Packer {
            fields,
            bits: offset,
            words: (offset as usize).div_ceil(64).max(1),
        }
    }

    /// Pack `state` (the first `n_state` slot values) into `out` (`self.words` words).
    pub fn pack_words(&self, state: &[i64], out: &mut [u64]) {
        out.iter_mut().for_each(|w| *w = 0);
        for (f, &v) in self.fields.iter().zip(state) {
            if f.width == 0 {
                continue;
            }
            let x = (v.wrapping_sub(f.lo) as u64) & mask(f.width);
            let word = (f.offset / 64) as usize;
            let sh = f.offset % 64;
            out[word] |= x << sh;
            if sh + f.width > 64 {
                out[word + 1] |= x >> (64 - sh);
            }
        }
    }

    /// Unpack `words` into `state`.
    pub fn unpack_words(&self, words: &[u64], state: &mut [i64]) {
        for (f, v) in self.fields.iter().zip(state.iter_mut()) {
            if f.width == 0 {
                *v = f.lo;
                continue;
            }
            let word = (f.offset / 64) as usize;
            let sh = f.offset % 64;
            let mut x = words[word] >> sh;
            if sh + f.width > 64 {
                x |= words[word + 1] << (64 - sh);
            }
            *v = f.lo.wrapping_add((x & mask(f.width)) as i64);
        }
    }

    /// Pack a state into a key.
    pub fn pack<K: Key>(&self, state: &[i64], scratch: &mut [u64]) -> K {
        self.pack_words(state, scratch);
        K::from_words(scratch)
    }

    /// Unpack a key into a state.
    pub fn unpack<K: Key>(&self, key: &K, scratch: &mut [u64], state: &mut [i64]) {
        key.to_words(scratch);
        self.unpack_words(scratch, state);
    }
}

fn mask(width: u32) -> u64 {
    if width >= 64 {
        u64::MAX
    } else {
        (1u64 << width) - 1
    }
}

/// A packed state as stored in the visited set.
pub trait Key: Clone + Eq + Send + Sync + 'static {
    /// The key of a packed vector.
    fn from_words(words: &[u64]) -> Self;
    /// The packed vector of a key.
    fn to_words(&self, words: &mut [u64]);
    /// A well-mixed 64-bit hash.
    fn hash64(&self) -> u64;
    /// The value marking an empty table slot (never a real key).
    fn empty() -> Self;
    /// True for [`Key::empty`].
    fn is_empty(&self) -> bool;
    /// Bytes held outside the table slot (for boxed keys).
    fn heap_bytes(&self) -> usize;
}

/// MurmurHash3's 64-bit finaliser.
fn fmix(mut h: u64) -> u64 {
    h ^= h >> 33;
    h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
    h ^= h >> 33;
    h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    h ^= h >> 33;
    h
}

impl Key for u64 {
    fn from_words(words: &[u64]) -> Self {
        words[0] + 1
    }
    fn to_words(&self, words: &mut [u64]) {
        words[0] = self - 1;
    }
    fn hash64(&self) -> u64 {
        fmix(*self)
    }
    fn empty() -> Self {
        0
    }
    fn is_empty(&self) -> bool {
        *self == 0
    }
    fn heap_bytes(&self) -> usize {
        0
    }
}

impl Key for u128 {
    fn from_words(words: &[u64]) -> Self {
        let hi = words.get(1).copied().unwrap_or(0);
        ((u128::from(hi) << 64) | u128::from(words[0])) + 1
    }
    fn to_words(&self, words: &mut [u64]) {
        let v = self - 1;
        words[0] = v as u64;
        if let Some(w) = words.get_mut(1) {
            *w = (v >> 64) as u64;
        }
    }
    fn hash64(&self) -> u64 {
        fmix(*self as u64 ^ fmix((*self >> 64) as u64))
    }
    fn empty() -> Self {
        0
    }
    fn is_empty(&self) -> bool {
        *self == 0
    }
    fn heap_bytes(&self) -> usize {
        0
    }
}

impl Key for Box<[u64]> {
    fn from_words(words: &[u64]) -> Self {
        words.into()
    }
    fn to_words(&self, words: &mut [u64]) {
        words.copy_from_slice(self);
    }
    fn hash64(&self) -> u64 {
        self.iter().fold(0x9e37_79b9_7f4a_7c15, |h, w| fmix(h ^ w))
    }
    fn empty() -> Self {
        Box::new([])
    }
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    fn heap_bytes(&self) -> usize {
        self.len() * 8
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn packer(ranges: &[(i64, i64)]) -> Packer {
        let mut offset = 0;
        let fields = ranges
            .iter()
            .map(|&(lo, hi)| {
                let width = 64 - (hi.wrapping_sub(lo) as u64).leading_zeros();
                let f = Field { lo, width, offset };
                offset += width;
                f
            })
            .collect();
        Packer {
            fields,
            bits: offset,
            words: (offset as usize).div_ceil(64).max(1),
        }
    }

    #[test]
    fn round_trips_across_word_boundaries() {
        let p = packer(&[
            (-3, 4),
            (0, 1),
            (i64::MIN, i64::MAX),
            (5, 5),
            (-100, 100),
            (0, (1 << 40) - 1),
        ]);
        let state = [-3, 1, -42, 5, 99, (1 << 40) - 2];
        let mut words = vec![0; p.words];
        let k: Box<[u64]> = p.pack(&state, &mut words);
        let mut back = [0i64; 6];
        p.unpack(&k, &mut words, &mut back);
        assert_eq!(back, state);
    }

    #[test]
    fn small_keys_never_collide_with_empty() {
        let p = packer(&[(0, 1), (0, 7)]);
        let mut words = vec![0; p.words];
        let k: u64 = p.pack(&[0, 0], &mut words);
        assert!(!k.is_empty());
        let mut back = [9i64; 2];
        p.unpack(&k, &mut words, &mut back);
        assert_eq!(back, [0, 0]);
        let k2: u128 = p.pack(&[1, 7], &mut words);
        p.unpack(&k2, &mut words, &mut back);
        assert_eq!(back, [1, 7]);
    }
}
