//! Signatures of AIG variables from bit-parallel random simulation of valid traces.
//!
//! 64 traces run side by side in each word from the reset state (uninitialized latches
//! random), with random inputs. A lane whose inputs violate an invariant constraint draws new
//! inputs a few times; if it still violates, its sample is dropped and the lane restarts from
//! reset, so every sample is a state reachable by a valid trace with inputs that satisfy the
//! constraints — exactly where signal correspondence claims its equalities. Each variable's
//! samples are hashed in both polarities; nodes that are equal, or complementary, on every
//! sample get the same normalized key.

use crate::aig::{Aig, Node};

/// Simulation effort.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Effort {
    /// 64-lane words side by side.
    pub words: usize,
    /// Ticks simulated.
    pub steps: usize,
    /// New input draws for lanes that violate a constraint, per tick.
    pub retries: usize,
}

/// A small, fast pseudo-random generator (splitmix64).
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

fn mix(h: u64, w: u64) -> u64 {
    let x = (h ^ w).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    x ^ (x >> 29)
}

/// Values of every variable for `words` words of lanes, given input and latch words.
pub(crate) fn eval(aig: &Aig, words: usize, inputs: &[u64], latches: &[u64], val: &mut [u64]) {
    for (v, n) in aig.nodes.iter().enumerate() {
        let at = v * words;
        match *n {
            Node::False => val[at..at + words].fill(0),
            Node::Input(i) => {
                let i = i as usize * words;
                val[at..at + words].copy_from_slice(&inputs[i..i + words]);
            }
            Node::Latch(i) => {
                let i = i as usize * words;
                val[at..at + words].copy_from_slice(&latches[i..i + words]);
            }
            Node::And(a, b) => {
                let (ma, mb) = (neg_mask(a.is_neg()), neg_mask(b.is_neg()));
                let (pa, pb) = (a.var() as usize * words, b.var() as usize * words);
                for w in 0..words {
                    val[at + w] = (val[pa + w] ^ ma) & (val[pb + w] ^ mb);
                }
            }
        }
    }
}

fn neg_mask(neg: bool) -> u64 {
    if neg {
        !0
    } else {
        0
    }
}

/// Word `w` of literal `l` in an evaluation.
fn lit_word(val: &[u64], words: usize, l: crate::aig::Lit, w: usize) -> u64 {
    val[l.var() as usize * words + w] ^ neg_mask(l.is_neg())
}

/// Per variable: a key of its normalized signature and the phase that normalizes it.
pub(crate) fn keys(aig: &Aig, effort: Effort, seed: u64) -> Vec<(u64, bool)> {
    let words = effort.words.max(1);
    let n = aig.nodes.len();
    let mut rng = Rng::new(seed);
    let init: Vec<Option<bool>> = aig.latches.iter().map(|l| l.init).collect();
    let reset = |rng: &mut Rng, i: usize| match init[i] {
        Some(true) => !0u64,
        Some(false) => 0,
        None => rng.next(),
    };
    let mut latches: Vec<u64> = (0..aig.latches.len() * words)
        .map(|k| reset(&mut rng, k / words))
        .collect();
    let mut inputs: Vec<u64> = vec![0; aig.inputs.len() * words];
    let mut val = vec![0u64; n * words];
    let mut pos = vec![0u64; n];
    let mut neg = vec![0u64; n];
    for _ in 0..effort.steps {
        draw(&mut rng, &mut inputs);
        eval(aig, words, &inputs, &latches, &mut val);
        let mut ok = constraint_words(aig, words, &val);
        for attempt in 0..effort.retries {
            if ok.iter().all(|&m| m == !0) {
                break;
            }
            // Failing lanes take a valid lane's inputs, mutated except on the last attempt
            // (input-only constraints then hold for sure); all-zero inputs when none is valid.
            let mutate = attempt + 1 < effort.retries;
            adopt(&mut rng, &mut inputs, words, &ok, mutate);
            eval(aig, words, &inputs, &latches, &mut val);
            ok = constraint_words(aig, words, &val);
        }
        for v in 0..n {
            let (mut hp, mut hn) = (pos[v], neg[v]);
            for (w, &m) in ok.iter().enumerate() {
                let x = val[v * words + w];
                hp = mix(hp, x & m);
                hn = mix(hn, !x & m);
            }
            pos[v] = hp;
            neg[v] = hn;
        }
        // Next states; lanes that found no valid input restart from reset.
        for (i, l) in aig.latches.iter().enumerate() {
            for (w, &m) in ok.iter().enumerate() {
                let next = lit_word(&val, words, l.next, w);
                let r = reset(&mut rng, i);
                latches[i * words + w] = (next & m) | (r & !m);
            }
        }
    }
    (0..n)
        .map(|v| {
            if pos[v] <= neg[v] {
                (pos[v], false)
            } else {
                (neg[v], true)
            }
        })
        .collect()
}

/// Random inputs: each input's word is uniform, sparse (1 in 8) or dense (7 in 8), so that
/// rare values such as "no fault" or "all zero" come up as often as arbitrary ones.
pub(crate) fn draw(rng: &mut Rng, inputs: &mut [u64]) {
    for x in inputs.iter_mut() {
        let r = rng.next();
        *x = match rng.next() % 3 {
            0 => r,
            1 => r & rng.next() & rng.next(),
            _ => r | rng.next() | rng.next(),
        };
    }
}

/// Give every lane not in `ok` the inputs of a random lane in `ok` (with about one bit in 16
/// flipped when `mutate`), or all-zero inputs when no lane is valid.
pub(crate) fn adopt(rng: &mut Rng, inputs: &mut [u64], words: usize, ok: &[u64], mutate: bool) {
    let valid: Vec<(usize, u32)> = (0..words)
        .flat_map(|w| {
            (0..64)
                .filter(move |b| ok[w] >> b & 1 == 1)
                .map(move |b| (w, b))
        })
        .collect();
    let n_in = inputs.len().checked_div(words).unwrap_or(0);
    for (w, &m) in ok.iter().enumerate() {
        if m == !0 {
            continue;
        }
        for b in (0..64u32).filter(|b| m >> b & 1 == 0) {
            let donor =
                (!valid.is_empty()).then(|| valid[(rng.next() % valid.len() as u64) as usize]);
            for i in 0..n_in {
                let mut bit = donor.is_some_and(|(dw, db)| inputs[i * words + dw] >> db & 1 == 1);
                if mutate && donor.is_some() && rng.next().is_multiple_of(16) {
                    bit = !bit;
                }
                let x = &mut inputs[i * words + w];
                *x = (*x & !(1 << b)) | (u64::from(bit) << b);
            }
        }
    }
}

/// Lanes (per word) where every constraint holds.
fn constraint_words(aig: &Aig, words: usize, val: &[u64]) -> Vec<u64> {
    (0..words)
        .map(|w| {
            aig.constraints
                .iter()
                .fold(!0u64, |m, &c| m & lit_word(val, words, c, w))
        })
        .collect()
}
