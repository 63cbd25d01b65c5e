//! The formatter: one canonical layout for a `.sc` file, comments kept.
//!
//! [`format`] parses the text, refuses it if it has syntax errors, and prints the syntax tree
//! again; `docs/tools.md` states the layout rules. Elements stay in their textual order (the
//! order of transitions, states and regions is meaning). Where the printer has a choice that
//! is not meaning, it decides from the tree, not from the old layout (one-line blocks and
//! states, line breaks in long expressions). What the tree does not record is read back from
//! the source so that the text keeps its spelling: integer literals (hex stays hex), compound
//! assignments (`x += 1`), `else if`, a chart-level `parallel { … }`, and parentheses the user
//! wrote around an operand (redundant ones elsewhere are dropped; ones that precedence needs
//! are added).
//!
//! Comments are trivia from the lexer. A comment on its own line is printed on its own line
//! before the element that follows it; a comment after an element on the same line stays
//! after it (aligned with those of the neighbouring lines). A comment inside a construct
//! printed on one line (say, in the middle of a guard) moves before that construct. Every
//! comment is printed exactly once, in textual order.
//!
//! The result parses to the same tree (up to spans), so it means the same; formatting it
//! again changes nothing. Both are tested on every model of the repository and on generated
//! inputs (`crates/syntax/tests/format.rs`, `crates/cli/tests/fmt.rs`,
//! `benches/fmt_fuzz.rs`).

mod body;
mod expr;
mod items;

use crate::lexer::{self, Tok, Token};
use statecheck_base::{Diagnostic, Span};

/// The line width the printer aims at when it decides whether a block fits on one line.
pub const WIDTH: usize = 100;

/// One level of indentation (the repository's models use two spaces).
const INDENT: &str = "  ";

/// Why a text could not be formatted.
#[derive(Clone, Debug)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
}

/// The kinds of [`Error`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The text has syntax errors (the diagnostics, sorted by position); only a file that
    /// parses is formatted, so that nothing the parser skipped is lost.
    Syntax(Vec<Diagnostic>),
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.kind {
            ErrorKind::Syntax(d) => write!(f, "the file has {} syntax error(s)", d.len()),
        }
    }
}

impl std::error::Error for Error {}

/// Format a whole `.sc` text into its canonical layout.
///
/// Fails only when the text has syntax errors (then nothing is printed).
pub fn format(source: &str) -> Result<String, Error> {
    let mut diags = Vec::new();
    let (toks, comments) = lexer::lex_with_comments(source, &mut diags);
    let file = crate::parser::parse_tokens_from(source, 0, toks.clone(), &mut diags);
    diags.retain(Diagnostic::is_error);
    if !diags.is_empty() {
        diags.sort_by_key(|d| d.span.start);
        return Err(Error {
            kind: ErrorKind::Syntax(diags),
        });
    }
    let mut p = Printer {
        src: source,
        toks,
        comments,
        next_comment: 0,
        out: String::with_capacity(source.len() + source.len() / 8),
        indent: 0,
        last_end: 0,
        at_block_start: true,
        force_blank: false,
        trailing: Vec::new(),
    };
    p.file(&file);
    Ok(align_trailing(&p.out, &p.trailing))
}

/// The printer's state: the source (for spellings, parentheses and blank lines), its tokens
/// and comments, and the output.
struct Printer<'a> {
    src: &'a str,
    toks: Vec<Token>,
    comments: Vec<Span>,
    /// The first comment not printed yet.
    next_comment: usize,
    out: String,
    indent: usize,
    /// Source offset of the end of the last element or comment printed: a blank line in the
    /// source between it and the next one is kept.
    last_end: usize,
    /// True right after an opening `{` line (no blank line goes there).
    at_block_start: bool,
    /// A blank line goes before the next element or comment whatever the source had (around
    /// charts and systems).
    force_blank: bool,
    /// Offsets in `out` where a comment after code on the same line starts.
    trailing: Vec<usize>,
}

/// Put the comments after code at one column in each run of consecutive lines that have one
/// (at the same indentation): one space after the longest code of the run. Blank lines, lines
/// without such a comment and changes of indentation end a run.
fn align_trailing(out: &str, trailing: &[usize]) -> String {
    // (code, comment) per line; comment is None for lines without a trailing comment.
    let mut lines: Vec<(&str, Option<&str>)> = Vec::new();
    let mut t = trailing.iter().copied().peekable();
    let mut start = 0;
    while start < out.len() {
        let end = out[start..].find('\n').map_or(out.len(), |i| start + i);
        match t.peek() {
            Some(&c) if c >= start && c <= end => {
                t.next();
                // A block comment running over several lines: its other lines are kept as
                // lines without a trailing comment, so they end the run.
                lines.push((&out[start..c], Some(&out[c..end])));
            }
            _ => lines.push((&out[start..end], None)),
        }
        start = end + 1;
    }
    let indent_of = |s: &str| s.len() - s.trim_start().len();
    let mut res = String::with_capacity(out.len() + 64);
    let mut i = 0;
    while i < lines.len() {
        let (code, comment) = lines[i];
        if comment.is_none() {
            res.push_str(code);
            res.push('\n');
            i += 1;
            continue;
        }
        let ind = indent_of(code);
        let mut j = i;
        let mut width = 0;
        while j < lines.len() && lines[j].1.is_some() && indent_of(lines[j].0) == ind {
            width = width.max(lines[j].0.trim_end().len());
            j += 1;
        }
        for (code, comment) in &lines[i..j] {
            let code = code.trim_end();
            res.push_str(code);
            for _ in code.len()..=width {
                res.push(' ');
            }
            res.push_str(comment.unwrap_or(""));
            res.push('\n');
        }
        i = j;
    }
    if !out.ends_with('\n') && res.ends_with('\n') {
        res.pop();
    }
    res
}

impl Printer<'_> {
    /// The source text of a span.
    fn text(&self, span: Span) -> &str {
        self.src.get(span.range()).unwrap_or("")
    }

    /// The last token ending at or before `pos`.
    fn tok_before(&self, pos: u32) -> Option<Token> {
        let i = self.toks.partition_point(|t| t.span.end <= pos);
        i.checked_sub(1).and_then(|i| self.toks.get(i)).copied()
    }

    /// The first token starting at or after `pos`.
    fn tok_after(&self, pos: u32) -> Option<Token> {
        let i = self.toks.partition_point(|t| t.span.start < pos);
        self.toks.get(i).copied()
    }

    /// The span of the parentheses right around `span`, if the source has them (a `(` just
    /// before it whose matching `)` comes just after it).
    fn paren_around(&self, span: Span) -> Option<Span> {
        let open = self.toks.partition_point(|t| t.span.end <= span.start);
        let open = open.checked_sub(1)?;
        if self.toks[open].kind != Tok::LParen {
            return None;
        }
        let close = self.toks.partition_point(|t| t.span.start < span.end);
        let close_tok = self.toks.get(close).filter(|t| t.kind == Tok::RParen)?;
        let outer = self.toks[open].span.to(close_tok.span);
        let mut depth = 0u32;
        for (i, t) in self.toks.iter().enumerate().skip(open) {
            match t.kind {
                Tok::LParen => depth += 1,
                Tok::RParen => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return (i == close).then_some(outer);
                    }
                }
                _ => {}
            }
            if i > close {
                return None;
            }
        }
        None
    }

    /// The end of the first `;` at or after `pos` (the end of a `let` or `return`).
    fn semi_after(&self, pos: u32) -> u32 {
        let i = self.toks.partition_point(|t| t.span.start < pos);
        self.toks[i..]
            .iter()
            .find(|t| t.kind == Tok::Semi)
            .map_or(pos, |t| t.span.end)
    }

    /// The first `{` at or after `pos` (its end), for comments after an opening brace.
    fn lbrace_after(&self, pos: u32) -> u32 {
        let i = self.toks.partition_point(|t| t.span.start < pos);
        self.toks[i..]
            .iter()
            .find(|t| t.kind == Tok::LBrace)
            .map_or(pos, |t| t.span.end)
    }

    /// True if any comment lies inside `span`.
    fn has_comment_in(&self, span: Span) -> bool {
        let i = self.comments.partition_point(|c| c.start < span.start);
        self.comments.get(i).is_some_and(|c| c.end <= span.end)
    }

    /// True if the source between `a` and `b` holds a blank line.
    fn blank_between(&self, a: usize, b: usize) -> bool {
        let gap = self.src.get(a..b).unwrap_or("");
        gap.bytes().filter(|&c| c == b'\n').count() >= 2
    }

    fn push_indent(&mut self) {
        for _ in 0..self.indent {
            self.out.push_str(INDENT);
        }
    }

    /// Print the comments that start before `pos`, each on its own line, with the blank
    /// lines of the source between them kept.
    fn comments_before(&mut self, pos: u32) {
        while let Some(&c) = self.comments.get(self.next_comment) {
            if c.start >= pos {
                break;
            }
            self.next_comment += 1;
            self.blank_line_before(c.start as usize);
            self.push_indent();
            let text = self.text(c).trim_end().to_string();
            self.out.push_str(&text);
            self.out.push('\n');
            self.last_end = self.last_end.max(c.end as usize);
            self.at_block_start = false;
        }
    }

    /// Print a blank line if the source has one between the last printed element and `pos`.
    fn blank_line_before(&mut self, pos: usize) {
        if !self.at_block_start && (self.force_blank || self.blank_between(self.last_end, pos)) {
            self.out.push('\n');
        }
        self.force_blank = false;
    }

    /// Start an element whose source starts at `start`: its leading comments, a kept blank
    /// line, the indentation.
    fn start_line(&mut self, start: u32) {
        self.comments_before(start);
        self.blank_line_before(start as usize);
        self.push_indent();
        self.at_block_start = false;
    }

    /// End the current output line, whose source ends at `end`: a comment on the same source
    /// line right after it (no token between) is printed after it.
    fn end_line(&mut self, end: u32) {
        if let Some(&c) = self.comments.get(self.next_comment) {
            let gap = self.src.get(end as usize..c.start as usize);
            let same_line = gap.is_some_and(|g| !g.contains('\n'));
            let no_token_between = self.tok_after(end).is_none_or(|t| t.span.start > c.start);
            if c.start >= end && same_line && no_token_between {
                self.next_comment += 1;
                let text = self.text(c).trim_end().to_string();
                self.trailing.push(self.out.len());
                self.out.push_str(&text);
                // A blank line after it is looked for past the comment, whose own text may
                // hold line breaks (a `/* … */` over several lines), not counted as blank.
                self.last_end = self.last_end.max(c.end as usize);
            }
        }
        self.out.push('\n');
        self.last_end = self.last_end.max(end as usize);
    }

    /// Print a line holding `text`, for an element spanning `span`, with the comments inside
    /// it moved before it.
    fn line(&mut self, span: Span, text: &str) {
        self.comments_before(span.end);
        self.start_line(span.start);
        self.out.push_str(text);
        self.end_line(span.end);
    }

    /// A line `head expr suffix` for an element spanning `span`; when it does not fit in
    /// [`WIDTH`], `head` ends its line and the expression follows one level deeper, over
    /// several lines if it must be (see [`Printer::expr_lines`]).
    fn line_expr(&mut self, span: Span, head: &str, e: &crate::ast::Expr, suffix: &str) {
        let one = format!("{head} {}{suffix}", self.expr(e));
        if self.indent_width() + one.len() <= WIDTH {
            self.line(span, &one);
            return;
        }
        self.comments_before(span.end);
        self.start_line(span.start);
        self.out.push_str(head);
        self.out.push('\n');
        self.indent += 1;
        let room = WIDTH.saturating_sub(self.indent_width() + suffix.len());
        let lines = self.expr_lines(e, room);
        let n = lines.len();
        for (i, l) in lines.into_iter().enumerate() {
            self.push_indent();
            self.out.push_str(&l);
            if i + 1 < n {
                self.out.push('\n');
            }
        }
        self.out.push_str(suffix);
        self.indent -= 1;
        self.end_line(span.end);
    }

    /// After a line ending in `{` (source offset `brace_end` after it): indent the elements.
    fn open(&mut self, brace_end: u32) {
        self.end_line(brace_end);
        self.indent += 1;
        self.at_block_start = true;
    }

    /// Close a block whose `}` ends at `close_end`: comments still inside it, then `}` and
    /// `suffix` (such as `;` or ` -> B;`); the line ends at `line_end`.
    fn close(&mut self, close_end: u32, suffix: &str, line_end: u32) {
        self.comments_before(close_end.saturating_sub(1));
        self.indent = self.indent.saturating_sub(1);
        self.push_indent();
        self.out.push('}');
        self.out.push_str(suffix);
        self.at_block_start = false;
        self.end_line(line_end);
    }

    /// Current column of the output (for the width decision).
    fn indent_width(&self) -> usize {
        self.indent * INDENT.len()
    }
}
