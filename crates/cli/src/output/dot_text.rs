//! The text of a drawing's labels: triggers, guards and actions as written in the source
//! (whitespace collapsed, abbreviated past [`MAX_PART`] characters), and DOT's escaping.

use statecheck_base::Span;
use statecheck_syntax::ast::{self, StateBody, Target};
use std::collections::HashMap;

/// Characters of a trigger, guard or action shown before it is abbreviated with `…`.
pub const MAX_PART: usize = 40;

/// What was written for one transition or choice branch.
#[derive(Clone, Copy, Default)]
pub struct Parts {
    /// The trigger (`ping`, `after(3 s)`).
    pub trigger: Option<Span>,
    /// The guard expression (without its brackets).
    pub guard: Option<Span>,
    /// The action block (with its braces).
    pub action: Option<Span>,
}

/// The written parts of every transition and branch of a file, by their span.
pub struct Written<'a> {
    source: &'a str,
    parts: HashMap<(u32, u32), Parts>,
}

impl<'a> Written<'a> {
    /// Collect the parts from the syntax tree `file` of `source`.
    pub fn new(source: &'a str, file: &ast::File) -> Self {
        let mut w = Written {
            source,
            parts: HashMap::new(),
        };
        for item in &file.items {
            match item {
                ast::Item::Chart(c) => w.body(&c.body),
                ast::Item::System(s) => {
                    for o in &s.observers {
                        w.body(&o.body);
                    }
                }
                _ => {}
            }
        }
        w
    }

    fn body(&mut self, b: &StateBody) {
        // Recursion follows the file's nesting, which the parser bounds.
        for t in &b.transitions {
            let trigger = t.trigger.as_ref().map(|tr| match tr {
                ast::Trigger::Event(id) => id.span,
                ast::Trigger::After { span, .. } => *span,
            });
            self.parts.insert(
                (t.span.start, t.span.end),
                Parts {
                    trigger,
                    guard: t.guard.as_ref().map(ast::Expr::span),
                    action: t.action.as_ref().map(|a| a.span),
                },
            );
            if let Some(target) = &t.target {
                self.target(target);
            }
        }
        for j in &b.junctions {
            self.branches(&j.branches);
        }
        for s in &b.states {
            self.body(&s.body);
        }
        for r in &b.regions {
            self.body(&r.body);
        }
    }

    fn target(&mut self, t: &Target) {
        if let Target::Choice { branches, .. } = t {
            self.branches(branches);
        }
    }

    fn branches(&mut self, bs: &[ast::Branch]) {
        for b in bs {
            self.parts.insert(
                (b.span.start, b.span.end),
                Parts {
                    trigger: None,
                    guard: b.guard.as_ref().map(ast::Expr::span),
                    action: b.action.as_ref().map(|a| a.span),
                },
            );
            self.target(&b.target);
        }
    }

    /// The parts written at `span` (empty when the span is not a transition's).
    pub fn parts(&self, span: Span) -> Parts {
        self.parts
            .get(&(span.start, span.end))
            .copied()
            .unwrap_or_default()
    }

    /// The text at `span`, whitespace collapsed, abbreviated past [`MAX_PART`] characters.
    pub fn text(&self, span: Span) -> String {
        let raw = self
            .source
            .get(span.start as usize..span.end as usize)
            .unwrap_or("");
        abbreviate(&collapse(raw), MAX_PART)
    }

    /// An action block's statements as written (without the braces), abbreviated.
    pub fn action(&self, span: Span) -> String {
        let raw = self
            .source
            .get(span.start as usize..span.end as usize)
            .unwrap_or("");
        let inner = raw
            .trim()
            .strip_prefix('{')
            .and_then(|r| r.strip_suffix('}'))
            .unwrap_or(raw);
        abbreviate(&collapse(inner), MAX_PART)
    }
}

/// Runs of whitespace (line breaks included) as one space, and comments dropped.
fn collapse(s: &str) -> String {
    let no_comments: Vec<&str> = s
        .lines()
        .map(|l| l.split_once("//").map_or(l, |(code, _)| code))
        .collect();
    no_comments
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// `s` cut to `max` characters, the last one `…`, when it is longer.
pub fn abbreviate(s: &str, max: usize) -> String {
    if s.chars().count() <= max {
        s.to_string()
    } else {
        let mut out: String = s.chars().take(max.saturating_sub(1)).collect();
        out.push('…');
        out
    }
}

/// A DOT label of several lines: each escaped for a quoted string and joined by DOT's line
/// break `\n` (one backslash in the file; Graphviz draws a centred line break).
pub fn label(lines: &[String]) -> String {
    lines
        .iter()
        .filter(|l| !l.is_empty())
        .map(|l| esc(l))
        .collect::<Vec<_>>()
        .join("\\n")
}

/// Escape text for a DOT quoted string: backslashes and quotes, and line breaks as `\n`.
pub fn esc(s: &str) -> String {
    s.replace('\\', "\\\\")
        .replace('"', "\\\"")
        .replace('\n', "\\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_joined_by_one_backslash() {
        // The bytes of the label are `Stop`, backslash, `n`, `×159`: Graphviz's line break.
        let l = label(&["Stop".to_string(), "×159".to_string()]);
        assert_eq!(l, "Stop\\n×159");
        assert_eq!(l.matches('\\').count(), 1);
        // A backslash or quote written in the text stays literal.
        assert_eq!(esc("a\\n\"b\""), "a\\\\n\\\"b\\\"");
    }

    #[test]
    fn long_text_is_abbreviated_to_forty_characters() {
        let s = "x".repeat(41);
        let a = abbreviate(&s, 40);
        assert_eq!(a.chars().count(), 40);
        assert!(a.ends_with('…'));
        assert_eq!(abbreviate("short", 40), "short");
        assert_eq!(collapse("a  &&\n   b // c\n"), "a && b");
    }
}
