//! C99 translation of IR expressions and statements, node by node.
//!
//! Expressions that cannot fail become plain C expressions over `int64_t`; a node that can fail
//! (overflow, division, shift, range check) becomes a call of a checked helper whose non-zero
//! status returns from the enclosing function with the node's site. Children are evaluated
//! left to right, exactly as the interpreter does, so the first error is the same error.

use statecheck_ir::{BinOp, UnOp};
use statecheck_ir::{Node, Program, SlotId, Stmt};
use statecheck_model::ops;
use std::fmt::Write;

/// Emits C statements into a buffer.
pub(crate) struct CEmit<'a> {
    /// The program.
    pub p: &'a Program,
    /// How a slot is read or written (an lvalue).
    pub slot: &'a dyn Fn(SlotId) -> String,
    /// C statement returning an error: `fail(kind_expr, site, value_expr)`.
    pub fail: &'a dyn Fn(&str, u32, &str) -> String,
    /// Range failure: `(site, value, lo, hi)`.
    pub fail_range: &'a dyn Fn(u32, &str, i64, i64) -> String,
    /// Comment for a statement-level item (coverage labels), by cover id.
    pub cover_comment: &'a dyn Fn(u32) -> String,
    /// Statement recording that a coverage item was hit, when the code counts coverage.
    pub cover_hit: Option<&'a dyn Fn(u32) -> String>,
    /// Comment for a site.
    pub site_comment: &'a dyn Fn(u32) -> String,
    /// Procedure call statement (returns on error).
    pub call: &'a dyn Fn(u32) -> String,
    /// Switch case label for value `k` of a slot.
    pub case_label: &'a dyn Fn(SlotId, usize) -> String,
    /// Output.
    pub out: String,
    /// Indentation depth.
    pub depth: usize,
    /// Fresh temporary counter.
    pub tmp: usize,
}

/// A C literal of type `int64_t`.
pub(crate) fn lit(v: i64) -> String {
    if v == i64::MIN {
        "INT64_MIN".into()
    } else if (-(1i64 << 31)..(1i64 << 31)).contains(&v) {
        v.to_string()
    } else {
        format!("INT64_C({v})")
    }
}

/// True when evaluating node `e` can never fail and needs no statements.
pub(crate) fn pure(p: &Program, e: u32) -> bool {
    match p.nodes[e as usize] {
        Node::Const(_) | Node::Slot(_) | Node::Local(_) => true,
        Node::Unary(op, a) => !ops::unary_can_fail(op) && pure(p, a),
        Node::Binary(op, a, b, _) => {
            let rhs = match p.nodes[b as usize] {
                Node::Const(k) => Some(k),
                _ => None,
            };
            !ops::binary_can_fail(op, rhs) && pure(p, a) && pure(p, b)
        }
        Node::Ite(c, a, b) => pure(p, c) && pure(p, a) && pure(p, b),
        Node::Min(a, b) | Node::Max(a, b) => pure(p, a) && pure(p, b),
        Node::Abs(..) | Node::Check(..) | Node::Let(..) => false,
    }
}

/// The arms of an `if` whose `else` holds exactly one `if` (and so on): `(condition, body)` in
/// order, and the final `else`. Walking it is a loop, where recursing on the `else` would go
/// as deep as a state has transitions.
pub(crate) fn else_if_chain<'s>(
    cond: u32,
    then: &'s [Stmt],
    otherwise: &'s [Stmt],
) -> (Vec<(u32, &'s [Stmt])>, &'s [Stmt]) {
    let mut arms = vec![(cond, then)];
    let mut rest = otherwise;
    while let [Stmt::If {
        cond,
        then,
        otherwise,
    }] = rest
    {
        arms.push((*cond, then.as_slice()));
        rest = otherwise;
    }
    (arms, rest)
}

/// Every expression local bound or read in `stmts` (not through calls: each procedure
/// declares its own).
pub(crate) fn lets_in_stmts(
    p: &Program,
    stmts: &[Stmt],
    acc: &mut std::collections::BTreeSet<u32>,
) {
    for s in stmts {
        match s {
            Stmt::Assign { expr, .. } => lets_in_expr(p, *expr, acc),
            Stmt::If {
                cond,
                then,
                otherwise,
            } => {
                let (arms, rest) = else_if_chain(*cond, then, otherwise);
                for (c, body) in arms {
                    lets_in_expr(p, c, acc);
                    lets_in_stmts(p, body, acc);
                }
                lets_in_stmts(p, rest, acc);
            }
            Stmt::Switch { cases, .. } => cases.iter().for_each(|c| lets_in_stmts(p, c, acc)),
            Stmt::Call(_) | Stmt::Cover(_) => {}
        }
    }
}

/// Every local bound by a `Let` or read by a `Local` inside expression `e`.
pub(crate) fn lets_in_expr(p: &Program, e: u32, acc: &mut std::collections::BTreeSet<u32>) {
    match p.nodes[e as usize] {
        Node::Const(_) | Node::Slot(_) => {}
        Node::Local(l) => {
            acc.insert(l);
        }
        Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, ..) => lets_in_expr(p, a, acc),
        Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) => {
            lets_in_expr(p, a, acc);
            lets_in_expr(p, b, acc);
        }
        Node::Ite(c, a, b) => {
            lets_in_expr(p, c, acc);
            lets_in_expr(p, a, acc);
            lets_in_expr(p, b, acc);
        }
        Node::Let(l, v, b) => {
            acc.insert(l);
            lets_in_expr(p, v, acc);
            lets_in_expr(p, b, acc);
        }
    }
}

fn helper(op: BinOp) -> Option<&'static str> {
    Some(match op {
        BinOp::Add => "sc_add",
        BinOp::Sub => "sc_sub",
        BinOp::Mul => "sc_mul",
        BinOp::Div => "sc_div",
        BinOp::Rem => "sc_rem",
        BinOp::Shl => "sc_shl",
        BinOp::Shr => "sc_shr",
        _ => return None,
    })
}

impl CEmit<'_> {
    fn line(&mut self, text: &str) {
        for _ in 0..self.depth {
            self.out.push_str("    ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }

    fn fresh(&mut self) -> String {
        self.tmp += 1;
        format!("t{}", self.tmp)
    }

    /// Materialise `text` into a fresh temporary (to fix its evaluation point).
    fn bind(&mut self, text: String) -> String {
        let t = self.fresh();
        self.line(&format!("const int64_t {t} = {text};"));
        t
    }

    /// Evaluate children in order; earlier pure results are bound before later statements run.
    fn operands(&mut self, es: &[u32]) -> Vec<String> {
        let mut vals: Vec<String> = Vec::new();
        for (k, &e) in es.iter().enumerate() {
            let later_impure = es[k + 1..].iter().any(|&x| !pure(self.p, x));
            let v = self.expr(e);
            let v = if later_impure && !is_atom(&v) {
                self.bind(v)
            } else {
                v
            };
            vals.push(v);
        }
        vals
    }

    /// A C expression for node `e`, emitting the statements it needs first.
    pub(crate) fn expr(&mut self, e: u32) -> String {
        let p = self.p;
        match p.nodes[e as usize] {
            Node::Const(v) => lit(v),
            Node::Slot(s) => format!("sc_v({})", (self.slot)(s)),
            Node::Local(l) => format!("l{l}"),
            Node::Unary(op, a) => {
                let a = self.expr(a);
                match op {
                    UnOp::Not => format!("(int64_t)({a} == 0)"),
                    UnOp::BitNot => format!("(~{a})"),
                    UnOp::Neg => {
                        let a = if is_atom(&a) { a } else { self.bind(a) };
                        let t = self.fresh();
                        self.line(&format!("int64_t {t};"));
                        let f = (self.fail)("SC_ERR_OVERFLOW", u32::MAX, "0");
                        self.line(&format!("if ({a} == INT64_MIN) {{ {f} }}"));
                        self.line(&format!("{t} = -{a};"));
                        t
                    }
                }
            }
            Node::Binary(op, a, b, site) => self.binary_impl(op, a, b, site, pure(p, e)),
            Node::Ite(c, a, b) => {
                if pure(p, e) {
                    let (c, a, b) = (self.expr(c), self.expr(a), self.expr(b));
                    return format!("({c} != 0 ? {a} : {b})");
                }
                let c = self.expr(c);
                let t = self.fresh();
                self.line(&format!("int64_t {t};"));
                self.line(&format!("if ({c} != 0) {{"));
                self.branch(&t, a);
                self.line("} else {");
                self.branch(&t, b);
                self.line("}");
                t
            }
            Node::Min(a, b) | Node::Max(a, b) => {
                let f = if matches!(p.nodes[e as usize], Node::Min(..)) {
                    "sc_min"
                } else {
                    "sc_max"
                };
                let v = self.operands(&[a, b]);
                format!("{f}({}, {})", v[0], v[1])
            }
            Node::Abs(a, site) => {
                let a = self.expr(a);
                let a = if is_atom(&a) { a } else { self.bind(a) };
                let t = self.fresh();
                self.line(&format!("int64_t {t};"));
                let f = (self.fail)("SC_ERR_OVERFLOW", site, "0");
                self.line(&format!("if ({a} == INT64_MIN) {{ {f} }}"));
                self.line(&format!("{t} = {a} < 0 ? -{a} : {a};"));
                t
            }
            Node::Check(a, lo, hi, site) => {
                let v = self.expr(a);
                let v = if is_atom(&v) { v } else { self.bind(v) };
                let f = (self.fail_range)(site, &v, lo, hi);
                let c = (self.site_comment)(site);
                self.line(&format!(
                    "if ({v} < {} || {v} > {}) {{ {f} }} {c}",
                    lit(lo),
                    lit(hi)
                ));
                v
            }
            Node::Let(l, v, body) => {
                let v = self.expr(v);
                self.line(&format!("l{l} = {v};"));
                let b = self.expr(body);
                if pure(p, body) && !is_atom(&b) {
                    self.bind(b)
                } else {
                    b
                }
            }
        }
    }

    fn branch(&mut self, t: &str, e: u32) {
        self.depth += 1;
        let v = self.expr(e);
        self.line(&format!("{t} = {v};"));
        self.depth -= 1;
    }
}

/// True for a temporary, local or literal (safe to repeat without re-evaluation).
fn is_atom(v: &str) -> bool {
    v.chars()
        .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
}

impl CEmit<'_> {
    fn binary_impl(&mut self, op: BinOp, a: u32, b: u32, site: u32, is_pure: bool) -> String {
        if matches!(op, BinOp::And | BinOp::Or) && !is_pure {
            let va = self.expr(a);
            let t = self.fresh();
            let (init, cond) = if op == BinOp::And {
                ("0", format!("{va} != 0"))
            } else {
                ("1", format!("{va} == 0"))
            };
            self.line(&format!("int64_t {t} = {init};"));
            self.line(&format!("if ({cond}) {{"));
            self.depth += 1;
            let vb = self.expr(b);
            self.line(&format!("{t} = (int64_t)({vb} != 0);"));
            self.depth -= 1;
            self.line("}");
            return t;
        }
        let v = self.operands(&[a, b]);
        let (x, y) = (&v[0], &v[1]);
        let c = |s: &str| format!("(int64_t)({x} {s} {y})");
        match op {
            BinOp::Or => format!("(int64_t)({x} != 0 || {y} != 0)"),
            BinOp::And => format!("(int64_t)({x} != 0 && {y} != 0)"),
            BinOp::Eq => c("=="),
            BinOp::Ne => c("!="),
            BinOp::Lt => c("<"),
            BinOp::Le => c("<="),
            BinOp::Gt => c(">"),
            BinOp::Ge => c(">="),
            // Through the identity `sc_v`: gcc's -Wtautological-compare rejects a comparison
            // of `x | K` or `x & K` with a constant it can decide, such as `(x | 4) != 1`.
            BinOp::BitOr => format!("sc_v({x} | {y})"),
            BinOp::BitXor => format!("({x} ^ {y})"),
            BinOp::BitAnd => format!("sc_v({x} & {y})"),
            BinOp::Div | BinOp::Rem if is_pure => {
                let s = if op == BinOp::Div { "/" } else { "%" };
                format!("({x} {s} {y})")
            }
            BinOp::Shr if is_pure => format!("sc_shr_ok({x}, {y})"),
            _ => {
                let h = helper(op).unwrap_or("sc_add");
                let t = self.fresh();
                self.line(&format!("int64_t {t};"));
                let f = (self.fail)("e_", site, "0");
                let cm = (self.site_comment)(site);
                self.line(&format!(
                    "{{ const int e_ = {h}({x}, {y}, &{t}); if (e_ != 0) {{ {f} }} }} {cm}"
                ));
                t
            }
        }
    }

    /// Emit a block of statements.
    pub(crate) fn block(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            self.stmt(s);
        }
    }

    /// An `if` and the `else if`s nested in its `else` (a state's transitions in priority
    /// order), emitted flat: the chain is walked in a loop, so neither the output's indentation
    /// nor the emitter's recursion grows with its length. Conditions without temporaries become
    /// `else if`; otherwise the arms go in a `do { .. } while (0)` that each taken arm leaves
    /// with `break`.
    fn if_chain(&mut self, cond: u32, then: &[Stmt], otherwise: &[Stmt]) {
        let p = self.p;
        let (arms, rest) = else_if_chain(cond, then, otherwise);
        if arms.len() > 1 && arms.iter().all(|(c, _)| pure(p, *c)) {
            for (k, (c, body)) in arms.iter().enumerate() {
                let c = self.expr(*c);
                let kw = if k == 0 { "if" } else { "} else if" };
                self.line(&format!("{kw} ({c} != 0) {{"));
                self.depth += 1;
                self.block(body);
                self.depth -= 1;
            }
            if !rest.is_empty() {
                self.line("} else {");
                self.depth += 1;
                self.block(rest);
                self.depth -= 1;
            }
            self.line("}");
            return;
        }
        if arms.len() > 1 {
            self.line("do {");
            self.depth += 1;
            for (c, body) in &arms {
                let opened = !pure(p, *c);
                if opened {
                    self.line("{");
                    self.depth += 1;
                }
                let c = self.expr(*c);
                self.line(&format!("if ({c} != 0) {{"));
                self.depth += 1;
                self.block(body);
                self.line("break;");
                self.depth -= 1;
                self.line("}");
                if opened {
                    self.depth -= 1;
                    self.line("}");
                }
            }
            self.block(rest);
            self.depth -= 1;
            self.line("} while (0);");
            return;
        }
        let opened = !pure(p, cond);
        if opened {
            self.line("{");
            self.depth += 1;
        }
        let c = self.expr(cond);
        self.line(&format!("if ({c} != 0) {{"));
        self.depth += 1;
        self.block(then);
        self.depth -= 1;
        if otherwise.is_empty() {
            self.line("}");
        } else {
            self.line("} else {");
            self.depth += 1;
            self.block(otherwise);
            self.depth -= 1;
            self.line("}");
        }
        if opened {
            self.depth -= 1;
            self.line("}");
        }
    }

    fn stmt(&mut self, s: &Stmt) {
        let p = self.p;
        match s {
            Stmt::Assign { slot, expr, site } => {
                let dst = (self.slot)(*slot);
                let ty = crate::c::c_type(&p.slots[*slot as usize]);
                if pure(p, *expr) && site.is_none() {
                    let v = self.expr(*expr);
                    self.line(&format!("{dst} = ({ty}){v};"));
                    return;
                }
                self.line("{");
                self.depth += 1;
                let v = self.expr(*expr);
                let v = if is_atom(&v) { v } else { self.bind(v) };
                if let Some(site) = site {
                    let sl = &p.slots[*slot as usize];
                    let f = (self.fail_range)(*site, &v, sl.lo, sl.hi);
                    let c = (self.site_comment)(*site);
                    self.line(&format!(
                        "if ({v} < {} || {v} > {}) {{ {f} }} {c}",
                        lit(sl.lo),
                        lit(sl.hi)
                    ));
                }
                self.line(&format!("{dst} = ({ty}){v};"));
                self.depth -= 1;
                self.line("}");
            }
            Stmt::If {
                cond,
                then,
                otherwise,
            } => self.if_chain(*cond, then, otherwise),
            Stmt::Switch { slot, cases } => {
                let sel = (self.slot)(*slot);
                self.line(&format!("switch ((int64_t){sel}) {{"));
                for (k, case) in cases.iter().enumerate() {
                    let label = (self.case_label)(*slot, k);
                    self.line(&format!("case {label}:"));
                    self.depth += 1;
                    self.block(case);
                    self.line("break;");
                    self.depth -= 1;
                }
                self.line("default:");
                self.line("    break;");
                self.line("}");
            }
            Stmt::Call(proc_id) => {
                let c = (self.call)(*proc_id);
                self.line(&c);
            }
            Stmt::Cover(c) => {
                let text = (self.cover_comment)(*c);
                let mut s = String::new();
                let _ = write!(s, "/* {text} */");
                self.line(&s);
                if let Some(hit) = self.cover_hit {
                    let h = hit(*c);
                    self.line(&h);
                }
            }
        }
    }
}
