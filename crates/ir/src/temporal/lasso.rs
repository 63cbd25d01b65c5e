//! The meaning of an LTL formula on a lasso: positions `0..n` where the position after `n-1`
//! is `loop_start` again (an ultimately periodic run). Used to replay lasso scenarios in the
//! simulator independently of the checker's automata.

use super::Ltl;
use crate::ExprId;

/// True when the lasso satisfies `f` at position 0; `atom(e, i)` is atom `e` at position `i`.
/// `n >= 1` and `loop_start < n`.
pub fn holds_on_lasso(
    f: &Ltl,
    atom: &dyn Fn(ExprId, usize) -> bool,
    n: usize,
    loop_start: usize,
) -> bool {
    values(f, atom, n, loop_start)
        .first()
        .copied()
        .unwrap_or(false)
}

/// The formula's value at every position (recursion bounded by the formula's depth, which
/// the parser bounds).
fn values(f: &Ltl, atom: &dyn Fn(ExprId, usize) -> bool, n: usize, l: usize) -> Vec<bool> {
    let next = |i: usize| if i + 1 < n { i + 1 } else { l };
    let rec = |g: &Ltl| values(g, atom, n, l);
    match f {
        Ltl::True => vec![true; n],
        Ltl::False => vec![false; n],
        Ltl::Atom(e) => (0..n).map(|i| atom(*e, i)).collect(),
        Ltl::Not(a) => rec(a).into_iter().map(|x| !x).collect(),
        Ltl::And(a, b) => rec(a)
            .into_iter()
            .zip(rec(b))
            .map(|(x, y)| x && y)
            .collect(),
        Ltl::Or(a, b) => rec(a)
            .into_iter()
            .zip(rec(b))
            .map(|(x, y)| x || y)
            .collect(),
        Ltl::Next(a) => {
            let v = rec(a);
            (0..n).map(|i| v[next(i)]).collect()
        }
        Ltl::Until(a, b) | Ltl::Release(a, b) => {
            let until = matches!(f, Ltl::Until(..));
            let (va, vb) = (rec(a), rec(b));
            // Least (until) or greatest (release) fixpoint, by backward sweeps: two rounds
            // around the loop reach it.
            let mut v = vec![!until; n];
            for _ in 0..2 {
                for i in (0..n).rev() {
                    v[i] = if until {
                        vb[i] || (va[i] && v[next(i)])
                    } else {
                        vb[i] && (va[i] || v[next(i)])
                    };
                }
            }
            v
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn b(f: Ltl) -> Box<Ltl> {
        Box::new(f)
    }

    #[test]
    fn hand_checked_lassos() {
        // Word: p at positions 0 and 2; loop 1 -> 2 -> 1. So p holds infinitely often,
        // G p fails, F G p fails, G F p holds, X p fails (position 1 has no p).
        let p = |_: ExprId, i: usize| i == 0 || i == 2;
        let a = || Ltl::Atom(0);
        let gf = Ltl::Release(b(Ltl::False), b(Ltl::Until(b(Ltl::True), b(a()))));
        let g = Ltl::Release(b(Ltl::False), b(a()));
        let fg = Ltl::Until(b(Ltl::True), b(g.clone()));
        assert!(holds_on_lasso(&gf, &p, 3, 1));
        assert!(!holds_on_lasso(&g, &p, 3, 1));
        assert!(!holds_on_lasso(&fg, &p, 3, 1));
        assert!(!holds_on_lasso(&Ltl::Next(b(a())), &p, 3, 1));
        // Loop on position 2 alone: p forever after 2, so F G p holds.
        assert!(holds_on_lasso(&fg, &p, 3, 2));
        // a U b where b never holds: false; a R b with b always: true.
        let never = |e: ExprId, _: usize| e == 0;
        let u = Ltl::Until(b(Ltl::Atom(0)), b(Ltl::Atom(1)));
        assert!(!holds_on_lasso(&u, &never, 2, 0));
        let r = Ltl::Release(b(Ltl::Atom(1)), b(Ltl::Atom(0)));
        assert!(holds_on_lasso(&r, &never, 2, 0));
    }
}
