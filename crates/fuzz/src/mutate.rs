//! The mutator: input `i` of a run with seed `s` is a seed of the corpus changed by a few
//! random byte- and token-level edits, drawn from a generator seeded by `(s, i)` alone, so
//! that the runner can rebuild any input from its index (a crashed worker reports only that).

use crate::corpus::Seed;
use crate::targets::Target;
use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};

/// Tokens worth inserting into a `.sc` text.
const SC_TOKENS: &[&str] = &[
    "chart ",
    "state ",
    "initial ",
    "region ",
    "parallel ",
    "system ",
    "instance ",
    "connect ",
    "input ",
    "output ",
    "local ",
    "const ",
    "event ",
    "int[",
    "..",
    "]",
    "bool",
    "= ",
    "on ",
    "after(",
    "entry ",
    "exit ",
    "during ",
    "-> ",
    "choice ",
    "else ",
    "if ",
    "then ",
    "raise ",
    "history deep;",
    "priority 1",
    "in(",
    "invariant p: ",
    "reachable r: ",
    "assume ",
    "respond q: ",
    " within 3",
    "observer o { ",
    "ltl l: G F ",
    "ctl c: AG EF ",
    "fair j: ",
    "nonblocking n: ",
    "import \"x.sc\";",
    "function f(a: int[0..3]): int[0..3] = ",
    "{",
    "}",
    "(",
    ")",
    ";",
    ",",
    ":",
    ".",
    "&&",
    "||",
    "!",
    "=>",
    "<<",
    ">>",
    "%",
    "/",
    "*",
    "-",
    "+",
    "min(",
    "max(",
    "abs(",
    "true",
    "false",
    "x",
    "y",
    "// c\n",
    "/* c */",
    "\n",
    "0x7fff",
    "9223372036854775807",
    "-9223372036854775808",
    "(-9223372036854775807 - 1)",
    "0",
    "-1",
];

/// Tokens worth inserting into a scenario.
const SCN_TOKENS: &[&str] = &[
    " = ",
    ",",
    " * ",
    "-",
    "\n",
    "loop:\n",
    "#",
    "true",
    "false",
    "0",
    "-1",
    "65535",
    "9223372036854775807",
    "-9223372036854775808",
    ".",
    "* 3",
    "* 0",
    "=",
    "  ",
];

/// Tokens worth inserting into an AIGER file.
const AIG_TOKENS: &[&str] = &[
    "aag ",
    "aig ",
    " ",
    "\n",
    "0",
    "1",
    "2",
    "4294967295",
    "18446744073709551615",
    "i0 ",
    "l0 ",
    "b0 ",
    "c\n",
    "o0 ",
    "j0 ",
    "f0 ",
    "\u{1b}[31m",
    "-1",
    "99999999",
];

/// Interesting integers to write over a digit run.
const NUMBERS: &[&str] = &[
    "0",
    "1",
    "-1",
    "2",
    "7",
    "8",
    "63",
    "64",
    "65",
    "255",
    "256",
    "32767",
    "65536",
    "2147483647",
    "2147483648",
    "4294967296",
    "9223372036854775807",
    "9223372036854775808",
    "18446744073709551616",
    "100000",
];

fn tokens(t: Target) -> &'static [&'static str] {
    match t {
        Target::Scenario => SCN_TOKENS,
        Target::Aiger => AIG_TOKENS,
        _ => SC_TOKENS,
    }
}

/// Largest input the mutator produces (bytes).
pub const MAX_LEN: usize = 128 * 1024;

/// The generator of input `index` of a run with `seed`.
pub fn rng_for(seed: u64, index: u64) -> StdRng {
    // SplitMix64 of the pair: neighbouring indices give unrelated streams.
    let mut z = seed
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add(index)
        .wrapping_add(0x632B_E59B_D9B4_E019);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    StdRng::seed_from_u64(z ^ (z >> 31))
}

/// Input `index` of a run of `target` with `seed` over `seeds` (non-empty): `(ctx, bytes)`.
/// The self-test target does not mutate: input `i` is seed `i mod n`.
pub fn input(target: Target, seeds: &[Seed], seed: u64, index: u64) -> (usize, Vec<u8>) {
    if seeds.is_empty() {
        return (0, Vec::new());
    }
    if target == Target::SelfTest {
        let s = &seeds[(index % seeds.len() as u64) as usize];
        return (s.ctx, s.bytes.clone());
    }
    let mut rng = rng_for(seed, index);
    let base = &seeds[rng.random_range(0..seeds.len())];
    let mut b = base.bytes.clone();
    // One in 16 inputs is a seed unchanged (the seeds themselves must pass).
    if rng.random_range(0..16u32) == 0 {
        return (base.ctx, b);
    }
    let edits = 1 + rng.random_range(0..6u32);
    for _ in 0..edits {
        edit(target, &mut b, seeds, &mut rng);
        b.truncate(MAX_LEN);
    }
    (base.ctx, b)
}

fn span(b: &[u8], rng: &mut StdRng) -> (usize, usize) {
    if b.is_empty() {
        return (0, 0);
    }
    let start = rng.random_range(0..b.len());
    let max = (b.len() - start).min(if rng.random_range(0..4u32) == 0 {
        4096
    } else {
        32
    });
    (start, start + rng.random_range(0..=max))
}

fn edit(target: Target, b: &mut Vec<u8>, seeds: &[Seed], rng: &mut StdRng) {
    let at = if b.is_empty() {
        0
    } else {
        rng.random_range(0..=b.len())
    };
    match rng.random_range(0..10u32) {
        0 if !b.is_empty() => {
            let i = rng.random_range(0..b.len());
            b[i] ^= 1 << rng.random_range(0..8u32);
        }
        1 if !b.is_empty() => {
            let i = rng.random_range(0..b.len());
            b[i] = [0u8, 0xff, b'\n', b' ', b'{', b'}', b'(', b'*', 0x80, 0xc3]
                [rng.random_range(0..10)];
        }
        2 => {
            let (s, e) = span(b, rng);
            b.drain(s..e);
        }
        3 => {
            // Duplicate a span (repetition drives nesting and long chains).
            let (s, e) = span(b, rng);
            let piece = b[s..e].to_vec();
            let times = if rng.random_range(0..8u32) == 0 {
                64
            } else {
                1
            };
            for _ in 0..times {
                if b.len() + piece.len() > MAX_LEN {
                    break;
                }
                b.splice(at.min(b.len())..at.min(b.len()), piece.iter().copied());
            }
        }
        4 | 5 => {
            let toks = tokens(target);
            let t = toks[rng.random_range(0..toks.len())].as_bytes();
            b.splice(at..at, t.iter().copied());
        }
        6 => {
            // Overwrite a run of digits with an interesting number.
            if let Some(i) = (0..b.len())
                .map(|k| (k + at) % b.len().max(1))
                .find(|&k| b.get(k).is_some_and(u8::is_ascii_digit))
            {
                let mut e = i;
                while b.get(e).is_some_and(u8::is_ascii_digit) {
                    e += 1;
                }
                let n = NUMBERS[rng.random_range(0..NUMBERS.len())].as_bytes();
                b.splice(i..e, n.iter().copied());
            }
        }
        7 => {
            // Splice in a piece of another seed.
            let other = &seeds[rng.random_range(0..seeds.len())].bytes;
            let (s, e) = span(other, rng);
            b.splice(at..at, other[s..e].iter().copied());
        }
        8 => {
            let (s, _) = span(b, rng);
            b.truncate(s.max(b.len() / 2));
        }
        _ => {
            // Swap two lines.
            let lines: Vec<usize> = b
                .iter()
                .enumerate()
                .filter(|(_, c)| **c == b'\n')
                .map(|(i, _)| i)
                .collect();
            if lines.len() >= 3 {
                let k = rng.random_range(0..lines.len() - 2);
                let (a, m, z) = (lines[k] + 1, lines[k + 1] + 1, lines[k + 2] + 1);
                let mut piece = b[m..z].to_vec();
                piece.extend_from_slice(&b[a..m]);
                b.splice(a..z, piece);
            }
        }
    }
}
