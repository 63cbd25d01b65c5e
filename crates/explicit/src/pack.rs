//! Bit-packed state vectors: every state slot stored as `value - lo` in `width()` bits.
//!
//! A packed vector is a little sequence of 64-bit words; [`Key`] turns it into the value the
//! visited set stores: a `u32` for vectors of up to 31 bits, a `u64` up to 64 bits, a `u128` up
//! to 127 bits, a boxed word slice beyond. The integer keys store `packed + 1` so that 0 can
//! mark an empty slot of the hash table; for a 64-bit vector of all ones that wraps to 0, which
//! the table keeps out of its slots (`table.rs`).

use statecheck_ir::Program;

/// Where one state slot lives in a packed vector.
#[derive(Clone, Copy, Debug)]
struct Field {
    lo: i64,
    width: u32,
    offset: u32,
    /// `width` low bits set.
    mask: u64,
}

/// A field of non-zero width, for the integer fast paths: where it sits in the 64-bit words.
#[derive(Clone, Copy, Debug)]
struct Live {
    /// Index of the slot in the state.
    slot: u32,
    lo: i64,
    offset: u32,
    mask: u64,
    /// The word of its first bit (0 or 1 in a 128-bit key).
    word: u32,
    /// Its first bit within that word.
    sh: u32,
    /// True when it continues into the next word (then `sh > 0`).
    spill: bool,
}

/// Packs and unpacks the persistent state of a program.
#[derive(Clone, Debug)]
pub struct Packer {
    fields: Vec<Field>,
    /// The fields of non-zero width (constant slots need no bits and no work when packing),
    /// in bit order.
    live: Vec<Live>,
    /// `live[..split.0]` lie within word 0, `live[split.0..split.1]` straddle words 0 and 1
    /// (at most one), `live[split.1..]` lie within word 1 or later.
    split: (usize, usize),
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
                    mask: mask(s.width()),
                };
                offset += f.width;
                f
            })
            .collect();
        Packer::with_fields(fields, offset)
    }

    fn with_fields(fields: Vec<Field>, bits: u32) -> Packer {
        let live: Vec<Live> = fields
            .iter()
            .enumerate()
            .filter(|(_, f)| f.width > 0)
            .map(|(i, f)| Live {
                slot: i as u32,
                lo: f.lo,
                offset: f.offset,
                mask: f.mask,
                word: f.offset / 64,
                sh: f.offset % 64,
                spill: f.offset % 64 + f.width > 64,
            })
            .collect();
        let within0 = live.iter().take_while(|f| f.word == 0 && !f.spill).count();
        let straddle = live[within0..].iter().take_while(|f| f.word == 0).count();
        Packer {
            fields,
            split: (within0, within0 + straddle),
            live,
            bits,
            words: (bits as usize).div_ceil(64).max(1),
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
    #[inline]
    pub fn pack<K: Key>(&self, state: &[i64], scratch: &mut [u64]) -> K {
        K::pack(self, state, scratch)
    }

    /// Unpack a key into a state.
    #[inline]
    pub fn unpack<K: Key>(&self, key: &K, scratch: &mut [u64], state: &mut [i64]) {
        key.unpack(self, scratch, state);
    }

    /// Unpack the fields of non-zero width of a key into a state whose constant slots are
    /// already set (by [`Packer::set_constants`] or an earlier unpacking); cheaper than
    /// [`Packer::unpack`] when many slots are constant.
    #[inline]
    pub fn unpack_live<K: Key>(&self, key: &K, scratch: &mut [u64], state: &mut [i64]) {
        key.unpack_live(self, scratch, state);
    }

    /// Set the constant slots (fields of width zero) of `state` to their only value.
    pub fn set_constants(&self, state: &mut [i64]) {
        for (f, v) in self.fields.iter().zip(state.iter_mut()) {
            if f.width == 0 {
                *v = f.lo;
            }
        }
    }

    /// Pack a state of at most 128 bits straight into an integer (no word buffer): the hot
    /// path of the 128-bit keys, one 64-bit word at a time (variable 128-bit shifts are slow).
    #[inline]
    fn pack_u128(&self, state: &[i64]) -> u128 {
        let (w0, w1) = (
            pack_word(&self.live[..self.split.0], state),
            pack_word(&self.live[self.split.1..], state),
        );
        let (mut w0, mut w1) = (w0, w1);
        // The field that straddles the two words, if any (then `0 < sh < 64`).
        for f in &self.live[self.split.0..self.split.1] {
            let v = state.get(f.slot as usize).copied().unwrap_or(f.lo);
            let x = v.wrapping_sub(f.lo) as u64 & f.mask;
            w0 |= x << f.sh;
            w1 |= x >> ((64 - f.sh) & 63);
        }
        u128::from(w0) | (u128::from(w1) << 64)
    }

    /// Pack a state of at most 64 bits straight into an integer.
    #[inline]
    fn pack_u64(&self, state: &[i64]) -> u64 {
        let mut acc = 0u64;
        for f in &self.live {
            let v = state.get(f.slot as usize).copied().unwrap_or(f.lo);
            // Used for vectors of at most 64 bits: every live field starts below bit 64.
            acc |= (v.wrapping_sub(f.lo) as u64 & f.mask) << (f.offset & 63);
        }
        acc
    }

    /// Unpack a vector of at most 64 bits.
    #[inline]
    fn unpack_u64(&self, packed: u64, state: &mut [i64]) {
        for (f, v) in self.fields.iter().zip(state.iter_mut()) {
            *v =
                f.lo.wrapping_add(((packed >> (f.offset & 63)) & f.mask) as i64);
        }
    }

    /// Unpack the live fields of a vector of at most 64 bits (the others are constant).
    #[inline]
    fn unpack_u64_live(&self, packed: u64, state: &mut [i64]) {
        for f in &self.live {
            if let Some(v) = state.get_mut(f.slot as usize) {
                *v =
                    f.lo.wrapping_add(((packed >> (f.offset & 63)) & f.mask) as i64);
            }
        }
    }

    /// Unpack a vector of at most 128 bits.
    #[inline]
    fn unpack_u128(&self, packed: u128, state: &mut [i64]) {
        self.set_constants(state);
        self.unpack_u128_live(packed, state);
    }

    /// Unpack the live fields of a vector of at most 128 bits (the others are constant).
    #[inline]
    fn unpack_u128_live(&self, packed: u128, state: &mut [i64]) {
        let w = [packed as u64, (packed >> 64) as u64];
        for f in &self.live {
            let lo = w[(f.word & 1) as usize] >> f.sh;
            let hi = if f.spill {
                w[1] << ((64 - f.sh) & 63)
            } else {
                0
            };
            if let Some(v) = state.get_mut(f.slot as usize) {
                *v = f.lo.wrapping_add(((lo | hi) & f.mask) as i64);
            }
        }
    }
}

/// The fields of one 64-bit word (each within it, at bit `sh`), packed.
#[inline]
fn pack_word(fields: &[Live], state: &[i64]) -> u64 {
    let mut acc = 0u64;
    for f in fields {
        let v = state.get(f.slot as usize).copied().unwrap_or(f.lo);
        acc |= (v.wrapping_sub(f.lo) as u64 & f.mask) << (f.sh & 63);
    }
    acc
}

#[inline]
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
    /// Pack `state` with `packer` (`scratch` holds `packer.words` words).
    fn pack(packer: &Packer, state: &[i64], scratch: &mut [u64]) -> Self {
        packer.pack_words(state, scratch);
        Self::from_words(scratch)
    }
    /// Unpack into `state` with `packer`.
    fn unpack(&self, packer: &Packer, scratch: &mut [u64], state: &mut [i64]) {
        self.to_words(scratch);
        packer.unpack_words(scratch, state);
    }
    /// Unpack the fields of non-zero width into `state`, whose constant slots are already set
    /// (see [`Packer::unpack_live`]).
    fn unpack_live(&self, packer: &Packer, scratch: &mut [u64], state: &mut [i64]) {
        self.unpack(packer, scratch, state);
    }
}

/// MurmurHash3's 64-bit finaliser.
pub(crate) fn fmix(mut h: u64) -> u64 {
    h ^= h >> 33;
    h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
    h ^= h >> 33;
    h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    h ^= h >> 33;
    h
}

impl Key for u32 {
    fn from_words(words: &[u64]) -> Self {
        words[0] as u32 + 1
    }
    fn to_words(&self, words: &mut [u64]) {
        words[0] = u64::from(self - 1);
    }
    fn hash64(&self) -> u64 {
        fmix(u64::from(*self))
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
    #[inline]
    fn pack(packer: &Packer, state: &[i64], _: &mut [u64]) -> Self {
        packer.pack_u64(state) as u32 + 1
    }
    #[inline]
    fn unpack(&self, packer: &Packer, _: &mut [u64], state: &mut [i64]) {
        packer.unpack_u64(u64::from(self - 1), state);
    }
    #[inline]
    fn unpack_live(&self, packer: &Packer, _: &mut [u64], state: &mut [i64]) {
        packer.unpack_u64_live(u64::from(self - 1), state);
    }
}

impl Key for u64 {
    fn from_words(words: &[u64]) -> Self {
        words[0].wrapping_add(1)
    }
    fn to_words(&self, words: &mut [u64]) {
        words[0] = self.wrapping_sub(1);
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
    #[inline]
    fn pack(packer: &Packer, state: &[i64], _: &mut [u64]) -> Self {
        packer.pack_u64(state).wrapping_add(1)
    }
    #[inline]
    fn unpack(&self, packer: &Packer, _: &mut [u64], state: &mut [i64]) {
        packer.unpack_u64(self.wrapping_sub(1), state);
    }
    #[inline]
    fn unpack_live(&self, packer: &Packer, _: &mut [u64], state: &mut [i64]) {
        packer.unpack_u64_live(self.wrapping_sub(1), state);
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
    #[inline]
    fn pack(packer: &Packer, state: &[i64], _: &mut [u64]) -> Self {
        packer.pack_u128(state) + 1
    }
    #[inline]
    fn unpack(&self, packer: &Packer, _: &mut [u64], state: &mut [i64]) {
        packer.unpack_u128(self - 1, state);
    }
    #[inline]
    fn unpack_live(&self, packer: &Packer, _: &mut [u64], state: &mut [i64]) {
        packer.unpack_u128_live(self - 1, state);
    }
}

/// A packed vector of up to `N` words held inline (no allocation per state), for states of
/// fewer than `N * 64` bits: the top bit of the last word is then always clear, so all ones
/// marks an empty slot. Shorter vectors are padded with zeros.
impl<const N: usize> Key for [u64; N] {
    fn from_words(words: &[u64]) -> Self {
        let mut k = [0u64; N];
        k[..words.len()].copy_from_slice(words);
        k
    }
    fn to_words(&self, words: &mut [u64]) {
        let n = words.len();
        words.copy_from_slice(&self[..n]);
    }
    fn hash64(&self) -> u64 {
        self.iter().fold(0x9e37_79b9_7f4a_7c15, |h, w| fmix(h ^ w))
    }
    fn empty() -> Self {
        [u64::MAX; N]
    }
    fn is_empty(&self) -> bool {
        *self == [u64::MAX; N]
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

/// Where one state slot lives in a packed vector, for code that packs on its own (the native
/// successor generator): bits `offset .. offset + width` hold `value - lo`.
#[derive(Clone, Copy, Debug)]
pub struct FieldLayout {
    /// Index of the slot in the state.
    pub slot: usize,
    /// Lowest value of the slot.
    pub lo: i64,
    /// Bits (0 for a constant slot).
    pub width: u32,
    /// First bit in the packed vector.
    pub offset: u32,
}

impl FieldLayout {
    /// `width` low bits set.
    pub fn mask(&self) -> u64 {
        mask(self.width)
    }
}

impl Packer {
    /// Every state slot's place, in slot order.
    pub fn layout(&self) -> impl Iterator<Item = FieldLayout> + '_ {
        self.fields.iter().enumerate().map(|(slot, f)| FieldLayout {
            slot,
            lo: f.lo,
            width: f.width,
            offset: f.offset,
        })
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
                let f = Field {
                    lo,
                    width,
                    offset,
                    mask: mask(width),
                };
                offset += width;
                f
            })
            .collect();
        Packer::with_fields(fields, offset)
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
    fn integer_fast_paths_agree_with_the_word_packing() {
        // Constant slots (width 0) in between, fields up to the last bit of each key width.
        for ranges in [
            vec![
                (-3, 4),
                (7, 7),
                (0, 1),
                (-100, 100),
                (5, 5),
                (0, (1 << 50) - 1),
            ],
            vec![
                (0, (1 << 40) - 1),
                (9, 9),
                (-1, (1 << 40) - 2),
                (0, (1 << 40) - 1),
            ],
            // Exactly 64 bits (a `u64` key).
            vec![(0, (1 << 60) - 1), (-8, 7)],
            // A field ending exactly at bit 64, then one starting exactly there.
            vec![(0, (1 << 60) - 1), (0, 15), (3, 3), (0, (1 << 62) - 1)],
        ] {
            let p = packer(&ranges);
            let mut words = vec![0; p.words];
            let state: Vec<i64> = ranges.iter().map(|&(lo, hi)| hi - (hi - lo) / 3).collect();
            p.pack_words(&state, &mut words);
            let mut back = vec![0i64; ranges.len()];
            if p.bits <= 64 {
                let k: u64 = p.pack(&state, &mut words);
                assert_eq!(k - 1, words[0]);
                p.unpack(&k, &mut words, &mut back);
            } else {
                let k: u128 = p.pack(&state, &mut words);
                assert_eq!(k - 1, u128::from(words[0]) | (u128::from(words[1]) << 64));
                p.unpack(&k, &mut words, &mut back);
            }
            assert_eq!(back, state);
            // Live fields only, over a state whose constants were set once.
            let mut live = vec![0i64; ranges.len()];
            p.set_constants(&mut live);
            if p.bits <= 64 {
                let k: u64 = p.pack(&state, &mut words);
                p.unpack_live(&k, &mut words, &mut live);
            } else {
                let k: u128 = p.pack(&state, &mut words);
                p.unpack_live(&k, &mut words, &mut live);
            }
            assert_eq!(live, state);
        }
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
