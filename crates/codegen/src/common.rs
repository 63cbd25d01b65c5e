//! Shared helpers of the generators: source positions for comments, identifiers, storage types.

use statecheck_base::{LineIndex, Span};
use statecheck_ir::{Program, SlotId};

/// The model's source, so that generated code can name source lines in comments.
pub struct Source {
    /// The file name shown in comments.
    pub file: String,
    index: LineIndex,
}

impl Source {
    /// A source named `file` with text `text`.
    pub fn new(file: &str, text: &str) -> Source {
        let base = file.rsplit('/').next().unwrap_or(file);
        Source {
            file: base.to_string(),
            index: LineIndex::new(text),
        }
    }

    /// `file:line` of a span.
    pub fn at(&self, span: Span) -> String {
        format!("{}:{}", self.file, self.index.line_col(span.start).0)
    }
}

/// A C/Rust identifier made of `text`'s letters, digits and underscores.
pub fn ident(text: &str) -> String {
    let mut s: String = text
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    while s.contains("__") {
        s = s.replace("__", "_");
    }
    let s = s.trim_matches('_').to_string();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        format!("v_{s}")
    } else {
        s
    }
}

/// A unique field name for every slot (sanitized display name, numbered on clashes).
pub fn slot_fields(p: &Program) -> Vec<String> {
    let mut seen = std::collections::BTreeSet::new();
    p.slots
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let mut name = ident(&s.name);
            if is_reserved(&name) || !seen.insert(name.clone()) {
                name = format!("{name}_{i}");
                seen.insert(name.clone());
            }
            name
        })
        .collect()
}

fn is_reserved(name: &str) -> bool {
    const WORDS: &[&str] = &[
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else",
        "enum", "extern", "float", "for", "goto", "if", "int", "long", "register", "return",
        "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned",
        "void", "volatile", "while", "inline", "restrict", "as", "fn", "let", "loop", "match",
        "mod", "move", "mut", "pub", "ref", "self", "type", "use", "where", "in", "true", "false",
        "crate", "impl", "trait", "super", "dyn", "async", "await", "bool",
    ];
    WORDS.contains(&name)
}

/// Where a slot lives in generated code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Area {
    /// Persistent state.
    State,
    /// Free input of the tick.
    Input,
    /// Temporary of the tick.
    Temp,
}

/// The area of a slot.
pub fn area(p: &Program, s: SlotId) -> Area {
    let s = s as usize;
    if s < p.n_state {
        Area::State
    } else if s < p.n_state + p.inputs.len() {
        Area::Input
    } else {
        Area::Temp
    }
}

/// Smallest signed or unsigned width (8, 16, 32, 64) holding `lo..=hi`: `(signed, bits)`.
pub fn int_width(lo: i64, hi: i64) -> (bool, u32) {
    if lo >= 0 {
        for bits in [8u32, 16, 32] {
            if hi < (1i64 << bits) {
                return (false, bits);
            }
        }
        (true, 64)
    } else {
        for bits in [8u32, 16, 32] {
            let half = 1i64 << (bits - 1);
            if lo >= -half && hi < half {
                return (true, bits);
            }
        }
        (true, 64)
    }
}
