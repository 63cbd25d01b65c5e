//! The engine on three key widths (u32, u128, boxed words; u64 keys are the linear drive's in
//! tests/native.rs) and thread count, against counts
//! derived by hand: `n` independent modulo-(m+1) counters, at most one incremented per tick,
//! give (m+1)^n states after tick 0 plus the pre-start state; the wide padding variables never
//! change, so they only widen the packed vector.

mod common;

use common::program;
use statecheck_explicit::{verify, Options, Verdict};

#[test]
fn counts_and_shortest_cex_on_every_key_width() {
    // 6 bits of counters, plus 3 × 40 bits per padding variable: u32, u128 and boxed keys.
    for pad in [0, 1, 3] {
        let p = program(3, 3, pad);
        let mut seen = Vec::new();
        for threads in [1, 2] {
            let r = verify(
                &p,
                &Options {
                    threads,
                    ..Options::default()
                },
                None,
            )
            .expect("runs");
            let key = [31, 127, u32::MAX]
                .iter()
                .position(|&w| r.stats.state_bits <= w);
            assert_eq!(key, [0, 1, 3].iter().position(|&p| p == pad));
            assert_eq!(
                r.stats.states,
                4 * 4 * 4 + 1,
                "pad {pad}, {} bits",
                r.stats.state_bits
            );
            // Each state: no event, or one of 3 events.
            assert_eq!(r.stats.transitions, r.stats.states * 4);
            let inv = &r.results[0];
            assert_eq!(inv.verdict, Verdict::Violated);
            // All three counters at 3 need 9 increments, one per tick from tick 1: tick 9.
            assert_eq!(inv.depth, 10);
            assert_eq!(inv.counterexample.as_ref().map(Vec::len), Some(10));
            seen.push((
                r.stats.states,
                r.stats.transitions,
                r.stats.depth,
                inv.counterexample.clone(),
            ));
        }
        assert_eq!(
            seen[0], seen[1],
            "same answer and counterexample on 1 and 2 threads"
        );
    }
}

#[test]
fn a_64_bit_vector_of_all_ones_is_a_state_like_any_other() {
    // x takes 62 bits, b one, the started flag one (a single state needs no bits): 64 bits,
    // stored as `u64` keys, where the all-ones vector's key is the table's free-slot mark.
    let text = "chart C {\n  input event go;\n  input event go2;\n  output x: int[0..4611686018427387903] = 0;\n  output b: bool = false;\n  initial S;\n  state S {\n    on go / { x = 4611686018427387903; b = true; };\n    on go2 / { x = 4611686018427387903; b = true; };\n  }\n}\nsystem S {\n  instance c: C;\n  reachable all_ones: c.x == 4611686018427387903 && c.b;\n}\n";
    let (file, _) = statecheck_syntax::parse(text);
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
    let p = statecheck_ir::lower(&model, model.system("S").expect("system")).expect("lowers");
    let r = verify(&p, &Options::default(), None).expect("runs");
    assert_eq!(r.stats.state_bits, 64);
    // Before tick 0; after tick 0 (started); after `go` or `go2` at tick 1 (all ones: three
    // transitions lead there, and it must be stored once). Four input vectors per state.
    assert_eq!((r.stats.states, r.stats.transitions), (3, 12));
    assert_eq!(r.results[0].verdict, Verdict::Reachable);
    assert_eq!(r.results[0].depth, 2);
    assert!(
        r.stats.bytes_per_state() <= 16.0 * 64.0,
        "a u64 table of 64 slots"
    );
}
