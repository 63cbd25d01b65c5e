//! Reading a model the way `statecheck sim` does: parse, check, choose the system, lower.
//!
//! The steps and their order are the CLI's (`crates/cli/src/load.rs`); what differs is only
//! the outcome: diagnostics become data for the page instead of rendered text.

use serde::Serialize;
use statecheck_base::{Diagnostic, LineIndex};
use statecheck_ir::Program;
use statecheck_model::Model;
use std::sync::Arc;

/// A model that checked and lowered: what every session runs.
pub struct Loaded {
    /// The path as given.
    pub path: String,
    /// Its text (for transition labels and error positions).
    pub source: String,
    /// The checked model.
    pub model: Model,
    /// The lowered system.
    pub program: Program,
    /// What a tick shows (active states, values, events), computed once.
    pub views: statecheck_ir::view::TraceView,
    /// The model description for the page (`describe::describe`), serialized once.
    pub description: String,
}

/// A diagnostic as the page shows it: `file:line:col`, code, message, hint.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct PageDiagnostic {
    /// `error`, `warning` or `note`.
    pub severity: String,
    /// Stable code, e.g. `E0102` (empty for file and system-choice problems).
    pub code: String,
    /// One-line summary.
    pub message: String,
    /// The file.
    pub file: String,
    /// 1-based line (0 when the problem has no position).
    pub line: usize,
    /// 1-based column (0 when the problem has no position).
    pub col: usize,
    /// The source line, for context.
    pub text: String,
    /// How to fix it, if known.
    pub hint: Option<String>,
}

/// Read, parse, check and lower `path` (system `system`, or the only one); the diagnostics
/// on failure.
pub fn load(path: &str, system: Option<&str>) -> Result<Arc<Loaded>, Vec<PageDiagnostic>> {
    let source = std::fs::read_to_string(path)
        .map_err(|e| vec![plain(path, format!("cannot read `{path}`: {e}"))])?;
    load_source(path, source, system)
}

/// [`load`] on text already read.
pub fn load_source(
    path: &str,
    source: String,
    system: Option<&str>,
) -> Result<Arc<Loaded>, Vec<PageDiagnostic>> {
    let (file, mut diags) = statecheck_syntax::parse(&source);
    let (model, more) = if diags.iter().any(Diagnostic::is_error) {
        // As the CLI: check what parsed, keep only errors that are not recovery artefacts.
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
    if diags.iter().any(Diagnostic::is_error) {
        let errors: Vec<Diagnostic> = diags.into_iter().filter(Diagnostic::is_error).collect();
        return Err(to_page(path, &source, &errors));
    }
    let sys = choose(&model, system).map_err(|m| vec![plain(path, m)])?;
    let program = statecheck_ir::lower(&model, sys).map_err(|d| to_page(path, &source, &d))?;
    let views = statecheck_ir::view::TraceView::new(&model, &program);
    let mut loaded = Loaded {
        path: path.to_string(),
        source,
        model,
        program,
        views,
        description: String::new(),
    };
    loaded.description = crate::describe::describe(&loaded).to_string();
    Ok(Arc::new(loaded))
}

/// The CLI's rule: by name, else the only explicit system, else the only chart.
fn choose<'m>(
    model: &'m Model,
    name: Option<&str>,
) -> Result<&'m statecheck_model::System, String> {
    let names = |it: &mut dyn Iterator<Item = &statecheck_model::System>| {
        it.map(|s| s.name.as_str()).collect::<Vec<_>>().join(", ")
    };
    if let Some(n) = name {
        return model.system(n).ok_or_else(|| {
            format!(
                "no system or chart named `{n}`; available: {}",
                names(&mut model.systems.iter())
            )
        });
    }
    // A system's configurations (`Plant:faulty`) are named explicitly, not counted.
    let sep = statecheck_model::components::CONFIG_SEP;
    let explicit: Vec<_> = model
        .systems
        .iter()
        .filter(|s| !s.implicit && !s.name.contains(sep))
        .collect();
    match explicit.as_slice() {
        [one] => return Ok(one),
        [] => {}
        many => {
            return Err(format!(
                "the file declares several systems; choose one with --system ({})",
                names(&mut many.iter().copied())
            ))
        }
    }
    match model.systems.as_slice() {
        [one] => Ok(one),
        [] => Err("the file declares no chart".into()),
        many => Err(format!(
            "the file declares several charts; choose one with --system ({})",
            names(&mut many.iter())
        )),
    }
}

fn plain(path: &str, message: String) -> PageDiagnostic {
    PageDiagnostic {
        severity: "error".into(),
        code: String::new(),
        message,
        file: path.to_string(),
        line: 0,
        col: 0,
        text: String::new(),
        hint: None,
    }
}

fn to_page(path: &str, source: &str, diags: &[Diagnostic]) -> Vec<PageDiagnostic> {
    let idx = LineIndex::new(source);
    diags
        .iter()
        .map(|d| {
            let (line, col) = idx.line_col(d.span.start);
            PageDiagnostic {
                severity: format!("{:?}", d.severity).to_lowercase(),
                code: d.code.to_string(),
                message: d.message.clone(),
                file: path.to_string(),
                line,
                col,
                text: source
                    .lines()
                    .nth(line.saturating_sub(1))
                    .unwrap_or("")
                    .to_string(),
                hint: d.hint.clone(),
            }
        })
        .collect()
}
