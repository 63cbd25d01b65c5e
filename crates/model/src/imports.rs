//! Imports: one program from several files, without I/O.
//!
//! `import "path.sc";` brings every item of another file into the program;
//! `import "path.sc" { A, B };` brings in its charts and systems `A` and `B` only (with the
//! charts a listed system instantiates), while its constants, enums, functions and `tick` —
//! what listed items may use — always come along. All items share one namespace: two files
//! declaring the same name are a duplicate (E0102) with both places shown.
//!
//! Reading files is the caller's job, through a [`Resolver`] (the CLI searches the importing
//! file's directory, then `--lib` directories and `STATECHECK_PATH`; tests bring their own in
//! memory). The files are appended to one text, [`Sources::text`], each parsed with
//! [`statecheck_syntax::parse_from`] at its own offset, so every span of the merged tree and of
//! every diagnostic is unique in that text and [`Sources::locate`] names its file. The merged
//! [`ast::File`] lists the imported files' items first, in depth-first post-order, so that a
//! constant may use the constants of the files it imports; the checker sees one flat file.
//!
//! | Code  | Meaning |
//! |-------|---------|
//! | E0140 | an imported file cannot be found or read (the resolver's message says where it looked) |
//! | E0141 | an import cycle: a file imports itself, directly or through others |
//! | E0142 | a name in an import list is not declared by that file |
//! | E0143 | the same file is imported twice by one file |

use crate::suggest::closest;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use std::collections::{BTreeMap, BTreeSet};

/// Longest chain of nested imports; deeper is reported (E0140) instead of recursing further.
pub const MAX_IMPORT_DEPTH: usize = 64;

/// Most files one program may consist of.
pub const MAX_FILES: usize = 4096;

/// One file as a [`Resolver`] found it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileText {
    /// Identity of the file (e.g. its canonical path): two imports naming the same key are the
    /// same file, loaded once.
    pub key: String,
    /// How diagnostics name the file (e.g. the path as the user would type it).
    pub name: String,
    /// Its contents.
    pub text: String,
}

/// Finds imported files. `from` is the [`FileText::key`] of the importing file, `path` the
/// string written in its `import`; `Err` is a message saying what was tried.
pub trait Resolver {
    /// Find and read the file `path` imported by the file `from`.
    fn resolve(&mut self, from: &str, path: &str) -> Result<FileText, String>;
}

/// A map from keys to texts, resolved by joining `path` to the importing key's directory
/// (`/`-separated, `..` and `.` folded): a resolver for tests and for tools that hold files in
/// memory.
#[derive(Clone, Debug, Default)]
pub struct MemoryResolver {
    /// Files by key.
    pub files: BTreeMap<String, String>,
}

/// `path` joined to the directory of the key `from` (`/`-separated, `..` and `.` folded); with
/// `keep_root`, a leading `/` stays (file-system paths), else it is dropped (memory keys).
fn join_key(from: &str, path: &str, keep_root: bool) -> String {
    let dir = from.rsplit_once('/').map_or("", |(d, _)| d);
    let joined = if dir.is_empty() || path.starts_with('/') {
        path.to_string()
    } else {
        format!("{dir}/{path}")
    };
    let mut parts: Vec<&str> = Vec::new();
    for p in joined.split('/') {
        match p {
            "." | "" => {}
            ".." => {
                parts.pop();
            }
            p => parts.push(p),
        }
    }
    let key = parts.join("/");
    if keep_root && joined.starts_with('/') {
        format!("/{key}")
    } else {
        key
    }
}

impl Resolver for MemoryResolver {
    fn resolve(&mut self, from: &str, path: &str) -> Result<FileText, String> {
        let key = join_key(from, path, false);
        match self.files.get(&key) {
            Some(text) => Ok(FileText {
                key: key.clone(),
                name: key,
                text: text.clone(),
            }),
            None => Err(format!("no file `{key}`")),
        }
    }
}

/// A resolver over a function that reads a file: `path` is joined to the importing key's
/// directory as by [`MemoryResolver`] (a leading `/` kept, so keys may be absolute file-system
/// paths) and `read` returns that key's text, or `None`. It searches only the importing file's
/// directory (no library path): for tests, benchmarks and tools that read model files
/// themselves; the CLI's resolver also searches `--lib` and `STATECHECK_PATH`.
pub struct ReadResolver<F>(pub F);

impl<F: FnMut(&str) -> Option<String>> Resolver for ReadResolver<F> {
    fn resolve(&mut self, from: &str, path: &str) -> Result<FileText, String> {
        let key = join_key(from, path, true);
        match (self.0)(&key) {
            Some(text) => Ok(FileText {
                key: key.clone(),
                name: key,
                text,
            }),
            None => Err(format!("cannot read `{key}`")),
        }
    }
}

/// The program of the file `path` (its text `text`), its imports read with `read` through a
/// [`ReadResolver`] — e.g. `load_with(p, text, |k| std::fs::read_to_string(k).ok())`.
pub fn load_with<F: FnMut(&str) -> Option<String>>(path: &str, text: String, read: F) -> Program {
    let root = FileText {
        key: path.to_string(),
        name: path.to_string(),
        text,
    };
    load(root, &mut ReadResolver(read))
}

/// Where one file sits in [`Sources::text`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SourceFile {
    /// The resolver's identity of the file.
    pub key: String,
    /// Its display name.
    pub name: String,
    /// First byte in [`Sources::text`].
    pub start: usize,
    /// One past its last byte.
    pub end: usize,
}

/// Every file of a program, appended to one text (separated by a newline).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sources {
    /// All files' texts, in loading order (the root first).
    pub text: String,
    /// The files, in loading order.
    pub files: Vec<SourceFile>,
}

impl Sources {
    /// The file containing byte `offset` (its end included, where "end of file" errors point)
    /// and the offset within that file.
    pub fn locate(&self, offset: usize) -> Option<(&SourceFile, usize)> {
        let i = self.files.partition_point(|f| f.start <= offset);
        let f = self.files.get(i.checked_sub(1)?)?;
        (offset <= f.end).then(|| (f, offset - f.start))
    }

    /// The text of one file.
    pub fn file_text(&self, f: &SourceFile) -> &str {
        self.text.get(f.start..f.end).unwrap_or("")
    }

    /// Where a span is, as `name:line:col` (1-based; `?` when the span is in no file).
    pub fn position(&self, span: Span) -> String {
        match self.locate(span.start as usize) {
            Some((f, at)) => {
                let idx = statecheck_base::LineIndex::new(self.file_text(f));
                let (l, c) = idx.line_col(at as u32);
                format!("{}:{l}:{c}", f.name)
            }
            None => "?".to_string(),
        }
    }
}

/// The program of a root file and everything it imports.
#[derive(Clone, Debug)]
pub struct Program {
    /// The files and their texts; every span below is an offset into `sources.text`.
    pub sources: Sources,
    /// The merged items: imported files' first (post-order), the root's last.
    pub file: ast::File,
    /// Syntax and import diagnostics of every file.
    pub diags: Vec<Diagnostic>,
}

/// Parse `root` and, through `resolver`, every file it imports, into one merged file.
/// Never fails: unreadable imports, cycles and bad lists are diagnostics.
pub fn load(root: FileText, resolver: &mut dyn Resolver) -> Program {
    let mut l = Loader {
        resolver,
        sources: Sources::default(),
        asts: Vec::new(),
        state: Vec::new(),
        index: BTreeMap::new(),
        wanted: Vec::new(),
        post: Vec::new(),
        stack: Vec::new(),
        diags: Vec::new(),
    };
    if let Some(i) = l.add(root, Span::default()) {
        l.wanted[i] = None;
        l.visit(i);
    }
    l.finish()
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Visit {
    Active,
    Done,
}

struct Loader<'r> {
    resolver: &'r mut dyn Resolver,
    sources: Sources,
    asts: Vec<ast::File>,
    state: Vec<Visit>,
    index: BTreeMap<String, usize>,
    /// Per file: `None` = every item wanted; `Some(names)` = only these charts and systems.
    wanted: Vec<Option<BTreeSet<String>>>,
    post: Vec<usize>,
    stack: Vec<usize>,
    diags: Vec<Diagnostic>,
}

impl Loader<'_> {
    /// Append a file and parse it; `None` (with E0140 at `at`) when the text has no room left.
    fn add(&mut self, f: FileText, at: Span) -> Option<usize> {
        let start = if self.sources.files.is_empty() {
            0
        } else {
            self.sources.text.len() + 1
        };
        let too_big = start.saturating_add(f.text.len()) >= u32::MAX as usize;
        if too_big || self.sources.files.len() >= MAX_FILES {
            self.diags.push(
                Diagnostic::error("E0140", format!("cannot import `{}`", f.name), at)
                    .with_label("too many or too large files")
                    .with_hint(format!(
                        "a program holds at most {MAX_FILES} files and 4 GiB of text"
                    )),
            );
            return None;
        }
        if start > 0 {
            self.sources.text.push('\n');
        }
        self.sources.text.push_str(&f.text);
        let end = self.sources.text.len();
        let (file, diags) = statecheck_syntax::parse_from(&self.sources.text, start);
        self.diags.extend(diags);
        self.index.insert(f.key.clone(), self.asts.len());
        self.sources.files.push(SourceFile {
            key: f.key,
            name: f.name,
            start,
            end,
        });
        self.asts.push(file);
        self.state.push(Visit::Active);
        self.wanted.push(Some(BTreeSet::new()));
        Some(self.asts.len() - 1)
    }

    fn visit(&mut self, i: usize) {
        self.stack.push(i);
        let imports: Vec<ast::ImportDecl> = self.asts[i]
            .items
            .iter()
            .filter_map(|it| match it {
                ast::Item::Import(d) => Some(d.clone()),
                _ => None,
            })
            .collect();
        let mut seen: BTreeMap<String, Span> = BTreeMap::new();
        for d in imports {
            if d.path.is_empty() {
                continue; // E0021 already
            }
            let from = self.sources.files[i].key.clone();
            let found = match self.resolver.resolve(&from, &d.path) {
                Ok(f) => f,
                Err(msg) => {
                    self.diags.push(
                        Diagnostic::error(
                            "E0140",
                            format!("cannot find `{}`", d.path),
                            d.path_span,
                        )
                        .with_label("imported here")
                        .with_hint(msg),
                    );
                    continue;
                }
            };
            if let Some(prev) = seen.insert(found.key.clone(), d.path_span) {
                self.diags.push(
                    Diagnostic::error(
                        "E0143",
                        format!("`{}` is imported twice", d.path),
                        d.path_span,
                    )
                    .with_label("imported again here")
                    .with_secondary(prev, "first imported here")
                    .with_hint("import the file once, listing every name you need"),
                );
                continue;
            }
            let j = match self.index.get(&found.key) {
                Some(&j) if self.state[j] == Visit::Active => {
                    self.cycle(j, &d);
                    continue;
                }
                Some(&j) => j,
                None if self.stack.len() >= MAX_IMPORT_DEPTH => {
                    self.diags.push(
                        Diagnostic::error(
                            "E0140",
                            format!("cannot import `{}`", d.path),
                            d.path_span,
                        )
                        .with_label("imports nested too deeply")
                        .with_hint(format!(
                            "a chain of imports may be at most {MAX_IMPORT_DEPTH} files long"
                        )),
                    );
                    continue;
                }
                None => {
                    let Some(j) = self.add(found, d.path_span) else {
                        continue;
                    };
                    self.visit(j);
                    j
                }
            };
            self.want(j, &d);
        }
        self.stack.pop();
        self.state[i] = Visit::Done;
        self.post.push(i);
    }

    /// E0141 at the import that closes a cycle back to file `j`.
    fn cycle(&mut self, j: usize, d: &ast::ImportDecl) {
        let pos = self.stack.iter().position(|&s| s == j).unwrap_or(0);
        let mut chain: Vec<&str> = self.stack[pos..]
            .iter()
            .map(|&s| self.sources.files[s].name.as_str())
            .collect();
        chain.push(self.sources.files[j].name.as_str());
        self.diags.push(
            Diagnostic::error("E0141", "import cycle", d.path_span)
                .with_label(format!("imports {}", chain.join(" -> ")))
                .with_hint("move what both files need into a third file that both import"),
        );
    }

    /// Record what an import of file `j` brings in; E0142 for names `j` does not declare.
    fn want(&mut self, j: usize, d: &ast::ImportDecl) {
        let Some(names) = &d.names else {
            self.wanted[j] = None;
            return;
        };
        let declared: Vec<&str> = self.asts[j].items.iter().filter_map(item_name).collect();
        let mut add = BTreeSet::new();
        for n in names {
            if declared.contains(&n.name.as_str()) {
                add.insert(n.name.clone());
                continue;
            }
            let mut diag = Diagnostic::error(
                "E0142",
                format!("`{}` does not declare `{}`", d.path, n.name),
                n.span,
            )
            .with_label("not in that file");
            if let Some(s) = closest(&n.name, declared.iter().copied()) {
                diag = diag.with_hint(format!("did you mean `{s}`?"));
            }
            self.diags.push(diag);
        }
        if let Some(w) = &mut self.wanted[j] {
            w.extend(add);
        }
    }

    fn finish(mut self) -> Program {
        let mut items = Vec::new();
        for &i in &self.post {
            let file = std::mem::take(&mut self.asts[i]);
            let keep = kept_charts(&file, self.wanted[i].as_ref());
            items.extend(file.items.into_iter().filter(|it| match it {
                ast::Item::Chart(c) => keep.as_ref().is_none_or(|k| k.contains(&c.name.name)),
                ast::Item::System(s) => keep.as_ref().is_none_or(|k| k.contains(&s.name.name)),
                ast::Item::Component(c) => keep.as_ref().is_none_or(|k| k.contains(&c.name.name)),
                _ => true,
            }));
        }
        self.diags.sort_by_key(|d| (d.span.start, d.span.end));
        Program {
            sources: self.sources,
            file: ast::File { items },
            diags: self.diags,
        }
    }
}

/// The charts, components and systems kept of a file imported with lists `wanted` (`None`:
/// all): the listed ones and the charts and components their systems and components
/// instantiate (transitively) or bind in configurations.
fn kept_charts(file: &ast::File, wanted: Option<&BTreeSet<String>>) -> Option<BTreeSet<String>> {
    let mut keep = wanted?.clone();
    // Each round adds what the kept systems and components use; a file has finitely many.
    loop {
        let before = keep.len();
        for it in &file.items {
            let body = match it {
                ast::Item::System(s) => s,
                ast::Item::Component(c) => &c.body,
                _ => continue,
            };
            if keep.contains(&body.name.name) {
                keep.extend(body.instances.iter().map(|i| i.chart.name.clone()));
                let bound = body.configurations.iter().flat_map(|c| &c.bindings);
                keep.extend(bound.map(|b| b.chart.name.clone()));
            }
        }
        if keep.len() == before {
            return Some(keep);
        }
    }
}

/// The name an item declares, if any.
fn item_name(it: &ast::Item) -> Option<&str> {
    Some(match it {
        ast::Item::Const(c) => &c.name.name,
        ast::Item::Enum(e) => &e.name.name,
        ast::Item::Fn(f) => &f.name.name,
        ast::Item::Chart(c) => &c.name.name,
        ast::Item::System(s) => &s.name.name,
        ast::Item::Interface(i) => &i.name.name,
        ast::Item::Component(c) => &c.name.name,
        ast::Item::Tick(_) | ast::Item::Import(_) => return None,
    })
}
