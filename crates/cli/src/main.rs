//! `statecheck`: simulate, check and draw statechart models written in the `.sc` language.
//!
//! The binary is the only place that does I/O: it reads model and scenario files, renders
//! diagnostics, traces and reports, and maps outcomes to exit codes
//! (0 ok, 1 model or run-time error, 2 usage error, 4 a property was violated in a run).

mod analyse_choices;
mod analyse_cmd;
mod diag;
mod diag_json;
mod export_cmd;
mod fmt_cmd;
mod gen_cmd;
mod load;
mod outpath;
mod output;
mod serve_cmd;
mod show_cmd;
mod sim_cmd;
mod sim_sink;
mod supervisor;
mod synth_cmd;
mod verify_cmd;

use anyhow::Result;
use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Statechart simulation, verification and code generation for supervisory controllers.
#[derive(Parser)]
#[command(name = "statecheck", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// A library directory searched for imported files (after the importing file's own
    /// directory; repeatable; `STATECHECK_PATH` directories come after these).
    #[arg(long = "lib", value_name = "DIR", global = true)]
    lib: Vec<String>,
    /// How diagnostics are printed on standard error: `human` (rendered, the default) or
    /// `json` (one JSON object per line; docs/tools.md).
    #[arg(long, global = true, value_enum, default_value_t = MessageFormat::Human)]
    message_format: MessageFormat,
}

/// The values of `--message-format`.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum MessageFormat {
    /// Rendered for people.
    Human,
    /// One JSON object per diagnostic and line.
    Json,
}

#[derive(Subcommand)]
enum Command {
    /// Parse, type-check and lint a model; exit 1 if it has errors.
    Check {
        /// The `.sc` model file.
        model: String,
    },
    /// Print the design-rule findings of a model.
    Lint {
        /// The `.sc` model file.
        model: String,
        /// Exit 1 when there are warnings.
        #[arg(long)]
        deny_warnings: bool,
    },
    /// Simulate a system with a scenario or random inputs.
    Sim(sim_cmd::SimArgs),
    /// Verify a system's properties exhaustively.
    Verify(verify_cmd::VerifyArgs),
    /// Generate code (C99, Rust, Modelica) from a system.
    Gen(gen_cmd::GenArgs),
    /// Export a system to another tool's input format.
    #[command(subcommand)]
    Export(export_cmd::ExportCommand),
    /// Synthesize a maximally permissive, controllable, nonblocking supervisor.
    Synth(synth_cmd::SynthArgs),
    /// Serve the validation studio: a local web page that animates the charts.
    Serve(serve_cmd::ServeArgs),
    /// The exact times of a model's continuous motion: clock readings, or, along a scenario,
    /// when each critical point is reached (docs/hybrid.md).
    Analyse(analyse_cmd::AnalyseArgs),
    /// Print a model as the checker sees it: `--discretized` shows continuous variables as
    /// grid variables, modes and timers (docs/hybrid.md).
    Show(show_cmd::ShowArgs),
    /// Rewrite model files in the canonical layout (`--check`: only report).
    Fmt(fmt_cmd::FmtArgs),
    /// Explain a diagnostic code (`statecheck explain E0111`); without a code, list them all.
    Explain {
        /// The code, e.g. E0111.
        code: Option<String>,
    },
    /// Run the language server on standard input and output (for editors; docs/tools.md).
    Lsp,
    /// Draw a system's charts as Graphviz DOT, optionally with coverage counts.
    Dot {
        /// The `.sc` model file.
        model: String,
        /// The system (or chart) to draw.
        #[arg(long)]
        system: Option<String>,
        /// A coverage JSON file written by `statecheck sim --coverage FILE`.
        #[arg(long)]
        coverage: Option<String>,
        /// Write to this file instead of standard output.
        #[arg(short, long)]
        output: Option<String>,
        /// Write SVG instead of DOT, drawn by Graphviz's `dot -Tsvg` (Graphviz must be
        /// installed: a missing `dot` is error E0160, exit 2).
        #[arg(long)]
        svg: bool,
    },
}

/// An error that maps to a specific exit code after its message was printed.
#[derive(Debug)]
pub struct Exit(pub u8);

impl std::fmt::Display for Exit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "exit {}", self.0)
    }
}

impl std::error::Error for Exit {}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = run(cli);
    // A native successor generator still compiling in the background (the explicit engine's
    // `auto` backend) must not outlive the run.
    statecheck_native::kill_compilers();
    match result {
        Ok(code) => ExitCode::from(code),
        Err(e) => {
            if let Some(Exit(code)) = e.downcast_ref::<Exit>() {
                return ExitCode::from(*code);
            }
            if e.downcast_ref::<load::ModelErrors>().is_some() {
                return ExitCode::from(1);
            }
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn run(cli: Cli) -> Result<u8> {
    load::set_lib_dirs(cli.lib);
    diag_json::set_json(cli.message_format == MessageFormat::Json);
    match cli.command {
        Command::Check { model } => {
            let loaded = load::load(&model, true)?;
            for sys in &loaded.model.systems {
                loaded.lower(sys)?;
            }
            let warnings = loaded.diags.iter().filter(|d| !d.is_error()).count();
            let charts = loaded.model.charts.len();
            let systems = loaded.model.systems.iter().filter(|s| !s.implicit).count();
            eprintln!("ok: {model}: {charts} chart(s), {systems} system(s), {warnings} warning(s)");
            Ok(0)
        }
        Command::Lint {
            model,
            deny_warnings,
        } => {
            let loaded = load::load(&model, true)?;
            let warnings = loaded.diags.iter().filter(|d| !d.is_error()).count();
            eprintln!("{model}: {warnings} finding(s)");
            Ok(if deny_warnings && warnings > 0 { 1 } else { 0 })
        }
        Command::Sim(args) => sim_cmd::run(args),
        Command::Verify(args) => verify_cmd::run(args),
        Command::Gen(args) => gen_cmd::run(args),
        Command::Export(c) => export_cmd::run(c),
        Command::Synth(args) => synth_cmd::run(args),
        Command::Serve(args) => serve_cmd::run(args),
        Command::Fmt(args) => fmt_cmd::run(args),
        Command::Show(args) => show_cmd::run(args),
        Command::Analyse(args) => analyse_cmd::run(args),
        Command::Explain { code } => explain(code.as_deref()),
        Command::Lsp => {
            statecheck_lsp::serve_stdio()?;
            Ok(0)
        }
        Command::Dot {
            model,
            system,
            coverage,
            output,
            svg,
        } => {
            let loaded = load::load(&model, false)?;
            let sys = loaded.system(system.as_deref())?;
            let program = loaded.lower(sys)?;
            let counts = match coverage {
                Some(f) => {
                    outpath::note_input(&f);
                    let text = std::fs::read_to_string(&f)
                        .map_err(|e| anyhow::anyhow!("cannot read `{f}`: {e}"))?;
                    let v: serde_json::Value = serde_json::from_str(&text)
                        .map_err(|e| anyhow::anyhow!("`{f}` is not JSON: {e}"))?;
                    Some(
                        output::coverage::from_json(&program, &v)
                            .map_err(|e| anyhow::anyhow!("{f}: {e}"))?,
                    )
                }
                None => None,
            };
            let written = output::dot_text::Written::new(&loaded.source, &loaded.file);
            let dot = output::dot::render(&loaded.model, &program, &written, counts.as_deref());
            if svg {
                let svg = output::svg::from_dot(&dot)?;
                write_out(output.as_deref(), &svg)?;
            } else {
                write_out(output.as_deref(), &dot)?;
            }
            Ok(0)
        }
    }
}

/// `statecheck explain [CODE]`: the page of a code from the one table of codes, or the list.
fn explain(code: Option<&str>) -> Result<u8> {
    use statecheck_base::codes;
    let Some(code) = code else {
        for c in codes::CODES {
            println!("{}  {}", c.code, c.title);
        }
        return Ok(0);
    };
    match codes::lookup(code) {
        Some(c) => {
            print!("{}", codes::page(c));
            Ok(0)
        }
        None => anyhow::bail!("unknown diagnostic code `{code}`; `statecheck explain` lists them"),
    }
}

/// Write to a file, or to standard output when no file is given.
pub fn write_out(path: Option<&str>, text: &str) -> Result<()> {
    use std::io::Write;
    match path {
        Some(p) => outpath::write(std::path::Path::new(p), text.as_bytes()),
        None => {
            let mut out = std::io::stdout().lock();
            // A closed pipe (e.g. `| head`) is not an error worth reporting.
            let _ = out.write_all(text.as_bytes());
            Ok(())
        }
    }
}
