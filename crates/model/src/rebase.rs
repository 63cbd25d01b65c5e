//! Re-target a chart-level expression at one instance of a system.

use crate::model::{Expr, ExprKind, Property, PropertyKind};

/// Make every "this instance" reference in `e` refer to instance `inst`.
pub(crate) fn expr(e: &mut Expr, inst: u32) {
    match &mut e.kind {
        ExprKind::Const(_) | ExprKind::Local(_) => {}
        ExprKind::Let(_, v, b) => {
            expr(v, inst);
            expr(b, inst);
        }
        ExprKind::Var(v) => {
            v.instance.get_or_insert(inst);
        }
        ExprKind::In(s) => {
            s.instance.get_or_insert(inst);
        }
        ExprKind::Unary(_, a) | ExprKind::Check(a, ..) => expr(a, inst),
        ExprKind::Binary(_, a, b) => {
            expr(a, inst);
            expr(b, inst);
        }
        ExprKind::If(c, a, b) => {
            expr(c, inst);
            expr(a, inst);
            expr(b, inst);
        }
        ExprKind::Builtin(_, args) => args.iter_mut().for_each(|a| expr(a, inst)),
    }
}

/// Re-target a property.
pub(crate) fn property(p: &mut Property, inst: u32) {
    match &mut p.kind {
        PropertyKind::Invariant { expr: e, assuming } => {
            expr(e, inst);
            if let Some(a) = assuming {
                expr(a, inst);
            }
        }
        PropertyKind::Reachable { expr: e } => expr(e, inst),
        PropertyKind::Respond {
            trigger, response, ..
        }
        | PropertyKind::RespondEventually { trigger, response } => {
            expr(trigger, inst);
            expr(response, inst);
        }
        PropertyKind::Ltl(f) | PropertyKind::Ctl(f) => f.atoms_mut(&mut |e| expr(e, inst)),
        PropertyKind::Nonblocking { expr: e } => expr(e, inst),
        PropertyKind::Fair { trigger, expr: e } => {
            if let Some(t) = trigger {
                expr(t, inst);
            }
            expr(e, inst);
        }
    }
}
