//! Typed translation of IR expressions into Modelica, node by node.
//!
//! The IR computes on integers; Modelica distinguishes `Integer`, `Boolean` and enumerations,
//! so every translated expression carries its Modelica type and is converted where the IR mixes
//! them (`(if b then 1 else 0)`, `(x <> 0)`, `(Integer(e) - 1)`, `T_of(i)`). A constant next to
//! an enumeration or a Boolean is written as the literal (`goState == GoStateT.Pause`,
//! `dir := DirT.Left`, `started := true`).
//!
//! Expressions that cannot fail become one Modelica expression. A node that can fail (division
//! or shift with a non-constant right operand, a range check) or that binds a local (`Let`)
//! emits statements first: an `assert` with the site's message, temporaries in evaluation
//! order. Children are evaluated left to right and `and`/`or` short-circuit explicitly, exactly
//! as the interpreter does, so the first failing check is the interpreter's.

use super::names::{Names, Ty};
use super::text::{int_lit, string_lit, strip, strip_rhs};
use crate::common::Source;
use statecheck_ir::{BinOp, UnOp};
use statecheck_ir::{Node, Program};
use std::collections::BTreeSet;

/// Helpers a program uses (so that only those are emitted).
#[derive(Default)]
pub(crate) struct Used {
    /// Bitwise and/or/xor, shifts.
    pub and: bool,
    /// Bitwise or.
    pub or: bool,
    /// Bitwise xor.
    pub xor: bool,
    /// Left shift.
    pub shl: bool,
    /// Right shift.
    pub shr: bool,
    /// Enumerations converted from an Integer.
    pub of_int: BTreeSet<usize>,
}

/// A translated expression.
pub(crate) struct V {
    /// Modelica text (parenthesized unless atomic).
    pub text: String,
    /// Its type.
    pub ty: Ty,
    /// True for a variable, temporary or literal (safe to repeat, fixed value).
    pub atom: bool,
}

/// Emits Modelica algorithm statements into a buffer.
pub(crate) struct Emit<'a> {
    /// The program.
    pub p: &'a Program,
    /// Its names.
    pub n: &'a Names,
    /// Source positions for messages and comments.
    pub src: &'a Source,
    /// Coverage counter (array, 1-based index) of each cover item, when counting.
    pub counters: Option<&'a [(String, usize)]>,
    /// Output.
    pub out: String,
    /// Indentation depth.
    pub depth: usize,
    /// Integer temporaries used.
    pub n_tmp: usize,
    /// Boolean temporaries used.
    pub n_tmpb: usize,
    /// Helpers used.
    pub used: Used,
    /// Procedures being inlined (a cycle would not terminate).
    pub stack: Vec<u32>,
    /// The first problem found, if any.
    pub error: Option<String>,
    /// Statements (not comments) written so far.
    pub written: usize,
}

impl Emit<'_> {
    /// Write one statement line.
    pub(crate) fn line(&mut self, text: &str) {
        for _ in 0..self.depth {
            self.out.push_str("  ");
        }
        self.out.push_str(text);
        self.out.push('\n');
        if !text.starts_with("//") {
            self.written += 1;
        }
    }

    /// True when node `e` translates to one Modelica expression without statements.
    pub(crate) fn pure(&self, e: u32) -> bool {
        let p = self.p;
        match p.nodes[e as usize] {
            Node::Const(_) | Node::Slot(_) | Node::Local(_) => true,
            Node::Unary(_, a) | Node::Abs(a, _) => self.pure(a),
            Node::Binary(op, a, b, _) => {
                let safe = match op {
                    BinOp::Div | BinOp::Rem => {
                        matches!(p.nodes[b as usize], Node::Const(k) if k != 0)
                    }
                    BinOp::Shl | BinOp::Shr => {
                        matches!(p.nodes[b as usize], Node::Const(k) if (0..=62).contains(&k))
                    }
                    _ => true,
                };
                safe && self.pure(a) && self.pure(b)
            }
            Node::Ite(c, a, b) => self.pure(c) && self.pure(a) && self.pure(b),
            Node::Min(a, b) | Node::Max(a, b) => self.pure(a) && self.pure(b),
            Node::Check(..) | Node::Let(..) => false,
        }
    }

    /// Whether constant `v` is a value of type `t`.
    pub(crate) fn fits(&self, t: Ty, v: i64) -> bool {
        match t {
            Ty::Int => true,
            Ty::Bool => v == 0 || v == 1,
            Ty::Enum(k) => self.n.literal(k, v).is_some(),
        }
    }

    /// The Modelica type of node `e`; `None` for a constant (it takes its context's type).
    pub(crate) fn ty_of(&self, e: u32) -> Option<Ty> {
        match self.p.nodes[e as usize] {
            Node::Const(_) => None,
            Node::Slot(s) => Some(self.n.tys[s as usize]),
            Node::Unary(UnOp::Not, _) => Some(Ty::Bool),
            Node::Binary(op, ..) => Some(match op {
                BinOp::And
                | BinOp::Or
                | BinOp::Eq
                | BinOp::Ne
                | BinOp::Lt
                | BinOp::Le
                | BinOp::Gt
                | BinOp::Ge => Ty::Bool,
                _ => Ty::Int,
            }),
            Node::Ite(_, a, b) => Some(self.common(a, b)),
            Node::Let(_, _, b) => Some(self.ty_of(b).unwrap_or(Ty::Int)),
            _ => Some(Ty::Int),
        }
    }

    /// The type two operands are compared or chosen in: their own when they agree (a constant
    /// adopts the other side's type if it is one of its values), else `Integer`.
    pub(crate) fn common(&self, a: u32, b: u32) -> Ty {
        let konst = |e: u32| match self.p.nodes[e as usize] {
            Node::Const(v) => Some(v),
            _ => None,
        };
        match (self.ty_of(a), self.ty_of(b)) {
            (Some(x), Some(y)) if x == y => x,
            (Some(x), None) if konst(b).is_some_and(|v| self.fits(x, v)) => x,
            (None, Some(y)) if konst(a).is_some_and(|v| self.fits(y, v)) => y,
            _ => Ty::Int,
        }
    }

    /// Constant `v` as a value of type `want`.
    pub(crate) fn lit(&mut self, v: i64, want: Ty) -> String {
        match want {
            Ty::Int => int_lit(v),
            Ty::Bool => (v != 0).to_string(),
            Ty::Enum(k) => match self.n.literal(k, v) {
                Some(l) => l,
                None => self.of_int(k, &int_lit(v)),
            },
        }
    }

    /// The literal of enumeration `k` with the Integer index `int_text` (a helper call).
    pub(crate) fn of_int(&mut self, k: usize, int_text: &str) -> String {
        self.used.of_int.insert(k);
        let f = self.n.enums.get(k).map_or("", |e| e.of_int.as_str());
        format!("{f}({})", strip(int_text))
    }

    /// `v` converted to type `want`.
    pub(crate) fn conv(&mut self, v: V, want: Ty) -> String {
        if v.ty == want {
            return v.text;
        }
        match want {
            Ty::Int => to_int(v),
            Ty::Bool => match v.ty {
                Ty::Enum(_) => format!("(Integer({}) <> 1)", v.text),
                _ => format!("({} <> 0)", v.text),
            },
            Ty::Enum(k) => {
                let i = to_int(v);
                self.of_int(k, &i)
            }
        }
    }

    /// Node `e` as a value of type `want` (constants written as literals of that type).
    pub(crate) fn expr_as(&mut self, e: u32, want: Ty) -> String {
        if let Node::Const(v) = self.p.nodes[e as usize] {
            return self.lit(v, want);
        }
        let v = self.expr(e);
        self.conv(v, want)
    }

    /// A fresh temporary of type `ty` (enumerations are held as their Integer index).
    pub(crate) fn fresh(&mut self, ty: Ty) -> String {
        if ty == Ty::Bool {
            self.n_tmpb += 1;
            format!("{}[{}]", self.n.tmpb, self.n_tmpb)
        } else {
            self.n_tmp += 1;
            format!("{}[{}]", self.n.tmp, self.n_tmp)
        }
    }

    /// Materialise `v` into a temporary (to fix its evaluation point).
    pub(crate) fn bind(&mut self, v: V) -> V {
        let ty = if v.ty == Ty::Bool { Ty::Bool } else { Ty::Int };
        let t = self.fresh(ty);
        let text = self.conv(v, ty);
        self.line(&format!("{t} := {};", strip_rhs(&text)));
        V {
            text: t,
            ty,
            atom: true,
        }
    }

    /// `v` as an atomic Integer (bound to a temporary unless it already is one).
    pub(crate) fn atom_int(&mut self, v: V) -> String {
        if v.atom && v.ty == Ty::Int {
            return v.text;
        }
        let text = self.conv(v, Ty::Int);
        self.bind(V {
            text,
            ty: Ty::Int,
            atom: false,
        })
        .text
    }

    /// Evaluate operands in order, each as its wanted type; earlier results that are not
    /// atomic are bound before a later operand's statements run.
    pub(crate) fn operands(&mut self, es: &[(u32, Ty)]) -> Vec<String> {
        let mut vals = Vec::new();
        for (k, &(e, want)) in es.iter().enumerate() {
            let later_impure = es[k + 1..].iter().any(|&(x, _)| !self.pure(x));
            let is_const = matches!(self.p.nodes[e as usize], Node::Const(_));
            let text = self.expr_as(e, want);
            let text = if later_impure && !is_const && !is_atom_text(&text) {
                let b = self.bind(V {
                    text,
                    ty: want,
                    atom: false,
                });
                self.conv(b, want)
            } else {
                text
            };
            vals.push(text);
        }
        vals
    }

    /// The message of a run-time error at `site`.
    pub(crate) fn site_msg(&self, kind: &str, site: u32) -> String {
        match self.p.sites.get(site as usize) {
            Some(s) => format!(
                "run-time error, {kind} at site {site}: {} ({})",
                s.what,
                self.src.at(s.span)
            ),
            None => format!("run-time error, {kind}"),
        }
    }

    /// `assert` that Integer atom `v` lies in `lo..=hi` (bounds beyond 32 bits are omitted:
    /// a Modelica Integer of 32 bits cannot leave them).
    pub(crate) fn assert_range(&mut self, v: &str, lo: i64, hi: i64, site: u32) {
        let mut parts = Vec::new();
        if lo > i64::from(i32::MIN) {
            parts.push(format!("{v} >= {}", int_lit(lo)));
        }
        if hi < i64::from(i32::MAX) {
            parts.push(format!("{v} <= {}", int_lit(hi)));
        }
        if parts.is_empty() {
            return;
        }
        let msg = string_lit(&format!("{}: value ", self.site_msg("range", site)));
        let tail = string_lit(&format!(" outside {lo}..{hi}"));
        self.line(&format!(
            "assert({}, {msg} + String({v}) + {tail});",
            parts.join(" and ")
        ));
    }

    /// A Modelica expression for node `e`, emitting the statements it needs first.
    pub(crate) fn expr(&mut self, e: u32) -> V {
        let p = self.p;
        let n = self.n;
        match p.nodes[e as usize] {
            Node::Const(v) => V {
                text: int_lit(v),
                ty: Ty::Int,
                atom: true,
            },
            Node::Slot(s) => V {
                text: n.vars[s as usize].clone(),
                ty: n.tys[s as usize],
                atom: true,
            },
            Node::Local(l) => V {
                text: format!("{}[{}]", n.loc, l + 1),
                ty: Ty::Int,
                atom: true,
            },
            Node::Unary(op, a) => {
                let (want, ty) = match op {
                    UnOp::Not => (Ty::Bool, Ty::Bool),
                    _ => (Ty::Int, Ty::Int),
                };
                let a = self.expr_as(a, want);
                let text = match op {
                    UnOp::Not => format!("(not {a})"),
                    UnOp::BitNot => format!("(-{a} - 1)"),
                    UnOp::Neg => format!("(-{a})"),
                };
                V {
                    text,
                    ty,
                    atom: false,
                }
            }
            Node::Binary(op, a, b, site) => self.binary(op, a, b, site, e),
            Node::Ite(c, a, b) => {
                let ty = self.common(a, b);
                if self.pure(e) {
                    let c = self.expr_as(c, Ty::Bool);
                    let a = self.expr_as(a, ty);
                    let b = self.expr_as(b, ty);
                    return V {
                        text: format!(
                            "(if {} then {} else {})",
                            strip(&c),
                            strip(&a),
                            strip_rhs(&b)
                        ),
                        ty,
                        atom: false,
                    };
                }
                let c = self.expr_as(c, Ty::Bool);
                let tt = if ty == Ty::Bool { Ty::Bool } else { Ty::Int };
                let t = self.fresh(tt);
                self.line(&format!("if {} then", strip(&c)));
                self.branch(&t, a, tt);
                self.line("else");
                self.branch(&t, b, tt);
                self.line("end if;");
                V {
                    text: t,
                    ty: tt,
                    atom: true,
                }
            }
            Node::Min(a, b) | Node::Max(a, b) => {
                let f = if matches!(p.nodes[e as usize], Node::Min(..)) {
                    "min"
                } else {
                    "max"
                };
                let v = self.operands(&[(a, Ty::Int), (b, Ty::Int)]);
                V {
                    text: format!("{f}({}, {})", strip(&v[0]), strip(&v[1])),
                    ty: Ty::Int,
                    atom: false,
                }
            }
            Node::Abs(a, _) => {
                let a = self.expr_as(a, Ty::Int);
                V {
                    text: format!("abs({})", strip(&a)),
                    ty: Ty::Int,
                    atom: false,
                }
            }
            Node::Check(a, lo, hi, site) => {
                let v = self.expr(a);
                let v = self.atom_int(v);
                self.assert_range(&v, lo, hi, site);
                V {
                    text: v,
                    ty: Ty::Int,
                    atom: true,
                }
            }
            Node::Let(l, v, body) => {
                let v = self.expr_as(v, Ty::Int);
                self.line(&format!("{}[{}] := {};", n.loc, l + 1, strip_rhs(&v)));
                let b = self.expr(body);
                if self.pure(body) && !b.atom {
                    self.bind(b)
                } else {
                    b
                }
            }
        }
    }

    fn branch(&mut self, t: &str, e: u32, ty: Ty) {
        self.depth += 1;
        let v = self.expr_as(e, ty);
        self.line(&format!("{t} := {};", strip_rhs(&v)));
        self.depth -= 1;
    }
}

/// `v` as an Integer expression.
pub(crate) fn to_int(v: V) -> String {
    match v.ty {
        Ty::Int => v.text,
        Ty::Bool => format!("(if {} then 1 else 0)", strip(&v.text)),
        Ty::Enum(_) => format!("(Integer({}) - 1)", v.text),
    }
}

/// True for a variable, array element, enumeration literal or number.
fn is_atom_text(t: &str) -> bool {
    let t = t
        .strip_prefix("(-")
        .and_then(|x| x.strip_suffix(')'))
        .unwrap_or(t);
    !t.is_empty()
        && t.chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '[' | ']'))
}
