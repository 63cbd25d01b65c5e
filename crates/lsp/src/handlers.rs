//! One function per capability: a document and the request's parameters in, the answer out.

use crate::convert::Lines;
use crate::index::{Index, SymKind};
use crate::Doc;
use lsp_types as lt;
use statecheck_base::{Diagnostic, Severity, Span};
use statecheck_syntax::ast::VarKind;
use std::collections::HashMap;

/// Request parameters that name a document.
pub trait HasUri {
    /// The document.
    fn uri(&self) -> &lt::Uri;
}

macro_rules! has_uri {
    ($($t:ty => |$p:ident| $e:expr;)*) => {
        $(impl HasUri for $t {
            fn uri(&self) -> &lt::Uri {
                let $p = self;
                &$e.uri
            }
        })*
    };
}

has_uri! {
    lt::HoverParams => |p| p.text_document_position_params.text_document;
    lt::GotoDefinitionParams => |p| p.text_document_position_params.text_document;
    lt::ReferenceParams => |p| p.text_document_position.text_document;
    lt::RenameParams => |p| p.text_document_position.text_document;
    lt::CompletionParams => |p| p.text_document_position.text_document;
    lt::DocumentSymbolParams => |p| p.text_document;
    lt::DocumentFormattingParams => |p| p.text_document;
    lt::CodeActionParams => |p| p.text_document;
}

/// Parse and check a text: its diagnostics (syntax first; the checker's too, except the
/// name errors that may only follow from the syntax errors' recovery, as in the CLI).
///
/// A document that imports files is checked with them (read from disk, `imports.rs`); only the
/// diagnostics in the document itself are kept.
fn check(uri: &lt::Uri, text: &str) -> Vec<Diagnostic> {
    let (file, mut diags) = statecheck_syntax::parse(text);
    if let Some(program) = crate::imports::program(uri, text, &file) {
        let root_end = program.sources.files.first().map_or(text.len(), |f| f.end);
        diags = program.diags;
        let syntax_errors = diags.iter().any(Diagnostic::is_error);
        let (_, more) = statecheck_model::check(&program.file);
        diags.extend(
            more.into_iter()
                .filter(|d| !syntax_errors || (d.is_error() && d.code != "E0101")),
        );
        diags.retain(|d| (d.span.start as usize) < root_end);
        diags.sort_by_key(|d| (d.span.start, d.span.end));
        return diags;
    }
    let syntax_errors = diags.iter().any(Diagnostic::is_error);
    let (_, more) = statecheck_model::check(&file);
    diags.extend(
        more.into_iter()
            .filter(|d| !syntax_errors || (d.is_error() && d.code != "E0101")),
    );
    diags.sort_by_key(|d| (d.span.start, d.span.end));
    diags
}

fn to_lsp(lines: &Lines<'_>, d: &Diagnostic) -> lt::Diagnostic {
    let severity = match d.severity {
        Severity::Error => lt::DiagnosticSeverity::ERROR,
        Severity::Warning => lt::DiagnosticSeverity::WARNING,
        Severity::Note => lt::DiagnosticSeverity::INFORMATION,
    };
    let mut message = d.message.clone();
    if let Some(h) = &d.hint {
        message.push_str("\nhelp: ");
        message.push_str(h);
    }
    lt::Diagnostic {
        range: lines.range(d.span),
        severity: Some(severity),
        code: Some(lt::NumberOrString::String(d.code.to_string())),
        source: Some("statecheck".to_string()),
        message,
        ..lt::Diagnostic::default()
    }
}

/// The diagnostics of a text, for `textDocument/publishDiagnostics`.
pub fn diagnostics(uri: &lt::Uri, text: &str) -> Vec<lt::Diagnostic> {
    let lines = Lines::new(text);
    check(uri, text).iter().map(|d| to_lsp(&lines, d)).collect()
}

fn index(text: &str) -> Index {
    let (file, _) = statecheck_syntax::parse(text);
    Index::new(&file)
}

fn kind_word(k: SymKind) -> &'static str {
    match k {
        SymKind::Const => "constant",
        SymKind::Enum => "enum",
        SymKind::Variant => "enum literal",
        SymKind::Fn => "function",
        SymKind::Param => "parameter",
        SymKind::Chart => "chart",
        SymKind::System => "system",
        SymKind::Var(VarKind::Input) => "input",
        SymKind::Var(VarKind::Output) => "output",
        SymKind::Var(VarKind::Local) => "local variable",
        SymKind::Event(VarKind::Input) => "input event",
        SymKind::Event(VarKind::Output) => "output event",
        SymKind::Event(VarKind::Local) => "local event",
        SymKind::State => "state",
        SymKind::Region => "region",
        SymKind::Junction => "junction",
        SymKind::Instance => "instance",
        SymKind::Property => "property",
    }
}

/// The first line of a declaration (for a state or chart: up to its `{`).
fn declaration_text(text: &str, full: Span) -> String {
    let s = text.get(full.range()).unwrap_or("");
    let head = s.split('{').next().unwrap_or(s);
    let line = head.lines().next().unwrap_or("").trim();
    line.trim_end_matches(';').trim().to_string()
}

/// Hover: the symbol's kind and declaration (for a variable, its type and range as
/// declared), over the occurrence's range.
pub fn hover(doc: &Doc<'_>, p: lt::HoverParams) -> Option<lt::Hover> {
    let lines = Lines::new(doc.text);
    let ix = index(doc.text);
    let off = lines.offset(p.text_document_position_params.position) as u32;
    let (span, sym) = ix.at(off)?;
    let s = &ix.symbols[sym];
    let mut value = format!(
        "{} `{}`\n\n```statecheck\n{}\n```",
        kind_word(s.kind),
        s.name,
        declaration_text(doc.text, s.full)
    );
    if let Some(c) = &s.of_chart {
        value.push_str(&format!("\n\ninstance of chart `{c}`"));
    }
    Some(lt::Hover {
        contents: lt::HoverContents::Markup(lt::MarkupContent {
            kind: lt::MarkupKind::Markdown,
            value,
        }),
        range: Some(lines.range(span)),
    })
}

/// Go to definition: where the symbol under the cursor is declared.
pub fn definition(
    doc: &Doc<'_>,
    p: lt::GotoDefinitionParams,
) -> Option<lt::GotoDefinitionResponse> {
    let lines = Lines::new(doc.text);
    let ix = index(doc.text);
    let off = lines.offset(p.text_document_position_params.position) as u32;
    let Some((_, sym)) = ix.at(off) else {
        // Not declared in this file: an imported chart, system, constant, enum or function.
        let name = crate::imports::word_at(doc.text, off as usize)?;
        let (file, _) = statecheck_syntax::parse(doc.text);
        let loc = crate::imports::definition(doc.uri, doc.text, &file, name)?;
        return Some(lt::GotoDefinitionResponse::Scalar(loc));
    };
    let loc = lt::Location::new(doc.uri.clone(), lines.range(ix.symbols[sym].decl));
    Some(lt::GotoDefinitionResponse::Scalar(loc))
}

/// Find references: every occurrence, the declaration included if asked.
pub fn references(doc: &Doc<'_>, p: lt::ReferenceParams) -> Option<Vec<lt::Location>> {
    let lines = Lines::new(doc.text);
    let off = lines.offset(p.text_document_position.position) as u32;
    if let Some(all) = across_imports(doc, off) {
        return Some(
            all.into_iter()
                .filter(|o| p.context.include_declaration || !o.is_decl)
                .map(|o| lt::Location::new(o.uri, o.range))
                .collect(),
        );
    }
    let ix = index(doc.text);
    let (_, sym) = ix.at(off)?;
    let decl = ix.symbols[sym].decl;
    Some(
        ix.occurrences_of(sym)
            .into_iter()
            .filter(|s| p.context.include_declaration || *s != decl)
            .map(|s| lt::Location::new(doc.uri.clone(), lines.range(s)))
            .collect(),
    )
}

/// The occurrences of the symbol at `off` across the document and its imports, when the
/// document imports files and the symbol is found in the whole program.
fn across_imports(doc: &Doc<'_>, off: u32) -> Option<Vec<crate::imports::Occurrence>> {
    let (file, _) = statecheck_syntax::parse(doc.text);
    crate::imports::occurrences(doc.uri, doc.text, &file, off)
}

/// A workspace edit of several documents (the edits of each in the order given).
#[allow(clippy::mutable_key_type)] // reason: the protocol type's map is keyed by `Uri`
fn edits_by_file(edits: impl Iterator<Item = (lt::Uri, lt::TextEdit)>) -> lt::WorkspaceEdit {
    let mut changes: HashMap<lt::Uri, Vec<lt::TextEdit>> = HashMap::new();
    for (uri, edit) in edits {
        changes.entry(uri).or_default().push(edit);
    }
    lt::WorkspaceEdit {
        changes: Some(changes),
        ..lt::WorkspaceEdit::default()
    }
}

/// A workspace edit of one document. (`Uri` caches its parse lazily, which clippy counts as
/// interior mutability in a map key; its hash and equality are those of the text.)
#[allow(clippy::mutable_key_type)] // reason: the protocol type's map is keyed by `Uri`
fn edit_of(uri: &lt::Uri, edits: Vec<lt::TextEdit>) -> lt::WorkspaceEdit {
    let mut changes = HashMap::new();
    changes.insert(uri.clone(), edits);
    lt::WorkspaceEdit {
        changes: Some(changes),
        ..lt::WorkspaceEdit::default()
    }
}

fn is_identifier(s: &str) -> bool {
    let mut cs = s.chars();
    cs.next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && cs.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Rename: every occurrence of the symbol under the cursor (nothing if the new name is not
/// an identifier).
pub fn rename(doc: &Doc<'_>, p: lt::RenameParams) -> Option<lt::WorkspaceEdit> {
    if !is_identifier(&p.new_name) {
        return None;
    }
    let lines = Lines::new(doc.text);
    let off = lines.offset(p.text_document_position.position) as u32;
    if let Some(all) = across_imports(doc, off) {
        let edits = all
            .into_iter()
            .map(|o| (o.uri, lt::TextEdit::new(o.range, p.new_name.clone())));
        return Some(edits_by_file(edits));
    }
    let ix = index(doc.text);
    let (_, sym) = ix.at(off)?;
    let edits = ix
        .occurrences_of(sym)
        .into_iter()
        .map(|s| lt::TextEdit::new(lines.range(s), p.new_name.clone()))
        .collect();
    Some(edit_of(doc.uri, edits))
}

/// Completion: the names usable at the cursor — in a chart, its states, events and
/// variables; everywhere, constants, enum literals and functions; in a system, its
/// instances.
pub fn completion(doc: &Doc<'_>, p: lt::CompletionParams) -> Option<lt::CompletionResponse> {
    let lines = Lines::new(doc.text);
    let ix = index(doc.text);
    let off = lines.offset(p.text_document_position.position) as u32;
    let chart = ix.chart_at(off);
    let system = ix
        .symbols
        .iter()
        .position(|s| s.kind == SymKind::System && s.full.start <= off && off <= s.full.end);
    let mut items = Vec::new();
    let mut seen = std::collections::BTreeSet::new();
    for (i, s) in ix.symbols.iter().enumerate() {
        let visible = match s.kind {
            SymKind::Const | SymKind::Variant | SymKind::Fn => true,
            SymKind::Var(_)
            | SymKind::Event(_)
            | SymKind::State
            | SymKind::Region
            | SymKind::Junction => chart.is_some_and(|c| ix.is_inside(i, c)),
            SymKind::Instance => system.is_some_and(|sy| s.parent == Some(sy)),
            _ => false,
        };
        if !visible || !seen.insert((s.name.clone(), kind_word(s.kind))) {
            continue;
        }
        let kind = match s.kind {
            SymKind::Const => lt::CompletionItemKind::CONSTANT,
            SymKind::Variant => lt::CompletionItemKind::ENUM_MEMBER,
            SymKind::Fn => lt::CompletionItemKind::FUNCTION,
            SymKind::Event(_) => lt::CompletionItemKind::EVENT,
            SymKind::Var(_) => lt::CompletionItemKind::VARIABLE,
            SymKind::Instance => lt::CompletionItemKind::MODULE,
            _ => lt::CompletionItemKind::CLASS,
        };
        items.push(lt::CompletionItem {
            label: s.name.clone(),
            kind: Some(kind),
            detail: Some(declaration_text(doc.text, s.full)),
            ..lt::CompletionItem::default()
        });
    }
    Some(lt::CompletionResponse::Array(items))
}

/// Document symbols: charts with their variables, properties and state hierarchy; systems
/// with their instances, properties and observers; constants, enums and functions.
pub fn symbols(doc: &Doc<'_>, _p: lt::DocumentSymbolParams) -> Option<lt::DocumentSymbolResponse> {
    let lines = Lines::new(doc.text);
    let ix = index(doc.text);
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); ix.symbols.len()];
    let mut roots = Vec::new();
    for (i, s) in ix.symbols.iter().enumerate() {
        if s.kind == SymKind::Param {
            continue;
        }
        match s.parent {
            Some(p) => children[p].push(i),
            None => roots.push(i),
        }
    }
    fn build(
        ix: &Index,
        lines: &Lines<'_>,
        children: &[Vec<usize>],
        i: usize,
        depth: u32,
    ) -> lt::DocumentSymbol {
        let s = &ix.symbols[i];
        let kind = match s.kind {
            SymKind::Const => lt::SymbolKind::CONSTANT,
            SymKind::Enum => lt::SymbolKind::ENUM,
            SymKind::Variant => lt::SymbolKind::ENUM_MEMBER,
            SymKind::Fn => lt::SymbolKind::FUNCTION,
            SymKind::Param => lt::SymbolKind::VARIABLE,
            SymKind::Chart => lt::SymbolKind::CLASS,
            SymKind::System => lt::SymbolKind::MODULE,
            SymKind::Var(_) => lt::SymbolKind::VARIABLE,
            SymKind::Event(_) => lt::SymbolKind::EVENT,
            SymKind::State | SymKind::Region => lt::SymbolKind::NAMESPACE,
            SymKind::Junction => lt::SymbolKind::OPERATOR,
            SymKind::Instance => lt::SymbolKind::OBJECT,
            SymKind::Property => lt::SymbolKind::BOOLEAN,
        };
        // The outline is as deep as the model (bounded by the parser's nesting limit).
        let kids: Vec<lt::DocumentSymbol> = if depth < 300 {
            children[i]
                .iter()
                .map(|&c| build(ix, lines, children, c, depth + 1))
                .collect()
        } else {
            Vec::new()
        };
        #[allow(deprecated)] // reason: `deprecated` is a required field of the protocol type
        lt::DocumentSymbol {
            name: s.name.clone(),
            detail: Some(kind_word(s.kind).to_string()),
            kind,
            tags: None,
            deprecated: None,
            range: lines.range(s.full),
            selection_range: lines.range(s.decl),
            children: if kids.is_empty() { None } else { Some(kids) },
        }
    }
    let out = roots
        .into_iter()
        .map(|r| build(&ix, &lines, &children, r, 0))
        .collect();
    Some(lt::DocumentSymbolResponse::Nested(out))
}

/// Formatting: the whole text replaced by `statecheck fmt`'s output (nothing when the text
/// has syntax errors or is already formatted).
pub fn formatting(doc: &Doc<'_>, _p: lt::DocumentFormattingParams) -> Option<Vec<lt::TextEdit>> {
    let formatted = statecheck_syntax::format::format(doc.text).ok()?;
    if formatted == doc.text {
        return Some(Vec::new());
    }
    let lines = Lines::new(doc.text);
    let all = Span::new(0, doc.text.len());
    Some(vec![lt::TextEdit::new(lines.range(all), formatted)])
}

/// The replacement a hint of the form "did you mean `X`?" proposes.
fn suggestion(hint: &str) -> Option<&str> {
    let rest = hint.strip_prefix("did you mean `")?;
    let x = rest.strip_suffix("`?")?;
    (!x.contains('`')).then_some(x)
}

/// Code actions: a quick fix for each diagnostic in the range whose hint proposes a
/// replacement of its span.
pub fn code_actions(doc: &Doc<'_>, p: lt::CodeActionParams) -> Option<lt::CodeActionResponse> {
    let lines = Lines::new(doc.text);
    let (a, b) = (
        lines.offset(p.range.start) as u32,
        lines.offset(p.range.end) as u32,
    );
    let mut out = Vec::new();
    for d in check(doc.uri, doc.text) {
        if d.span.end < a || d.span.start > b {
            continue;
        }
        let Some(new) = d.hint.as_deref().and_then(suggestion) else {
            continue;
        };
        let edit = edit_of(
            doc.uri,
            vec![lt::TextEdit::new(lines.range(d.span), new.to_string())],
        );
        out.push(lt::CodeActionOrCommand::CodeAction(lt::CodeAction {
            title: format!("replace with `{new}`"),
            kind: Some(lt::CodeActionKind::QUICKFIX),
            diagnostics: Some(vec![to_lsp(&lines, &d)]),
            edit: Some(edit),
            is_preferred: Some(true),
            ..lt::CodeAction::default()
        }));
    }
    Some(out)
}
