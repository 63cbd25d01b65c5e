//! The E0111 hint ("write the path from an enclosing state: `a` or `b`", "did you mean `x`?")
//! proposes only targets that resolve: each proposed path, put in place of the unknown
//! target, makes that transition's E0111 go away.

use std::path::PathBuf;

fn files() -> Vec<(String, String)> {
    let dir: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "tests",
        "diagnostics",
    ]
    .iter()
    .collect();
    ["e0111_targets.sc", "e0111_unknown_target.sc"]
        .iter()
        .map(|n| {
            let p = dir.join(n);
            let text =
                std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            (n.to_string(), text)
        })
        .collect()
}

/// The backticked parts of a hint.
fn proposals(hint: &str) -> Vec<String> {
    hint.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

#[test]
fn every_proposed_target_resolves() {
    let mut tried = 0;
    for (name, src) in files() {
        let (file, _) = statecheck_syntax::parse(&src);
        let (_, diags) = statecheck_model::check(&file);
        for d in diags
            .iter()
            .filter(|d| d.code == "E0111" && d.message.starts_with("no state"))
        {
            let Some(hint) = &d.hint else { continue };
            for path in proposals(hint) {
                let fixed = format!(
                    "{}{}{}",
                    &src[..d.span.start as usize],
                    path,
                    &src[d.span.end as usize..]
                );
                let (f2, _) = statecheck_syntax::parse(&fixed);
                let (_, d2) = statecheck_model::check(&f2);
                let still = d2
                    .iter()
                    .any(|e| e.code == "E0111" && e.span.start == d.span.start);
                assert!(
                    !still,
                    "{name}: the hint's `{path}` for `{}` does not resolve",
                    d.message
                );
                tried += 1;
            }
        }
    }
    // Both files hold unknown targets with proposals (at least the two of e0111_unknown_target.sc).
    assert!(tried >= 2, "only {tried} proposals tried");
}
