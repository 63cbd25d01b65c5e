//! The lexer: turns source text into a vector of [`Token`]s with byte spans.
//!
//! The lexer never fails. Characters that cannot start a token are reported (E0001) and
//! skipped; an unterminated block comment is reported (E0002) and runs to the end of the file;
//! an integer literal that does not fit in `i64` is reported (E0003 or E0004) and lexed as `0`
//! so the parser can go on. The token list always ends with exactly one [`Tok::Eof`].

use statecheck_base::{Diagnostic, Span};

/// A keyword of the language (see `docs/grammar.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kw {
    /// `const`
    Const,
    /// `enum`
    Enum,
    /// `fn`
    Fn,
    /// `return`
    Return,
    /// `let`
    Let,
    /// `chart`
    Chart,
    /// `system`
    System,
    /// `tick`
    Tick,
    /// `input`
    Input,
    /// `output`
    Output,
    /// `local`
    Local,
    /// `event`
    Event,
    /// `state`
    State,
    /// `region`
    Region,
    /// `parallel`
    Parallel,
    /// `initial`
    Initial,
    /// `history`
    History,
    /// `shallow`
    Shallow,
    /// `deep`
    Deep,
    /// `entry`
    Entry,
    /// `during`
    During,
    /// `exit`
    Exit,
    /// `on`
    On,
    /// `after`
    After,
    /// `in`
    In,
    /// `choice`
    Choice,
    /// `junction`
    Junction,
    /// `else`
    Else,
    /// `priority`
    Priority,
    /// `raise`
    Raise,
    /// `if`
    If,
    /// `then`
    Then,
    /// `true`
    True,
    /// `false`
    False,
    /// `bool`
    Bool,
    /// `int`
    Int,
    /// `instance`
    Instance,
    /// `connect`
    Connect,
    /// `order`
    Order,
    /// `assume`
    Assume,
    /// `invariant`
    Invariant,
    /// `reachable`
    Reachable,
    /// `respond`
    Respond,
    /// `within`
    Within,
    /// `assuming`
    Assuming,
    /// `observer`
    Observer,
    /// `plant`
    Plant,
    /// `requirement`
    Requirement,
    /// `controllable` (synthesis: an event the supervisor may disable)
    Controllable,
    /// `uncontrollable` (synthesis: an event the supervisor cannot disable)
    Uncontrollable,
    /// `marked` (synthesis: an accepting state)
    Marked,
}

/// Every keyword with its spelling.
const KEYWORDS: &[(&str, Kw)] = &[
    ("const", Kw::Const),
    ("enum", Kw::Enum),
    ("fn", Kw::Fn),
    ("return", Kw::Return),
    ("let", Kw::Let),
    ("chart", Kw::Chart),
    ("system", Kw::System),
    ("tick", Kw::Tick),
    ("input", Kw::Input),
    ("output", Kw::Output),
    ("local", Kw::Local),
    ("event", Kw::Event),
    ("state", Kw::State),
    ("region", Kw::Region),
    ("parallel", Kw::Parallel),
    ("initial", Kw::Initial),
    ("history", Kw::History),
    ("shallow", Kw::Shallow),
    ("deep", Kw::Deep),
    ("entry", Kw::Entry),
    ("during", Kw::During),
    ("exit", Kw::Exit),
    ("on", Kw::On),
    ("after", Kw::After),
    ("in", Kw::In),
    ("choice", Kw::Choice),
    ("junction", Kw::Junction),
    ("else", Kw::Else),
    ("priority", Kw::Priority),
    ("raise", Kw::Raise),
    ("if", Kw::If),
    ("then", Kw::Then),
    ("true", Kw::True),
    ("false", Kw::False),
    ("bool", Kw::Bool),
    ("int", Kw::Int),
    ("instance", Kw::Instance),
    ("connect", Kw::Connect),
    ("order", Kw::Order),
    ("assume", Kw::Assume),
    ("invariant", Kw::Invariant),
    ("reachable", Kw::Reachable),
    ("respond", Kw::Respond),
    ("within", Kw::Within),
    ("assuming", Kw::Assuming),
    ("observer", Kw::Observer),
    ("plant", Kw::Plant),
    ("requirement", Kw::Requirement),
    ("controllable", Kw::Controllable),
    ("uncontrollable", Kw::Uncontrollable),
    ("marked", Kw::Marked),
];

impl Kw {
    /// The keyword's spelling.
    pub fn as_str(self) -> &'static str {
        KEYWORDS
            .iter()
            .find(|(_, k)| *k == self)
            .map_or("?", |(s, _)| s)
    }

    fn from_str(s: &str) -> Option<Kw> {
        KEYWORDS.iter().find(|(t, _)| *t == s).map(|(_, k)| *k)
    }
}

/// The kind of a token. Identifier text is recovered from the span.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tok {
    /// An identifier (including the contextual `ms`, `s`, `min`).
    Ident,
    /// An integer literal with its value (0 if it was out of range).
    Int(i64),
    /// A double-quoted string on one line, quotes included in the span. Only produced right
    /// after the contextual keyword `import` (the language has no other strings, so a quote
    /// anywhere else stays the lexical error E0001).
    Str,
    /// A keyword.
    Kw(Kw),
    /// `{`
    LBrace,
    /// `}`
    RBrace,
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `[`
    LBracket,
    /// `]`
    RBracket,
    /// `;`
    Semi,
    /// `:`
    Colon,
    /// `,`
    Comma,
    /// `.`
    Dot,
    /// `..`
    DotDot,
    /// `->`
    Arrow,
    /// `=>`
    FatArrow,
    /// `/`
    Slash,
    /// `=`
    Assign,
    /// `+=`
    PlusAssign,
    /// `-=`
    MinusAssign,
    /// `==`
    EqEq,
    /// `!=`
    NotEq,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `+`
    Plus,
    /// `-`
    Minus,
    /// `*`
    Star,
    /// `%`
    Percent,
    /// `!`
    Bang,
    /// `~`
    Tilde,
    /// `&`
    Amp,
    /// `|`
    Pipe,
    /// `^`
    Caret,
    /// `&&`
    AndAnd,
    /// `||`
    OrOr,
    /// `<<`
    Shl,
    /// `>>`
    Shr,
    /// End of input (always the last token).
    Eof,
}

impl Tok {
    /// How the token kind is spelled, for messages (`None` for identifiers, integers and EOF).
    pub fn spelling(self) -> Option<&'static str> {
        Some(match self {
            Tok::Ident | Tok::Int(_) | Tok::Str | Tok::Eof => return None,
            Tok::Kw(k) => k.as_str(),
            Tok::LBrace => "{",
            Tok::RBrace => "}",
            Tok::LParen => "(",
            Tok::RParen => ")",
            Tok::LBracket => "[",
            Tok::RBracket => "]",
            Tok::Semi => ";",
            Tok::Colon => ":",
            Tok::Comma => ",",
            Tok::Dot => ".",
            Tok::DotDot => "..",
            Tok::Arrow => "->",
            Tok::FatArrow => "=>",
            Tok::Slash => "/",
            Tok::Assign => "=",
            Tok::PlusAssign => "+=",
            Tok::MinusAssign => "-=",
            Tok::EqEq => "==",
            Tok::NotEq => "!=",
            Tok::Lt => "<",
            Tok::Le => "<=",
            Tok::Gt => ">",
            Tok::Ge => ">=",
            Tok::Plus => "+",
            Tok::Minus => "-",
            Tok::Star => "*",
            Tok::Percent => "%",
            Tok::Bang => "!",
            Tok::Tilde => "~",
            Tok::Amp => "&",
            Tok::Pipe => "|",
            Tok::Caret => "^",
            Tok::AndAnd => "&&",
            Tok::OrOr => "||",
            Tok::Shl => "<<",
            Tok::Shr => ">>",
        })
    }
}

/// A token: its kind and where it was written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    /// What it is.
    pub kind: Tok,
    /// Where it is.
    pub span: Span,
}

/// Split `source` into tokens (ending with [`Tok::Eof`]), appending lexical errors to `diags`.
#[cfg(test)]
pub fn lex(source: &str, diags: &mut Vec<Diagnostic>) -> Vec<Token> {
    lex_with_comments(source, diags).0
}

/// [`lex`], also returning the spans of the comments (`// …` without its newline, `/* … */`)
/// in textual order: the trivia the formatter keeps.
pub fn lex_with_comments(source: &str, diags: &mut Vec<Diagnostic>) -> (Vec<Token>, Vec<Span>) {
    lex_from_with_comments(source, 0, diags)
}

/// Like [`lex`], starting at byte `start` of `source` (spans stay offsets into `source`).
pub fn lex_from(source: &str, start: usize, diags: &mut Vec<Diagnostic>) -> Vec<Token> {
    lex_from_with_comments(source, start, diags).0
}

/// [`lex_with_comments`] from byte `start` of `source` on.
pub fn lex_from_with_comments(
    source: &str,
    start: usize,
    diags: &mut Vec<Diagnostic>,
) -> (Vec<Token>, Vec<Span>) {
    let mut lx = Lexer {
        src: source,
        bytes: source.as_bytes(),
        pos: start.min(source.len()),
        toks: Vec::new(),
        comments: Vec::new(),
        diags,
        bad_start: None,
    };
    lx.run();
    (lx.toks, lx.comments)
}

struct Lexer<'a, 'd> {
    src: &'a str,
    bytes: &'a [u8],
    pos: usize,
    toks: Vec<Token>,
    comments: Vec<Span>,
    diags: &'d mut Vec<Diagnostic>,
    /// Start of the current run of unexpected characters, reported as one diagnostic.
    bad_start: Option<usize>,
}

fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_'
}

fn is_ident_continue(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

impl Lexer<'_, '_> {
    fn peek(&self, ahead: usize) -> u8 {
        self.bytes.get(self.pos + ahead).copied().unwrap_or(0)
    }

    fn push(&mut self, kind: Tok, start: usize) {
        self.toks.push(Token {
            kind,
            span: Span::new(start, self.pos),
        });
    }

    fn flush_bad(&mut self) {
        if let Some(start) = self.bad_start.take() {
            let text = self.src.get(start..self.pos).unwrap_or("?");
            let what = if text.chars().count() == 1 {
                format!("unexpected character `{text}`")
            } else {
                format!("unexpected characters `{text}`")
            };
            self.diags.push(
                Diagnostic::error("E0001", what, Span::new(start, self.pos))
                    .with_label("not valid in a `.sc` file"),
            );
        }
    }

    fn run(&mut self) {
        while self.pos < self.bytes.len() {
            let b = self.bytes[self.pos];
            let start = self.pos;
            if b.is_ascii_whitespace() {
                self.flush_bad();
                self.pos += 1;
            } else if b == b'/' && self.peek(1) == b'/' {
                self.flush_bad();
                while self.pos < self.bytes.len() && self.bytes[self.pos] != b'\n' {
                    self.pos += 1;
                }
                self.comments.push(Span::new(start, self.pos));
            } else if b == b'/' && self.peek(1) == b'*' {
                self.flush_bad();
                self.block_comment();
                self.comments.push(Span::new(start, self.pos));
            } else if is_ident_start(b) {
                self.flush_bad();
                while self.pos < self.bytes.len() && is_ident_continue(self.bytes[self.pos]) {
                    self.pos += 1;
                }
                let text = &self.src[start..self.pos];
                let kind = Kw::from_str(text).map_or(Tok::Ident, Tok::Kw);
                self.push(kind, start);
            } else if b.is_ascii_digit() {
                self.flush_bad();
                self.number();
            } else if b == b'"' && self.after_import() {
                self.flush_bad();
                self.string();
            } else if b == b'#' || b == b'"' || b == b'\'' {
                // Likely a comment or a string from another language: report it once and skip
                // it whole, so the parser does not trip over its contents.
                self.flush_bad();
                self.foreign(b);
            } else if let Some((kind, len)) = self.punct() {
                self.flush_bad();
                self.pos += len;
                self.push(kind, start);
            } else {
                // Unexpected character: skip the whole UTF-8 sequence.
                if self.bad_start.is_none() {
                    self.bad_start = Some(start);
                }
                let len = self.src[start..].chars().next().map_or(1, char::len_utf8);
                self.pos += len;
            }
        }
        self.flush_bad();
        let end = self.bytes.len();
        self.toks.push(Token {
            kind: Tok::Eof,
            span: Span::new(end, end),
        });
    }

    /// True when the previous token is the identifier `import` (a contextual keyword).
    fn after_import(&self) -> bool {
        self.toks
            .last()
            .is_some_and(|t| t.kind == Tok::Ident && &self.src[t.span.range()] == "import")
    }

    /// A `"…"` string closed on the same line; an unclosed one is reported (E0001) and kept
    /// as a token so the parser reports no cascade.
    fn string(&mut self) {
        let start = self.pos;
        self.pos += 1;
        while self.pos < self.bytes.len() && !matches!(self.bytes[self.pos], b'"' | b'\n') {
            self.pos += 1;
        }
        if self.bytes.get(self.pos) == Some(&b'"') {
            self.pos += 1;
        } else {
            self.diags.push(
                Diagnostic::error("E0001", "unterminated string", Span::new(start, self.pos))
                    .with_label("no closing `\"` on this line")
                    .with_hint("write the path on one line: `import \"file.sc\";`"),
            );
        }
        self.push(Tok::Str, start);
    }

    /// Skip a `# …` comment (to end of line) or a quoted literal (to its closing quote on
    /// the same line), reporting E0001.
    fn foreign(&mut self, first: u8) {
        let start = self.pos;
        self.pos += 1;
        while self.pos < self.bytes.len() && self.bytes[self.pos] != b'\n' {
            let c = self.bytes[self.pos];
            self.pos += 1;
            if first != b'#' && c == first {
                break;
            }
        }
        let (msg, hint) = if first == b'#' {
            (
                "`#` does not start a comment",
                "comments start with `//` or are enclosed in `/* … */`",
            )
        } else {
            (
                "unexpected string literal",
                "the language has no string or character literals",
            )
        };
        self.diags.push(
            Diagnostic::error("E0001", msg, Span::new(start, self.pos))
                .with_label("not valid in a `.sc` file")
                .with_hint(hint),
        );
    }

    fn block_comment(&mut self) {
        let start = self.pos;
        self.pos += 2;
        while self.pos < self.bytes.len() {
            if self.bytes[self.pos] == b'*' && self.peek(1) == b'/' {
                self.pos += 2;
                return;
            }
            self.pos += 1;
        }
        self.diags.push(
            Diagnostic::error(
                "E0002",
                "unterminated block comment",
                Span::new(start, start + 2),
            )
            .with_label("this comment is never closed")
            .with_hint("close it with `*/`; block comments do not nest"),
        );
    }

    fn number(&mut self) {
        let start = self.pos;
        let (radix, name) = match (self.peek(0), self.peek(1)) {
            (b'0', b'x' | b'X') => (16, "hexadecimal"),
            (b'0', b'b' | b'B') => (2, "binary"),
            _ => (10, "decimal"),
        };
        let mut value: Option<i64> = Some(0);
        let mut digits = 0usize;
        let mut bad_digit: Option<(usize, char)> = None;
        if radix == 10 {
            while self.pos < self.bytes.len()
                && (self.bytes[self.pos].is_ascii_digit() || self.bytes[self.pos] == b'_')
            {
                let c = self.bytes[self.pos];
                if c != b'_' {
                    digits += 1;
                    value = value
                        .and_then(|v| v.checked_mul(10))
                        .and_then(|v| v.checked_add(i64::from(c - b'0')));
                }
                self.pos += 1;
            }
        } else {
            self.pos += 2;
            while self.pos < self.bytes.len() && is_ident_continue(self.bytes[self.pos]) {
                let c = self.bytes[self.pos];
                if c != b'_' {
                    match char::from(c).to_digit(radix) {
                        Some(d) => {
                            digits += 1;
                            value = value
                                .and_then(|v| v.checked_mul(i64::from(radix)))
                                .and_then(|v| v.checked_add(i64::from(d)));
                        }
                        None => {
                            if bad_digit.is_none() {
                                bad_digit = Some((self.pos, char::from(c)));
                            }
                        }
                    }
                }
                self.pos += 1;
            }
        }
        let span = Span::new(start, self.pos);
        let value = if let Some((at, c)) = bad_digit {
            self.diags.push(
                Diagnostic::error(
                    "E0004",
                    format!("invalid digit `{c}` in {name} integer literal"),
                    Span::new(at, at + 1),
                )
                .with_label(format!("not a {name} digit"))
                .with_hint(if radix == 16 {
                    "hexadecimal digits are `0`-`9` and `a`-`f`"
                } else {
                    "binary digits are `0` and `1`"
                }),
            );
            0
        } else if digits == 0 {
            self.diags.push(
                Diagnostic::error(
                    "E0004",
                    format!("{name} integer literal has no digits"),
                    span,
                )
                .with_label("digits expected after the prefix"),
            );
            0
        } else if let Some(v) = value {
            v
        } else {
            self.diags.push(
                Diagnostic::error("E0003", "integer literal out of range", span)
                    .with_label("does not fit in a 64-bit signed integer")
                    .with_hint(format!("the largest integer is {}", i64::MAX)),
            );
            0
        };
        self.toks.push(Token {
            kind: Tok::Int(value),
            span,
        });
    }

    fn punct(&self) -> Option<(Tok, usize)> {
        let two = (self.peek(0), self.peek(1));
        let t2 = match two {
            (b'.', b'.') => Some(Tok::DotDot),
            (b'-', b'>') => Some(Tok::Arrow),
            (b'=', b'>') => Some(Tok::FatArrow),
            (b'+', b'=') => Some(Tok::PlusAssign),
            (b'-', b'=') => Some(Tok::MinusAssign),
            (b'=', b'=') => Some(Tok::EqEq),
            (b'!', b'=') => Some(Tok::NotEq),
            (b'<', b'=') => Some(Tok::Le),
            (b'>', b'=') => Some(Tok::Ge),
            (b'&', b'&') => Some(Tok::AndAnd),
            (b'|', b'|') => Some(Tok::OrOr),
            (b'<', b'<') => Some(Tok::Shl),
            (b'>', b'>') => Some(Tok::Shr),
            _ => None,
        };
        if let Some(t) = t2 {
            return Some((t, 2));
        }
        let t1 = match two.0 {
            b'{' => Tok::LBrace,
            b'}' => Tok::RBrace,
            b'(' => Tok::LParen,
            b')' => Tok::RParen,
            b'[' => Tok::LBracket,
            b']' => Tok::RBracket,
            b';' => Tok::Semi,
            b':' => Tok::Colon,
            b',' => Tok::Comma,
            b'.' => Tok::Dot,
            b'/' => Tok::Slash,
            b'=' => Tok::Assign,
            b'<' => Tok::Lt,
            b'>' => Tok::Gt,
            b'+' => Tok::Plus,
            b'-' => Tok::Minus,
            b'*' => Tok::Star,
            b'%' => Tok::Percent,
            b'!' => Tok::Bang,
            b'~' => Tok::Tilde,
            b'&' => Tok::Amp,
            b'|' => Tok::Pipe,
            b'^' => Tok::Caret,
            _ => return None,
        };
        Some((t1, 1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<Tok> {
        let mut d = Vec::new();
        lex(src, &mut d).into_iter().map(|t| t.kind).collect()
    }

    #[test]
    fn maximal_munch() {
        assert_eq!(
            kinds("a->b..c=>d>>=e"),
            vec![
                Tok::Ident,
                Tok::Arrow,
                Tok::Ident,
                Tok::DotDot,
                Tok::Ident,
                Tok::FatArrow,
                Tok::Ident,
                Tok::Shr,
                Tok::Assign,
                Tok::Ident,
                Tok::Eof
            ]
        );
    }

    #[test]
    fn numbers() {
        assert_eq!(
            kinds("4_095 0x7FF 0b1010 100ms 0..3"),
            vec![
                Tok::Int(4095),
                Tok::Int(0x7FF),
                Tok::Int(10),
                Tok::Int(100),
                Tok::Ident,
                Tok::Int(0),
                Tok::DotDot,
                Tok::Int(3),
                Tok::Eof
            ]
        );
        let mut d = Vec::new();
        lex("9223372036854775808 9223372036854775807", &mut d);
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].code, "E0003");
    }

    #[test]
    fn bad_characters_are_grouped() {
        let mut d = Vec::new();
        let toks = lex("a €€ b ` c", &mut d);
        assert_eq!(toks.len(), 4);
        assert_eq!(d.len(), 2);
        assert_eq!(d[0].span, Span::new(2, 8));
    }
}
