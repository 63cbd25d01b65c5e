//! `statecheck dot --svg`: the DOT text drawn by Graphviz (`dot -Tsvg`), which must be
//! installed; without it the command fails with E0901.

use anyhow::{Context, Result};
use std::io::Write;
use std::process::{Command, Stdio};

/// The program run: `STATECHECK_DOT` when set (tests point it at a missing file), else `dot`.
fn program() -> String {
    std::env::var("STATECHECK_DOT").unwrap_or_else(|_| "dot".to_string())
}

/// Draw `dot` as SVG with Graphviz.
pub fn from_dot(dot: &str) -> Result<String> {
    let prog = program();
    let mut child = match Command::new(&prog)
        .arg("-Tsvg")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(c) => c,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            eprintln!(
                "error[E0901]: Graphviz's `{prog}` was not found: --svg needs Graphviz installed\n  = hint: install the `graphviz` package (e.g. `apt-get install graphviz`), or drop --svg and draw the DOT text elsewhere"
            );
            return Err(crate::Exit(2).into());
        }
        Err(e) => return Err(e).with_context(|| format!("cannot run `{prog}`")),
    };
    // Feed the input from another thread so that a large drawing cannot block both pipes.
    let mut stdin = child.stdin.take().context("no pipe to Graphviz")?;
    let input = dot.to_string();
    let feeder = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child
        .wait_with_output()
        .with_context(|| format!("cannot run `{prog}`"))?;
    let fed = feeder.join();
    if !out.status.success() {
        eprintln!(
            "error[E0902]: Graphviz's `{prog} -Tsvg` failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        );
        return Err(crate::Exit(2).into());
    }
    if let Ok(Err(e)) = fed {
        return Err(e).with_context(|| format!("cannot write to `{prog}`"));
    }
    String::from_utf8(out.stdout).context("Graphviz wrote SVG that is not UTF-8")
}
