//! Robustness: the parser must never panic or overflow the stack, whatever the input. Every
//! prefix of every data file and many deterministic random mutations are parsed, plus
//! pathological inputs (deep nesting, long operator chains, huge literals, binary junk).

#![allow(clippy::unwrap_used)] // tests may unwrap

mod common;

use statecheck_syntax::parse;

/// A tiny deterministic linear congruential generator (no extra dependencies).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 33
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn all_sources() -> Vec<(String, String)> {
    let mut v = common::data_files("parse");
    v.extend(common::data_files("errors"));
    v
}

/// Parse and check basic invariants of the result.
fn check(src: &str) {
    let (_file, diags) = parse(src);
    for d in &diags {
        assert!(d.span.start <= d.span.end);
        assert!(
            d.span.end as usize <= src.len(),
            "span out of bounds for {src:?}"
        );
    }
}

#[test]
fn every_prefix_parses() {
    for (_, src) in all_sources() {
        for (i, _) in src.char_indices() {
            check(&src[..i]);
        }
        check(&src);
    }
}

#[test]
fn random_mutations_parse() {
    const INTERESTING: &[u8] = b"{}()[];:,.=-+<>!&|^~*/%_ \n0123456789aszxif\"#@\x80\xC3\xE2\xFF";
    let mut rng = Lcg(0x5eed);
    for (_, src) in all_sources() {
        let bytes = src.as_bytes();
        for _ in 0..150 {
            let mut b = bytes.to_vec();
            for _ in 0..1 + rng.below(4) {
                let len = b.len();
                match rng.below(4) {
                    0 if len > 0 => {
                        let i = rng.below(len);
                        b[i] = INTERESTING[rng.below(INTERESTING.len())];
                    }
                    1 if len > 0 => {
                        let i = rng.below(len);
                        let n = rng.below(8).min(len - i);
                        b.drain(i..i + n);
                    }
                    2 => {
                        let i = rng.below(len + 1);
                        b.insert(i, INTERESTING[rng.below(INTERESTING.len())]);
                    }
                    _ if len > 0 => {
                        let i = rng.below(len);
                        let n = rng.below(16).min(len - i);
                        let chunk: Vec<u8> = b[i..i + n].to_vec();
                        let j = rng.below(b.len() + 1);
                        b.splice(j..j, chunk);
                    }
                    _ => {}
                }
            }
            check(&String::from_utf8_lossy(&b));
        }
    }
}

#[test]
fn pathological_inputs_parse() {
    let n = 100_000;
    let cases = [
        format!("const A = {}1{};", "(".repeat(n), ")".repeat(n)),
        format!("const A = {}1;", "(".repeat(n)),
        format!("const A = {}1;", "-".repeat(n)),
        format!("const A = {}1;", "!~".repeat(n)),
        format!("const A = 1{};", " + 1".repeat(n)),
        format!("const A = 1{};", " * (1 + 1)".repeat(n)),
        format!("const A = {}1;", "if a then ".repeat(n)),
        format!("const A = x{};", "[x".repeat(n)),
        format!("const A = f({}1);", "f(".repeat(n)),
        format!("const A = in({}x);", "in(".repeat(n)),
        format!("chart C {{ {} }}", "state S { ".repeat(n)),
        format!("chart C {{ {} }}", "region R { ".repeat(n)),
        format!("chart C {{ entry {{ {} }} }}", "if a { ".repeat(n)),
        format!(
            "chart C {{ entry {{ if a {{ }} {} }} }}",
            "else if a { } ".repeat(n)
        ),
        format!("chart C {{ on go -> {}A; }}", "choice { else -> ".repeat(n)),
        format!("chart C {{ {} }}", "{".repeat(n)),
        "}".repeat(n),
        format!("const A = {};", "9".repeat(1000)),
        format!("const A = 0x{};", "F".repeat(1000)),
        "/*".to_string(),
        "/* unterminated * / comment".to_string(),
        "const A = 1; /".to_string(),
        "\u{0}\u{1}\u{7f}ÿ€😀 chart 😀 { }".to_string(),
        String::from_utf8_lossy(&(0u8..=255).collect::<Vec<_>>()).into_owned(),
        "on; on; on;".repeat(1000),
        ";".repeat(n),
    ];
    for src in &cases {
        check(src);
    }
}

/// Over-deep nesting is reported as E0013 rather than crashing.
#[test]
fn deep_nesting_is_reported() {
    let src = format!("const A = {}1{};", "(".repeat(1000), ")".repeat(1000));
    let (_, diags) = parse(&src);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0].code, "E0013");
    let src = format!("const A = 1{};", " + 1".repeat(10_000));
    let (_, diags) = parse(&src);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0].code, "E0013");
}
