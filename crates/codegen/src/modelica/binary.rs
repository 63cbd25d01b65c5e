//! Binary operators: `and`/`or` (short-circuited explicitly when the right operand can
//! fail), comparisons in the operands' common type, Integer arithmetic with `div`/`rem`, and
//! the helper functions for shifts and bitwise operators. A division or shift whose right
//! operand is not a safe constant is preceded by an `assert` with the interpreter's site.

use super::expr::{Emit, V};
use super::names::Ty;
use super::text::{string_lit, strip, strip_rhs};
use statecheck_ir::BinOp;
use statecheck_ir::Node;

impl Emit<'_> {
    /// Node `e`, the binary operation `op` of `a` and `b` with run-time check site `site`.
    pub(crate) fn binary(&mut self, op: BinOp, a: u32, b: u32, site: u32, e: u32) -> V {
        let is_pure = self.pure(e);
        let bool_v = |text: String| V {
            text,
            ty: Ty::Bool,
            atom: false,
        };
        let int_v = |text: String| V {
            text,
            ty: Ty::Int,
            atom: false,
        };
        if matches!(op, BinOp::And | BinOp::Or) && !is_pure {
            // Short-circuit explicitly: the right operand's statements run only when needed.
            let va = self.expr_as(a, Ty::Bool);
            let t = self.fresh(Ty::Bool);
            if op == BinOp::And {
                self.line(&format!("{t} := false;"));
                self.line(&format!("if {} then", strip(&va)));
            } else {
                self.line(&format!("{t} := true;"));
                self.line(&format!("if not {va} then"));
            }
            self.depth += 1;
            let vb = self.expr_as(b, Ty::Bool);
            self.line(&format!("{t} := {};", strip_rhs(&vb)));
            self.depth -= 1;
            self.line("end if;");
            return V {
                text: t,
                ty: Ty::Bool,
                atom: true,
            };
        }
        match op {
            BinOp::And | BinOp::Or => {
                let v = self.operands(&[(a, Ty::Bool), (b, Ty::Bool)]);
                let o = if op == BinOp::And { "and" } else { "or" };
                bool_v(format!("({} {o} {})", v[0], v[1]))
            }
            BinOp::Eq | BinOp::Ne => {
                let ty = self.common(a, b);
                let eq = op == BinOp::Eq;
                if ty == Ty::Bool {
                    // `b == true` is `b`, `b == false` is `not b`.
                    for (x, y) in [(a, b), (b, a)] {
                        if let Node::Const(k) = self.p.nodes[y as usize] {
                            let v = self.expr_as(x, Ty::Bool);
                            return bool_v(if (k != 0) == eq {
                                v
                            } else {
                                format!("(not {v})")
                            });
                        }
                    }
                }
                let v = self.operands(&[(a, ty), (b, ty)]);
                let o = if eq { "==" } else { "<>" };
                bool_v(format!("({} {o} {})", v[0], v[1]))
            }
            BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge => {
                let v = self.operands(&[(a, Ty::Int), (b, Ty::Int)]);
                let o = match op {
                    BinOp::Lt => "<",
                    BinOp::Le => "<=",
                    BinOp::Gt => ">",
                    _ => ">=",
                };
                bool_v(format!("({} {o} {})", v[0], v[1]))
            }
            BinOp::Add | BinOp::Sub | BinOp::Mul => {
                let v = self.operands(&[(a, Ty::Int), (b, Ty::Int)]);
                let o = match op {
                    BinOp::Add => "+",
                    BinOp::Sub => "-",
                    _ => "*",
                };
                int_v(format!("({} {o} {})", v[0], v[1]))
            }
            BinOp::Div | BinOp::Rem => {
                let v = self.operands(&[(a, Ty::Int), (b, Ty::Int)]);
                let f = if op == BinOp::Div { "div" } else { "rem" };
                let y = if is_pure {
                    v[1].clone()
                } else {
                    let y = self.atom_int(int_v(v[1].clone()));
                    let msg = string_lit(&self.site_msg("division by zero", site));
                    self.line(&format!("assert({y} <> 0, {msg});"));
                    y
                };
                int_v(format!("{f}({}, {})", strip(&v[0]), strip(&y)))
            }
            BinOp::Shl | BinOp::Shr => {
                let v = self.operands(&[(a, Ty::Int), (b, Ty::Int)]);
                let y = if is_pure {
                    v[1].clone()
                } else {
                    let y = self.atom_int(int_v(v[1].clone()));
                    let msg = string_lit(&self.site_msg("bad shift", site));
                    self.line(&format!("assert({y} >= 0 and {y} <= 62, {msg});"));
                    y
                };
                let f = if op == BinOp::Shl {
                    self.used.shl = true;
                    &self.n.helpers.shl
                } else {
                    self.used.shr = true;
                    &self.n.helpers.shr
                };
                int_v(format!("{f}({}, {})", strip(&v[0]), strip(&y)))
            }
            BinOp::BitAnd | BinOp::BitOr | BinOp::BitXor => {
                let v = self.operands(&[(a, Ty::Int), (b, Ty::Int)]);
                let f = match op {
                    BinOp::BitAnd => {
                        self.used.and = true;
                        &self.n.helpers.and
                    }
                    BinOp::BitOr => {
                        self.used.or = true;
                        &self.n.helpers.or
                    }
                    _ => {
                        self.used.xor = true;
                        &self.n.helpers.xor
                    }
                };
                int_v(format!("{f}({}, {})", strip(&v[0]), strip(&v[1])))
            }
        }
    }
}
