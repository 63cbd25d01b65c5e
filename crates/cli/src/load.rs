//! The front half of every command: read, parse, check, choose a system, lower.
//!
//! Imports are resolved here (the model layer does no I/O): a path is looked up relative to
//! the importing file, then in each `--lib` directory, then in each directory of
//! `STATECHECK_PATH`, in that order (docs/components.md).

use crate::diag;
use anyhow::{bail, Context, Result};
use statecheck_base::Diagnostic;
use statecheck_ir::Program;
use statecheck_model::imports::{FileText, Resolver, Sources};
use statecheck_model::Model;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The `--lib` directories of this run (set once by `main`).
static LIB_DIRS: OnceLock<Vec<PathBuf>> = OnceLock::new();

/// Record the `--lib` directories; later calls are ignored.
pub fn set_lib_dirs(dirs: Vec<String>) {
    let _ = LIB_DIRS.set(dirs.into_iter().map(PathBuf::from).collect());
}

/// The library search path: `--lib` directories, then `STATECHECK_PATH`'s.
pub fn search_path() -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = LIB_DIRS.get().cloned().unwrap_or_default();
    if let Some(p) = std::env::var_os("STATECHECK_PATH") {
        dirs.extend(std::env::split_paths(&p).filter(|d| !d.as_os_str().is_empty()));
    }
    dirs
}

/// Resolves imports on the file system. Keys are canonical paths; names are the paths as
/// found (relative to the working directory when the user's paths were).
struct FsResolver {
    dirs: Vec<PathBuf>,
    /// Display name of each key, to build names relative to the importing file's.
    names: std::collections::BTreeMap<String, PathBuf>,
}

/// `a/./b/../c` as `a/c` (lexically; used for display names only).
fn tidy(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir
                if matches!(
                    out.components().next_back(),
                    Some(std::path::Component::Normal(_))
                ) =>
            {
                out.pop();
            }
            c => out.push(c),
        }
    }
    out
}

impl FsResolver {
    fn read(&mut self, display: PathBuf) -> Option<FileText> {
        let text = std::fs::read_to_string(&display).ok()?;
        let key = std::fs::canonicalize(&display)
            .unwrap_or_else(|_| display.clone())
            .to_string_lossy()
            .into_owned();
        let display = tidy(&display);
        self.names.entry(key.clone()).or_insert(display.clone());
        Some(FileText {
            key,
            name: display.to_string_lossy().into_owned(),
            text,
        })
    }
}

impl Resolver for FsResolver {
    fn resolve(&mut self, from: &str, path: &str) -> Result<FileText, String> {
        let from_name = self.names.get(from).cloned().unwrap_or_else(|| from.into());
        let here = from_name.parent().unwrap_or(Path::new("")).join(path);
        let mut tried = vec![here.clone()];
        if let Some(f) = self.read(here) {
            return Ok(f);
        }
        for d in self.dirs.clone() {
            let p = d.join(path);
            tried.push(p.clone());
            if let Some(f) = self.read(p) {
                return Ok(f);
            }
        }
        let tried: Vec<String> = tried.iter().map(|p| format!("`{}`", p.display())).collect();
        Err(format!(
            "looked for {}; add a directory with `--lib DIR` or `STATECHECK_PATH`",
            tried.join(", ")
        ))
    }
}

/// A model file after checking.
pub struct Loaded {
    /// The path as given.
    pub path: String,
    /// The text of the file and of every file it imports, one after the other: every span of
    /// the model is an offset into it (see `sources`).
    pub source: String,
    /// The files of the program, to name the file of a span.
    pub sources: Sources,
    /// The merged syntax tree the model was checked from (`dot` labels transitions with
    /// their text as written).
    pub file: statecheck_syntax::ast::File,
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
    let key = std::fs::canonicalize(path)
        .map_or_else(|_| path.to_string(), |p| p.to_string_lossy().into_owned());
    let mut resolver = FsResolver {
        dirs: search_path(),
        names: [(key.clone(), PathBuf::from(path))].into_iter().collect(),
    };
    let root = FileText {
        key,
        name: path.to_string(),
        text: source,
    };
    let program = statecheck_model::imports::load(root, &mut resolver);
    let (file, sources, mut diags) = (program.file, program.sources, program.diags);
    let source = sources.text.clone();
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
    diag::eprint_sources(&sources, &shown);
    if diags.iter().any(Diagnostic::is_error) {
        return Err(ModelErrors.into());
    }
    Ok(Loaded {
        path: path.to_string(),
        source,
        sources,
        file,
        model,
        diags,
    })
}

impl Loaded {
    /// The configurations the system `base` declares, in order: the model holds one system
    /// `base:NAME` per configuration (`statecheck_model::components`, docs/components.md).
    pub fn configurations(&self, base: &str) -> Vec<String> {
        let prefix = format!("{base}{}", statecheck_model::components::CONFIG_SEP);
        self.model
            .systems
            .iter()
            .filter_map(|s| s.name.strip_prefix(&prefix).map(str::to_string))
            .collect()
    }

    /// [`Loaded::system`], then, with `config`, that system in that configuration (a usage
    /// error when it has no such configuration).
    pub fn system_in(
        &self,
        name: Option<&str>,
        config: Option<&str>,
    ) -> Result<&statecheck_model::System> {
        let sys = self.system(name)?;
        let Some(config) = config else {
            return Ok(sys);
        };
        let base = sys.name.as_str();
        let all = self.configurations(base);
        if all.is_empty() {
            bail!("system `{base}` declares no configurations");
        }
        if !all.iter().any(|c| c == config) {
            bail!(
                "system `{base}` has no configuration `{config}`; it has: {}",
                all.join(", ")
            );
        }
        let sep = statecheck_model::components::CONFIG_SEP;
        self.system(Some(&format!("{base}{sep}{config}")))
    }

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
        // A system's configurations (`Plant:faulty`) are chosen with --config, not counted.
        let sep = statecheck_model::components::CONFIG_SEP;
        let explicit: Vec<_> = systems
            .iter()
            .filter(|s| !s.implicit && !s.name.contains(sep))
            .collect();
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
                diag::eprint_sources(&self.sources, &diags);
                Err(ModelErrors.into())
            }
        }
    }
}
