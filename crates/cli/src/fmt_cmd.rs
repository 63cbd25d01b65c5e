//! `statecheck fmt`: rewrite model files in the canonical layout (`statecheck_syntax::format`).

use crate::diag;
use anyhow::{Context, Result};
use clap::Args;
use std::io::{Read, Write};

/// Arguments of `statecheck fmt`.
#[derive(Args)]
pub struct FmtArgs {
    /// The `.sc` files to format in place; `-` reads standard input and writes standard output.
    #[arg(required = true)]
    files: Vec<String>,
    /// Change nothing; list the files that would change and exit 1 if there is one.
    #[arg(long)]
    check: bool,
}

/// Format the files; exit 1 when a file has syntax errors or (with `--check`) would change.
pub fn run(args: FmtArgs) -> Result<u8> {
    let mut code = 0;
    for path in &args.files {
        let source = if path == "-" {
            let mut s = String::new();
            std::io::stdin()
                .read_to_string(&mut s)
                .context("cannot read standard input")?;
            s
        } else {
            std::fs::read_to_string(path).with_context(|| format!("cannot read `{path}`"))?
        };
        let formatted = match statecheck_syntax::format::format(&source) {
            Ok(f) => f,
            Err(e) => {
                let statecheck_syntax::format::ErrorKind::Syntax(d) = &e.kind else {
                    anyhow::bail!("{path}: {e}");
                };
                let shown = if path == "-" {
                    "<stdin>"
                } else {
                    path.as_str()
                };
                diag::eprint(shown, &source, d);
                eprintln!("{shown}: not formatted: {e}");
                code = 1;
                continue;
            }
        };
        let changed = formatted != source;
        if args.check {
            if changed {
                println!("{path}");
                code = 1;
            }
        } else if path == "-" {
            let _ = std::io::stdout().lock().write_all(formatted.as_bytes());
        } else if changed {
            std::fs::write(path, &formatted).with_context(|| format!("cannot write `{path}`"))?;
        }
    }
    Ok(code)
}
