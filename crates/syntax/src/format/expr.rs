//! Expressions, paths, types and durations, each rendered to one line of text.
//!
//! Parentheses: an operand is parenthesised when precedence needs it (the parser's levels,
//! `parser/expr.rs`: binary operators associate to the left, comparisons do not associate,
//! an `if` expression as an operand needs parentheses) or when the user wrote parentheses
//! around it. Redundant parentheses anywhere else (around a whole guard, an argument, …)
//! are dropped. Neither changes the tree.

use super::Printer;
use crate::ast::{BinOp, Delay, Duration, Expr, Index, Path, TimeUnit, TypeExpr, UnOp};

/// Binding level of a binary operator (the parser's `LVL_*`).
fn level(op: BinOp) -> u8 {
    match op {
        BinOp::Or => 0,
        BinOp::And => 1,
        BinOp::Eq | BinOp::Ne | BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge => 2,
        BinOp::BitOr => 3,
        BinOp::BitXor => 4,
        BinOp::BitAnd => 5,
        BinOp::Shl | BinOp::Shr => 6,
        BinOp::Add | BinOp::Sub => 7,
        BinOp::Mul | BinOp::Div | BinOp::Rem => 8,
    }
}

const LVL_CMP: u8 = 2;
const LVL_UNARY: u8 = 9;
const LVL_ATOM: u8 = 10;

/// How tightly an expression binds: an `if` loosest, then binary levels, unary, atoms.
fn prec(e: &Expr) -> Option<u8> {
    match e {
        Expr::If(..) => None,
        Expr::Binary(op, ..) => Some(level(*op)),
        Expr::Unary(..) => Some(LVL_UNARY),
        _ => Some(LVL_ATOM),
    }
}

/// The spelling of a binary operator.
pub(super) fn binop_str(op: BinOp) -> &'static str {
    match op {
        BinOp::Or => "||",
        BinOp::And => "&&",
        BinOp::Eq => "==",
        BinOp::Ne => "!=",
        BinOp::Lt => "<",
        BinOp::Le => "<=",
        BinOp::Gt => ">",
        BinOp::Ge => ">=",
        BinOp::BitOr => "|",
        BinOp::BitXor => "^",
        BinOp::BitAnd => "&",
        BinOp::Shl => "<<",
        BinOp::Shr => ">>",
        BinOp::Add => "+",
        BinOp::Sub => "-",
        BinOp::Mul => "*",
        BinOp::Div => "/",
        BinOp::Rem => "%",
    }
}

fn unit_str(u: TimeUnit) -> &'static str {
    match u {
        TimeUnit::Ms => "ms",
        TimeUnit::S => "s",
        TimeUnit::Min => "min",
    }
}

impl Printer<'_> {
    /// An expression in a position that needs no parentheses (a guard, a value, an argument).
    pub(super) fn expr(&self, e: &Expr) -> String {
        let mut s = String::new();
        self.expr_into(e, &mut s);
        s
    }

    fn expr_into(&self, e: &Expr, s: &mut String) {
        match e {
            Expr::Int(_, span) => s.push_str(self.text(*span)),
            Expr::Bool(b, _) => s.push_str(if *b { "true" } else { "false" }),
            Expr::Path(p) => self.path_into(p, s),
            Expr::In(p, _) => {
                s.push_str("in(");
                self.path_into(p, s);
                s.push(')');
            }
            Expr::Call { func, args, .. } => {
                s.push_str(&func.name);
                s.push('(');
                for (i, a) in args.iter().enumerate() {
                    if i > 0 {
                        s.push_str(", ");
                    }
                    self.expr_into(a, s);
                }
                s.push(')');
            }
            Expr::Unary(op, x, _) => {
                s.push(match op {
                    UnOp::Neg => '-',
                    UnOp::Not => '!',
                    UnOp::BitNot => '~',
                });
                let wrap = prec(x).is_none_or(|p| p < LVL_UNARY) || self.own_parens(x);
                self.operand_into(x, wrap, s);
            }
            Expr::Binary(op, l, r, _) => {
                let lvl = level(*op);
                let wrap_l = match prec(l) {
                    None => true,
                    Some(p) => p < lvl || (lvl == LVL_CMP && p == LVL_CMP),
                } || self.own_parens(l);
                self.operand_into(l, wrap_l, s);
                s.push(' ');
                s.push_str(binop_str(*op));
                s.push(' ');
                let wrap_r = prec(r).is_none_or(|p| p <= lvl) || self.own_parens(r);
                self.operand_into(r, wrap_r, s);
            }
            Expr::If(c, a, b, _) => {
                s.push_str("if ");
                self.expr_into(c, s);
                s.push_str(" then ");
                self.expr_into(a, s);
                s.push_str(" else ");
                self.expr_into(b, s);
            }
            // Not reached: files with syntax errors are not formatted.
            Expr::Error(span) => s.push_str(self.text(*span)),
        }
    }

    /// An expression over several lines when it does not fit in `room` columns: a chain of
    /// one binary operator (`a || b || c`, `a | b | c`) with one operand per line (the operator leading), an `if`
    /// with its `else` (and `else if`) branches on their own lines. Anything else, and any
    /// operand that is still too long, stays on one line.
    pub(super) fn expr_lines(&self, e: &Expr, room: usize) -> Vec<String> {
        let one = self.expr(e);
        if one.len() <= room {
            return vec![one];
        }
        match e {
            Expr::Binary(op, ..) => {
                // The left spine of the same operator, as the parser built it.
                let mut operands = Vec::new();
                let mut cur = e;
                while let Expr::Binary(o, l, r, _) = cur {
                    if o != op {
                        break;
                    }
                    let lvl = level(*op);
                    let wrap_r = prec(r).is_none_or(|p| p <= lvl) || self.own_parens(r);
                    operands.push((&**r, wrap_r));
                    let left_wrapped = match prec(l) {
                        None => true,
                        Some(p) => p < lvl,
                    } || self.own_parens(l);
                    if left_wrapped || !matches!(&**l, Expr::Binary(lo, ..) if lo == op) {
                        operands.push((&**l, left_wrapped));
                        break;
                    }
                    cur = l;
                }
                operands.reverse();
                let mut lines = Vec::with_capacity(operands.len());
                for (i, (x, wrap)) in operands.into_iter().enumerate() {
                    let mut t = String::new();
                    if i > 0 {
                        t.push_str(binop_str(*op));
                        t.push(' ');
                    }
                    self.operand_into(x, wrap, &mut t);
                    lines.push(t);
                }
                lines
            }
            Expr::If(..) => {
                let mut lines = Vec::new();
                let mut cur = e;
                let mut prefix = "";
                while let Expr::If(c, a, b, _) = cur {
                    lines.push(format!("{prefix}if {} then {}", self.expr(c), self.expr(a)));
                    prefix = "else ";
                    cur = b;
                }
                lines.push(format!("else {}", self.expr(cur)));
                lines
            }
            _ => vec![one],
        }
    }

    /// The source extent of `e` without its own parentheses: a binary or unary expression's
    /// span stops at its operands' inner text, so the parentheses written around its first
    /// and last operands are added back.
    fn extent(&self, e: &Expr) -> statecheck_base::Span {
        let inner = |x: &Expr| self.with_parens(x);
        match e {
            Expr::Binary(_, l, r, _) => inner(l).to(inner(r)),
            Expr::Unary(_, x, span) => span.to(inner(x)),
            _ => e.span(),
        }
    }

    /// The source extent of `e` with all parentheses written around it.
    fn with_parens(&self, e: &Expr) -> statecheck_base::Span {
        let mut span = self.extent(e);
        while let Some(outer) = self.paren_around(span) {
            span = outer;
        }
        span
    }

    /// True when the user wrote parentheses around `e`.
    fn own_parens(&self, e: &Expr) -> bool {
        self.paren_around(self.extent(e)).is_some()
    }

    fn operand_into(&self, e: &Expr, wrap: bool, s: &mut String) {
        if wrap {
            s.push('(');
        }
        self.expr_into(e, s);
        if wrap {
            s.push(')');
        }
    }

    /// A dotted path with its indexes.
    pub(super) fn path(&self, p: &Path) -> String {
        let mut s = String::new();
        self.path_into(p, &mut s);
        s
    }

    fn path_into(&self, p: &Path, s: &mut String) {
        for (i, seg) in p.segments.iter().enumerate() {
            if i > 0 {
                s.push('.');
            }
            s.push_str(&seg.name.name);
            match &seg.index {
                None => {}
                Some(Index::All(_)) => s.push_str("[*]"),
                Some(Index::At(e)) => {
                    s.push('[');
                    self.expr_into(e, s);
                    s.push(']');
                }
            }
        }
    }

    /// A type as written.
    pub(super) fn ty(&self, t: &TypeExpr) -> String {
        match t {
            TypeExpr::Bool(_) => "bool".to_string(),
            TypeExpr::Int(_) => "int".to_string(),
            TypeExpr::Range { lo, hi, .. } => {
                format!("int[{}..{}]", self.expr(lo), self.expr(hi))
            }
            TypeExpr::Named(i) => i.name.clone(),
        }
    }

    /// A duration: an atomic amount as is, any other in parentheses (the grammar's
    /// `primary unit`).
    pub(super) fn duration(&self, d: &Duration) -> String {
        let amount = self.expr(&d.amount);
        let atomic = matches!(
            *d.amount,
            Expr::Int(..) | Expr::Bool(..) | Expr::Path(_) | Expr::In(..) | Expr::Call { .. }
        );
        if atomic {
            format!("{amount} {}", unit_str(d.unit))
        } else {
            format!("({amount}) {}", unit_str(d.unit))
        }
    }

    /// The inside of `after( … )`.
    pub(super) fn delay(&self, d: &Delay) -> String {
        match d {
            Delay::Ticks(e) => self.expr(e),
            Delay::Time(d) => self.duration(d),
        }
    }
}
