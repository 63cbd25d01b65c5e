//! Modelica text of literals, and parentheses that can be left out.

/// A Modelica Integer literal (negative ones parenthesized: `a + (-3)`).
pub(crate) fn int_lit(v: i64) -> String {
    if v < 0 {
        format!("({v})")
    } else {
        v.to_string()
    }
}

/// A Modelica string literal.
pub(crate) fn string_lit(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}

/// `text` without one pair of enclosing parentheses, if they enclose all of it and do not
/// hold an if-expression (those keep theirs in conditions, operands and arguments).
pub(crate) fn strip(text: &str) -> &str {
    let inner = strip_rhs(text);
    if inner.starts_with("if ") {
        text
    } else {
        inner
    }
}

/// [`strip`], also for an if-expression: for the right-hand side of `:=` and `else` branches.
pub(crate) fn strip_rhs(text: &str) -> &str {
    let Some(inner) = text.strip_prefix('(').and_then(|t| t.strip_suffix(')')) else {
        return text;
    };
    let mut depth = 0i32;
    for c in inner.chars() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth < 0 {
                    return text;
                }
            }
            _ => {}
        }
    }
    if depth == 0 {
        inner
    } else {
        text
    }
}
