//! `statecheck gen`: code generation (C99, Rust, Modelica) from the IR.

use crate::load;
use anyhow::{bail, Result};
use clap::Args;
use statecheck_codegen::Source;
use statecheck_ir::view::TraceView;
use std::path::Path;

/// Arguments of `statecheck gen`.
#[derive(Args)]
pub struct GenArgs {
    /// Target language: c, rust or modelica.
    target: String,
    /// The `.sc` model file.
    model: String,
    /// The system (or chart) to generate.
    #[arg(long)]
    system: Option<String>,
    /// The system's configuration (`configuration NAME { … }`, docs/components.md).
    #[arg(long, value_name = "NAME")]
    config: Option<String>,
    /// Output directory (c, rust) or file (modelica; standard output when absent).
    #[arg(short, long)]
    output: Option<String>,
    /// C only: also emit `PREFIX_harness.c`, a `main` replaying a scenario file and printing
    /// the trace as `statecheck sim --json` does.
    #[arg(long)]
    harness: bool,
    /// Modelica only: add coverage counters, one per state entry and one per transition
    /// (`stateCoverage`, `transitionCoverage`).
    #[arg(long)]
    coverage: bool,
}

/// Run the command; returns the exit code.
pub fn run(a: GenArgs) -> Result<u8> {
    let loaded = load::load(&a.model, false)?;
    let sys = loaded.system_in(a.system.as_deref(), a.config.as_deref())?;
    let program = loaded.lower(sys)?;
    let src = Source::new(&loaded.path, &loaded.source);
    let prefix = statecheck_codegen::common::ident(&program.name).to_lowercase();
    if a.coverage && a.target != "modelica" {
        bail!("--coverage applies to the modelica target only");
    }
    match a.target.as_str() {
        "c" => {
            let dir = out_dir(a.output.as_deref())?;
            let names = statecheck_ir::view::value_names(&loaded.model, &program);
            let files = statecheck_codegen::c::generate_named(&program, &src, &prefix, Some(names));
            write(&dir.join(format!("{}.h", files.prefix)), &files.header)?;
            write(&dir.join(format!("{}.c", files.prefix)), &files.source)?;
            if a.harness {
                let obs = TraceView::new(&loaded.model, &program);
                let h = statecheck_codegen::c_harness(&program, &src, &obs, &prefix);
                write(&dir.join(format!("{}_harness.c", files.prefix)), &h)?;
            }
            eprintln!(
                "wrote {}/{}.h and {}.c{}",
                dir.display(),
                files.prefix,
                files.prefix,
                if a.harness { " and the harness" } else { "" }
            );
            Ok(0)
        }
        "rust" => {
            let dir = out_dir(a.output.as_deref())?;
            let path = dir.join(format!("{prefix}.rs"));
            write(&path, &statecheck_codegen::rust::generate(&program, &src))?;
            eprintln!("wrote {}", path.display());
            Ok(0)
        }
        "modelica" => {
            if a.harness {
                bail!("--harness applies to the c target only");
            }
            let opts = statecheck_codegen::modelica::ModelicaOptions {
                coverage: a.coverage,
            };
            let text = statecheck_codegen::modelica::generate(&program, &loaded.model, &src, &opts)
                .map_err(|e| anyhow::anyhow!("cannot generate Modelica: {e}"))?;
            match a.output.as_deref() {
                Some(f) => {
                    write(Path::new(f), &text)?;
                    eprintln!("wrote {f}");
                }
                None => print!("{text}"),
            }
            Ok(0)
        }
        other => bail!("unknown target `{other}` (expected c, rust or modelica)"),
    }
}

fn out_dir(o: Option<&str>) -> Result<&Path> {
    let Some(d) = o else {
        bail!("give an output directory with -o DIR")
    };
    crate::outpath::create_dir(d, "-o")?;
    Ok(Path::new(d))
}

fn write(path: &Path, text: &str) -> Result<()> {
    crate::outpath::write(path, text.as_bytes())
}
