//! Following `import`s from an editor's document (`docs/components.md`): imported files are
//! read from disk, relative to the document's file, then in the directories of
//! `STATECHECK_PATH`, as the CLI does. Used for the diagnostics of the whole program (only
//! those in the document are shown) and for go-to-definition of imported names.

use crate::convert::Lines;
use lsp_types as lt;
use statecheck_model::imports::{load, FileText, Program, Resolver};
use statecheck_syntax::ast;
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// The path of a `file://` URI (percent-decoded); `None` for other schemes.
pub(crate) fn doc_path(uri: &lt::Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    // `file://host/path` is not a local file; `file:///path` has an empty host.
    let path = rest.strip_prefix("localhost").unwrap_or(rest);
    if !path.starts_with('/') {
        return None;
    }
    let bytes = path.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            let hex = std::str::from_utf8(&bytes[i + 1..i + 3]).ok();
            if let Some(b) = hex.and_then(|h| u8::from_str_radix(h, 16).ok()) {
                out.push(b);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    String::from_utf8(out).ok().map(PathBuf::from)
}

/// The `file://` URI of a path, percent-encoding all but unreserved characters and `/`.
fn path_uri(path: &Path) -> Option<lt::Uri> {
    let mut s = String::from("file://");
    for b in path.to_string_lossy().bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    lt::Uri::from_str(&s).ok()
}

/// Reads imported files: next to the importing file, then on `STATECHECK_PATH`.
struct FsResolver {
    dirs: Vec<PathBuf>,
}

impl Resolver for FsResolver {
    fn resolve(&mut self, from: &str, path: &str) -> Result<FileText, String> {
        let here = Path::new(from).parent().unwrap_or(Path::new("")).join(path);
        let candidates = std::iter::once(here).chain(self.dirs.iter().map(|d| d.join(path)));
        let mut tried = Vec::new();
        for p in candidates {
            if let Ok(text) = std::fs::read_to_string(&p) {
                let key = std::fs::canonicalize(&p)
                    .unwrap_or(p)
                    .to_string_lossy()
                    .into_owned();
                return Ok(FileText {
                    name: key.clone(),
                    key,
                    text,
                });
            }
            tried.push(format!("`{}`", p.display()));
        }
        Err(format!(
            "looked for {}; the editor's server searches next to the file and on STATECHECK_PATH",
            tried.join(", ")
        ))
    }
}

/// The program of a document that imports files: `None` when it imports nothing or is not a
/// local file. The document's own text is the first file (its offsets are unchanged).
pub(crate) fn program(uri: &lt::Uri, text: &str, file: &ast::File) -> Option<Program> {
    if !file.items.iter().any(|i| matches!(i, ast::Item::Import(_))) {
        return None;
    }
    let path = doc_path(uri)?;
    let key = std::fs::canonicalize(&path)
        .unwrap_or(path)
        .to_string_lossy()
        .into_owned();
    let mut resolver = FsResolver {
        dirs: std::env::var_os("STATECHECK_PATH")
            .map(|p| {
                std::env::split_paths(&p)
                    .filter(|d| !d.as_os_str().is_empty())
                    .collect()
            })
            .unwrap_or_default(),
    };
    let root = FileText {
        name: key.clone(),
        key,
        text: text.to_string(),
    };
    Some(load(root, &mut resolver))
}

/// The identifier around byte `offset` of `text`.
pub(crate) fn word_at(text: &str, offset: usize) -> Option<&str> {
    let is_word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let start = text[..offset]
        .char_indices()
        .rev()
        .take_while(|(_, c)| is_word(*c))
        .last()
        .map_or(offset, |(i, _)| i);
    let end = text[offset..]
        .char_indices()
        .find(|(_, c)| !is_word(*c))
        .map_or(text.len(), |(i, _)| offset + i);
    (start < end).then(|| &text[start..end])
}

/// Where an imported top-level item named `name` is declared: its file's URI and the range of
/// its name there.
pub(crate) fn definition(
    uri: &lt::Uri,
    text: &str,
    file: &ast::File,
    name: &str,
) -> Option<lt::Location> {
    let program = program(uri, text, file)?;
    let root_end = program.sources.files.first()?.end;
    let span = program.file.items.iter().find_map(|i| {
        let id = match i {
            ast::Item::Const(c) => &c.name,
            ast::Item::Enum(e) => &e.name,
            ast::Item::Fn(f) => &f.name,
            ast::Item::Chart(c) => &c.name,
            ast::Item::System(s) => &s.name,
            ast::Item::Interface(d) => &d.name,
            ast::Item::Component(c) => &c.name,
            ast::Item::Tick(_) | ast::Item::Import(_) => return None,
        };
        (id.name == name && id.span.start as usize >= root_end).then_some(id.span)
    })?;
    let (f, at) = program.sources.locate(span.start as usize)?;
    let local = statecheck_base::Span::new(at, at + (span.end - span.start) as usize);
    let range = Lines::new(program.sources.file_text(f)).range(local);
    Some(lt::Location::new(path_uri(Path::new(&f.name))?, range))
}

/// One occurrence of a symbol in the program of a document that imports files.
pub(crate) struct Occurrence {
    /// The file it is in (the document's own URI for the document).
    pub uri: lt::Uri,
    /// Where, in that file.
    pub range: lt::Range,
    /// Whether it is the declaration.
    pub is_decl: bool,
}

/// Every occurrence of the symbol at byte `offset` of the document, across the document and
/// the files it imports (the whole program indexed as one file, so a chart, constant or
/// function declared in a library is found in every file that uses it): `None` when the
/// document imports nothing or no symbol is there.
pub(crate) fn occurrences(
    uri: &lt::Uri,
    text: &str,
    file: &ast::File,
    offset: u32,
) -> Option<Vec<Occurrence>> {
    let program = program(uri, text, file)?;
    let root_end = program.sources.files.first()?.end;
    let ix = crate::index::Index::new(&program.file);
    let (_, sym) = ix.at(offset)?;
    let decl = ix.symbols[sym].decl;
    let mut out = Vec::new();
    for s in ix.occurrences_of(sym) {
        let Some((f, at)) = program.sources.locate(s.start as usize) else {
            continue;
        };
        let local = statecheck_base::Span::new(at, at + (s.end - s.start) as usize);
        let range = Lines::new(program.sources.file_text(f)).range(local);
        let file_uri = if (s.start as usize) < root_end {
            uri.clone()
        } else {
            match path_uri(Path::new(&f.name)) {
                Some(u) => u,
                None => continue,
            }
        };
        out.push(Occurrence {
            uri: file_uri,
            range,
            is_decl: s == decl,
        });
    }
    Some(out)
}
