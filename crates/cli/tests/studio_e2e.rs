//! The studio in a real browser: runs `crates/studio/e2e/studio.e2e.js` (Debian's chromium
//! driven by playwright-core) against this build of `statecheck`. The script opens the FAM
//! closed loop, injects a stall, compares the highlighted states and every tick with
//! `statecheck sim --json` of the scenario the page saves, replays a `verify --cex-dir`
//! counterexample to its violating tick, steps back and forward, replays a lasso of a
//! temporal property verified from the page and steps around its loop, reloads the page and
//! finds its session, and writes the screenshots of docs/studio.md to docs/studio/.
//!
//! `scripts/test.sh` installs chromium and the npm package; where either is missing (a bare
//! `cargo test`), this test says so on stderr and checks nothing.

use std::path::Path;
use std::process::Command;

#[test]
fn studio_in_chromium() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let e2e = root.join("crates/studio/e2e");
    let chromium = Path::new("/usr/bin/chromium");
    if !chromium.exists() || !e2e.join("node_modules/playwright-core").exists() {
        eprintln!(
            "studio e2e: chromium or crates/studio/e2e/node_modules missing; run scripts/test.sh"
        );
        return;
    }
    let out = Command::new("node")
        .arg("studio.e2e.js")
        .current_dir(&e2e)
        .env("STATECHECK_BIN", env!("CARGO_BIN_EXE_statecheck"))
        .output()
        .expect("node runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    println!("{stdout}");
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
