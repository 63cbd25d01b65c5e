//! Reading a model the way `statecheck sim` does: parse, check, choose the system, lower.
//!
//! The steps and their order are the CLI's (`crates/cli/src/load.rs`); what differs is only
//! the outcome: diagnostics become data for the page instead of rendered text.

use serde::Serialize;
use statecheck_base::{Diagnostic, LineIndex};
use statecheck_ir::Program;
use statecheck_model::imports::{FileText, Resolver, Sources};
use statecheck_model::Model;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A model that checked and lowered: what every session runs.
pub struct Loaded {
    /// The path as given.
    pub path: String,
    /// Its text and the text of every file it imports, one after the other: the model's
    /// spans are offsets into it (for transition labels and error positions).
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
/// on failure. Imports are looked up relative to the importing file only.
pub fn load(path: &str, system: Option<&str>) -> Result<Arc<Loaded>, Vec<PageDiagnostic>> {
    load_with(path, system, &[])
}

/// [`load`] with a library search path: imports not found beside the importing file are
/// looked up in each of `lib`, in order (the CLI passes `--lib` and `STATECHECK_PATH`).
pub fn load_with(
    path: &str,
    system: Option<&str>,
    lib: &[PathBuf],
) -> Result<Arc<Loaded>, Vec<PageDiagnostic>> {
    let source = std::fs::read_to_string(path)
        .map_err(|e| vec![plain(path, format!("cannot read `{path}`: {e}"))])?;
    let key = std::fs::canonicalize(path)
        .map_or_else(|_| path.to_string(), |p| p.to_string_lossy().into_owned());
    let mut resolver = FsResolver {
        dirs: lib.to_vec(),
        names: [(key.clone(), PathBuf::from(path))].into_iter().collect(),
    };
    let root = FileText {
        key,
        name: path.to_string(),
        text: source,
    };
    let program = statecheck_model::imports::load(root, &mut resolver);
    load_program(path, program, system)
}

/// Resolves imports on the file system, as the CLI does: relative to the importing file,
/// then in each library directory. Keys are canonical paths.
struct FsResolver {
    dirs: Vec<PathBuf>,
    /// The path each key was found at, to resolve its own imports relative to it.
    names: BTreeMap<String, PathBuf>,
}

impl Resolver for FsResolver {
    fn resolve(&mut self, from: &str, path: &str) -> Result<FileText, String> {
        let from_name = self.names.get(from).cloned().unwrap_or_else(|| from.into());
        let here = from_name.parent().unwrap_or(Path::new("")).join(path);
        let mut tried = Vec::new();
        for p in std::iter::once(here).chain(self.dirs.iter().map(|d| d.join(path))) {
            if let Ok(text) = std::fs::read_to_string(&p) {
                let key = std::fs::canonicalize(&p)
                    .unwrap_or_else(|_| p.clone())
                    .to_string_lossy()
                    .into_owned();
                self.names.entry(key.clone()).or_insert(p.clone());
                return Ok(FileText {
                    key,
                    name: p.to_string_lossy().into_owned(),
                    text,
                });
            }
            tried.push(format!("`{}`", p.display()));
        }
        Err(format!("looked for {}", tried.join(", ")))
    }
}

/// Check and lower a program whose imports are resolved.
fn load_program(
    path: &str,
    program: statecheck_model::imports::Program,
    system: Option<&str>,
) -> Result<Arc<Loaded>, Vec<PageDiagnostic>> {
    let (file, sources, mut diags) = (program.file, program.sources, program.diags);
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
        return Err(to_page(path, &sources, &errors));
    }
    let sys = choose(&model, system).map_err(|m| vec![plain(path, m)])?;
    let program = statecheck_ir::lower(&model, sys).map_err(|d| to_page(path, &sources, &d))?;
    let views = statecheck_ir::view::TraceView::new(&model, &program);
    let mut loaded = Loaded {
        path: path.to_string(),
        source: sources.text.clone(),
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

/// Diagnostics for the page, each in the file (of the program's files) that contains it.
fn to_page(path: &str, sources: &Sources, diags: &[Diagnostic]) -> Vec<PageDiagnostic> {
    diags
        .iter()
        .map(|d| {
            let (file, text, at) = match sources.locate(d.span.start as usize) {
                Some((f, at)) => (f.name.clone(), sources.file_text(f), at),
                None => (
                    path.to_string(),
                    sources.text.as_str(),
                    d.span.start as usize,
                ),
            };
            let (line, col) = LineIndex::new(text).line_col(at as u32);
            PageDiagnostic {
                severity: format!("{:?}", d.severity).to_lowercase(),
                code: d.code.to_string(),
                message: d.message.clone(),
                file,
                line,
                col,
                text: text
                    .lines()
                    .nth(line.saturating_sub(1))
                    .unwrap_or("")
                    .to_string(),
                hint: d.hint.clone(),
            }
        })
        .collect()
}
