//! The front half of every command: read, parse, check, choose a system, lower.

use crate::diag;
use anyhow::{bail, Context, Result};
use statecheck_base::Diagnostic;
use statecheck_ir::Program;
use statecheck_model::Model;

/// A model file after checking.
pub struct Loaded {
    /// The path as given.
    pub path: String,
    /// Its text.
    pub source: String,
    /// The checked model.
    pub model: Model,
    /// All diagnostics (errors, warnings).
    pub diags: Vec<Diagnostic>,
}

/// Signals "the model has errors; they were printed" (exit code 1).
#[derive(Debug)]
pub struct ModelErrors;

impl std::fmt::Display for ModelErrors {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "the model has errors")
    }
}

impl std::error::Error for ModelErrors {}

/// Read and check a model; print its diagnostics (warnings only if `show_warnings`).
pub fn load(path: &str, show_warnings: bool) -> Result<Loaded> {
    crate::outpath::note_input(path);
    let bytes = std::fs::read(path).with_context(|| format!("cannot read `{path}`"))?;
    let source = match String::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => {
            // A model error at the offending byte (exit 1), not a failure to read (exit 2).
            let at = e.utf8_error().valid_up_to();
            let bad = e.as_bytes().get(at).copied().unwrap_or(0);
            let shown = String::from_utf8_lossy(e.as_bytes()).into_owned();
            let d = Diagnostic::error(
                "E0005",
                format!("the file is not valid UTF-8 (byte 0x{bad:02X} at offset {at})"),
                // In the text shown the byte became U+FFFD, three bytes long.
                statecheck_base::Span::new(at, at + '\u{FFFD}'.len_utf8()),
            )
            .with_label("not UTF-8")
            .with_hint("save the file as UTF-8");
            diag::eprint(path, &shown, &[d]);
            return Err(ModelErrors.into());
        }
    };
    let (file, mut diags) = statecheck_syntax::parse(&source);
    let (model, more) = if diags.iter().any(Diagnostic::is_error) {
        // Still check what parsed, to report name and type errors in the same run, but drop
        // diagnostics that may be consequences of the syntax errors' recovery.
        let (m, more) = statecheck_model::check(&file);
        (
            m,
            more.into_iter()
                .filter(|d| d.is_error() && d.code != "E0101")
                .collect::<Vec<_>>(),
        )
    } else {
        statecheck_model::check(&file)
    };
    diags.extend(more);
    diags.sort_by_key(|d| (d.span.start, d.span.end));
    let shown: Vec<Diagnostic> = diags
        .iter()
        .filter(|d| show_warnings || d.is_error())
        .cloned()
        .collect();
    diag::eprint(path, &source, &shown);
    if diags.iter().any(Diagnostic::is_error) {
        return Err(ModelErrors.into());
    }
    Ok(Loaded {
        path: path.to_string(),
        source,
        model,
        diags,
    })
}

impl Loaded {
    /// Choose the system: by name, else the only explicit one, else the only chart.
    pub fn system(&self, name: Option<&str>) -> Result<&statecheck_model::System> {
        let systems = &self.model.systems;
        if let Some(n) = name {
            return match self.model.system(n) {
                Some(s) => Ok(s),
                None => bail!(
                    "no system or chart named `{n}` in {}; available: {}",
                    self.path,
                    systems
                        .iter()
                        .map(|s| s.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            };
        }
        let explicit: Vec<_> = systems.iter().filter(|s| !s.implicit).collect();
        match explicit.as_slice() {
            [one] => return Ok(one),
            [] => {}
            many => bail!(
                "{} declares several systems; choose one with --system ({})",
                self.path,
                many.iter()
                    .map(|s| s.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }
        match systems.as_slice() {
            [one] => Ok(one),
            [] => bail!("{} declares no chart", self.path),
            many => bail!(
                "{} declares several charts; choose one with --system ({})",
                self.path,
                many.iter()
                    .map(|s| s.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }
    }

    /// Lower a system, printing any lowering diagnostics.
    pub fn lower(&self, sys: &statecheck_model::System) -> Result<Program> {
        match statecheck_ir::lower(&self.model, sys) {
            Ok(p) => Ok(p),
            Err(diags) => {
                diag::eprint(&self.path, &self.source, &diags);
                Err(ModelErrors.into())
            }
        }
    }
}
