//! Text → AST for the `.sc` statechart language.
//!
//! This crate exists so that every later stage (checker, IR, simulator, CLI) starts from one
//! faithful syntax tree of a model file, with spans for every node a diagnostic may point at.
//! Its single entry point, [`parse`], **never fails and never panics**: it always returns a
//! [`ast::File`] holding everything that could be parsed, plus a list of [`Diagnostic`]s with
//! stable codes (see the table in the `parser` module docs, E0001–E0020). Malformed parts are
//! skipped up to a synchronisation point, and missing expressions become
//! [`ast::Expr::Error`] placeholders, so one run reports many errors.
//!
//! The grammar is `docs/grammar.md`; the lexer and the recursive-descent parser are
//! hand-written to give precise messages and hints (e.g. `=` in a guard suggests `==`).

pub mod ast;
pub mod format;
mod formula;
mod lexer;
mod parser;

use statecheck_base::Diagnostic;

pub use parser::{MAX_DEPTH, MAX_HEIGHT};

/// Parse a whole `.sc` source text.
///
/// Returns the syntax tree and the lexical and syntax diagnostics, sorted by position. The file is usable only if no diagnostic is an error; even then the tree
/// contains every construct that parsed.
pub fn parse(source: &str) -> (ast::File, Vec<Diagnostic>) {
    parse_from(source, 0)
}

/// Parse the file that occupies `source[start..]`, with spans that stay offsets into all of
/// `source`.
///
/// This is how several files share one offset space (`statecheck_model::imports` appends
/// each imported file to one text): every span of every file's tree and diagnostics is then
/// unique, and a renderer finds the file from the offset alone.
pub fn parse_from(source: &str, start: usize) -> (ast::File, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    let start = if source.is_char_boundary(start) {
        start
    } else {
        0
    };
    let tokens = lexer::lex_from(source, start, &mut diags);
    let file = parser::parse_tokens_from(source, start, tokens, &mut diags);
    diags.sort_by_key(|d| d.span.start);
    (file, diags)
}
