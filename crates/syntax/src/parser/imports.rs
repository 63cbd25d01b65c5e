//! `import "path.sc";` and `import "path.sc" { A, B };` (docs/components.md).
//!
//! `import` is a contextual keyword: only an identifier `import` at the start of an item
//! starts one, so models that use `import` as a name elsewhere still parse. The path is the
//! one string literal of the language (the lexer produces [`Tok::Str`] only after `import`).

use super::{Failed, PResult, Parser};
use crate::ast::ImportDecl;
use crate::lexer::Tok;
use statecheck_base::{Diagnostic, Span};

impl Parser<'_> {
    /// `'import' STRING [ '{' IDENT { ',' IDENT } [ ',' ] '}' ] ';'` (at the `import` token).
    pub(super) fn import_decl(&mut self) -> PResult<ImportDecl> {
        let start = self.bump().span;
        if !self.at(Tok::Str) {
            let found = self.describe(self.tok());
            let d = Diagnostic::error(
                "E0021",
                format!("expected a quoted file path after `import`, found {found}"),
                self.missing_span(),
            )
            .with_label("expected a path")
            .with_hint("write `import \"file.sc\";` (relative to this file or the library path)");
            self.report(d);
            return Err(Failed);
        }
        let lit = self.bump().span;
        let raw = self.text(lit);
        let path = raw
            .strip_prefix('"')
            .map(|r| r.strip_suffix('"').unwrap_or(r))
            .unwrap_or(raw)
            .to_string();
        let path_span = lit;
        if path.is_empty() {
            self.report(
                Diagnostic::error("E0021", "empty import path", lit)
                    .with_label("no file named here"),
            );
        }
        let names = if self.eat(Tok::LBrace).is_some() {
            Some(self.import_names()?)
        } else {
            None
        };
        self.expect_semi("after the `import` declaration");
        Ok(ImportDecl {
            path,
            path_span,
            names,
            span: self.span_from(start),
        })
    }

    /// The names of `{ A, B }` after the opening brace, through the closing one.
    fn import_names(&mut self) -> PResult<Vec<crate::ast::Ident>> {
        let open = Span::new(self.prev_end().saturating_sub(1), self.prev_end());
        let mut names = Vec::new();
        loop {
            if self.eat(Tok::RBrace).is_some() {
                break;
            }
            if self.at(Tok::Eof) {
                let d = Diagnostic::error("E0012", "unclosed `{` of the import list", open)
                    .with_label("opened here");
                self.report(d);
                return Err(Failed);
            }
            names.push(self.expect_ident("a chart, system or other item name to import")?);
            if self.eat(Tok::Comma).is_none() {
                self.expect(Tok::RBrace, "after the imported names")?;
                break;
            }
        }
        if names.is_empty() {
            self.report(
                Diagnostic::error("E0021", "empty import list", self.span_from(open))
                    .with_label("names nothing")
                    .with_hint("list the items to bring in, or drop the braces to import all"),
            );
        }
        Ok(names)
    }
}
