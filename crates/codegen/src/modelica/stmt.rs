//! IR statements as Modelica algorithm statements, in the paper's shape: a `switch` on a
//! level's selector becomes `if goState == GoStateT.GoLeft then ... elseif ...` (the "if-clauses
//! for transitions" of §2.4), a chain of transitions tried in priority order becomes one
//! `if ... elseif ... else` chain, and each entry/exit procedure is inlined where the IR calls
//! it, so entry activities run exactly where the step semantics runs them.

use super::expr::{Emit, V};
use super::names::Ty;
use super::text::{strip, strip_rhs};
use statecheck_ir::{CoverKind, Stmt};

impl Emit<'_> {
    /// Emit a block of statements.
    pub(crate) fn block(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            self.stmt(s);
        }
    }

    /// Emit `stmts` one level deeper into a separate buffer: (text, statements written).
    fn capture(&mut self, stmts: &[Stmt]) -> (String, usize) {
        let saved = std::mem::take(&mut self.out);
        let before = self.written;
        self.depth += 1;
        self.block(stmts);
        self.depth -= 1;
        let text = std::mem::replace(&mut self.out, saved);
        (text, self.written - before)
    }

    fn stmt(&mut self, s: &Stmt) {
        let p = self.p;
        match s {
            Stmt::Assign { slot, expr, site } => {
                let dst = self.n.vars[*slot as usize].clone();
                let want = self.n.tys[*slot as usize];
                let value = match site {
                    None => self.expr_as(*expr, want),
                    Some(site) => {
                        let v = self.expr(*expr);
                        let v = self.atom_int(v);
                        let sl = &p.slots[*slot as usize];
                        self.assert_range(&v, sl.lo, sl.hi, *site);
                        self.conv(
                            V {
                                text: v,
                                ty: Ty::Int,
                                atom: true,
                            },
                            want,
                        )
                    }
                };
                self.line(&format!("{dst} := {};", strip_rhs(&value)));
            }
            Stmt::If {
                cond,
                then,
                otherwise,
            } => {
                let c = self.expr_as(*cond, Ty::Bool);
                self.line(&format!("if {} then", strip(&c)));
                let (t, _) = self.capture(then);
                self.out.push_str(&t);
                let mut rest: &[Stmt] = otherwise;
                loop {
                    match rest {
                        [] => break,
                        [Stmt::If {
                            cond,
                            then,
                            otherwise,
                        }] if self.pure(*cond) => {
                            let c = self.expr_as(*cond, Ty::Bool);
                            self.line(&format!("elseif {} then", strip(&c)));
                            let (t, _) = self.capture(then);
                            self.out.push_str(&t);
                            rest = otherwise;
                        }
                        _ => {
                            self.line("else");
                            let (t, _) = self.capture(rest);
                            self.out.push_str(&t);
                            break;
                        }
                    }
                }
                self.line("end if;");
            }
            Stmt::Switch { slot, cases } => {
                let sel = self.n.vars[*slot as usize].clone();
                let ty = self.n.tys[*slot as usize];
                // Cases that do nothing are left out: the others test exclusive values.
                let arms: Vec<(usize, String)> = cases
                    .iter()
                    .enumerate()
                    .filter_map(|(k, case)| {
                        let (text, _) = self.capture(case);
                        (!text.is_empty()).then_some((k, text))
                    })
                    .collect();
                for (j, (k, text)) in arms.iter().enumerate() {
                    let value = match ty {
                        Ty::Enum(t) => self.n.literal(t, *k as i64),
                        _ => None,
                    };
                    let cond = match (value, ty) {
                        (Some(l), _) => format!("{sel} == {l}"),
                        (None, Ty::Bool) if *k == 0 => format!("not {sel}"),
                        (None, Ty::Bool) => sel.clone(),
                        (None, Ty::Enum(_)) => format!("Integer({sel}) - 1 == {k}"),
                        (None, Ty::Int) => format!("{sel} == {k}"),
                    };
                    let kw = if j == 0 { "if" } else { "elseif" };
                    self.line(&format!("{kw} {cond} then"));
                    self.out.push_str(text);
                }
                if !arms.is_empty() {
                    self.line("end if;");
                }
            }
            Stmt::Call(k) => {
                let Some(proc_) = p.procs.get(*k as usize) else {
                    self.error = Some(format!("call of unknown procedure {k}"));
                    return;
                };
                if self.stack.contains(k) {
                    self.error = Some(format!("procedure `{}` calls itself", proc_.name));
                    return;
                }
                self.stack.push(*k);
                self.depth -= 1;
                let (text, _) = self.capture(&proc_.body);
                self.depth += 1;
                self.stack.pop();
                if !text.is_empty() {
                    self.line(&format!("// {}", proc_.name));
                }
                self.out.push_str(&text);
            }
            Stmt::Cover(c) => {
                let Some(cv) = p.covers.get(*c as usize) else {
                    return;
                };
                let what = match cv.kind {
                    CoverKind::State(_) => "entry of",
                    CoverKind::Transition(_) => "transition",
                    CoverKind::Branch(..) => "via",
                };
                let inst = match p.instances.get(cv.instance as usize) {
                    Some(i) if p.instances.len() > 1 => format!("{}: ", i.name),
                    _ => String::new(),
                };
                let at = self.src.at(cv.span);
                self.line(&format!("// {inst}{what} {} ({at})", cv.label));
                if let Some((arr, idx)) = self.counters.and_then(|all| all.get(*c as usize)) {
                    self.line(&format!("{arr}[{idx}] := {arr}[{idx}] + 1;"));
                }
            }
        }
    }
}
