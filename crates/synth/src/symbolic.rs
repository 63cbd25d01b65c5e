//! The symbolic engine: the same fixpoint as [`crate::explicit`], on BDDs over the bits of
//! the location vector (biodivine-lib-bdd), never enumerating product states.
//!
//! Images need no next-state variables because automata are deterministic: the pre-image of
//! a set `S` under event `e` substitutes, automaton by automaton, each of `e`'s transitions
//! `src → dst` into `S` (`loc = src ∧ S[loc := dst]`, a cofactor), and the post-image does
//! the reverse.

use crate::encode::Encoding;
use crate::problem::{EventId, Kind, Pred, Problem};
use biodivine_lib_bdd::Bdd;

/// The result of the symbolic fixpoint.
pub struct Symbolic {
    /// The encoding the sets are expressed in.
    pub enc: Encoding,
    /// Kept states (after the fixpoint, not yet restricted to reachable ones).
    pub good: Bdd,
    /// Controlled reachable states (empty if the initial state is not kept).
    pub reach: Bdd,
    /// Per event: every plant automaton with it can take it.
    pub plant_en: Vec<Bdd>,
    /// Per event: the requirements (automata and `needs`) allow it.
    pub req_en: Vec<Bdd>,
    /// Fixpoint rounds (nonblocking + controllability) until stable.
    pub rounds: usize,
}

struct Ctx<'p> {
    p: &'p Problem,
    enc: Encoding,
    /// Per event, per automaton with it: its transitions `(src, dst)`.
    moves: Vec<Vec<Moves>>,
    plant_en: Vec<Bdd>,
    req_en: Vec<Bdd>,
}

/// One automaton's transitions on one event: `(automaton, [(src, dst)])`.
type Moves = (usize, Vec<(u32, u32)>);

/// Per event, the transitions of every automaton that has it.
fn moves_of(p: &Problem) -> Vec<Vec<Moves>> {
    let mut moves: Vec<Vec<Moves>> = vec![Vec::new(); p.events.len()];
    for (ai, a) in p.automata.iter().enumerate() {
        for &e in &a.alphabet {
            let ts: Vec<(u32, u32)> = (0..a.locs.len() as u32)
                .filter_map(|l| a.step(l, e).map(|t| (l, t)))
                .collect();
            moves[e as usize].push((ai, ts));
        }
    }
    moves
}

impl Ctx<'_> {
    fn enabled(&self, kind: Kind, e: EventId) -> Bdd {
        let mut r = self.enc.vars.mk_true();
        for (a, ts) in &self.moves[e as usize] {
            if self.p.automata[*a].kind == kind {
                let mut any = self.enc.vars.mk_false();
                for (src, _) in ts {
                    any = any.or(&self.enc.loc_eq(*a, *src));
                }
                r = r.and(&any);
            }
        }
        r
    }

    fn pred(&self, p: &Pred) -> Bdd {
        match p {
            Pred::Const(true) => self.enc.vars.mk_true(),
            Pred::Const(false) => self.enc.vars.mk_false(),
            Pred::At(a, l) => self.enc.loc_eq(*a as usize, *l),
            Pred::Not(x) => self.pred(x).not(),
            Pred::And(a, b) => self.pred(a).and(&self.pred(b)),
            Pred::Or(a, b) => self.pred(a).or(&self.pred(b)),
        }
    }

    /// States with an `e`-transition (allowed by the requirements) into `s`.
    fn pre(&self, e: EventId, s: &Bdd) -> Bdd {
        let mut r = s.clone();
        for (a, ts) in &self.moves[e as usize] {
            let mut acc = self.enc.vars.mk_false();
            for (src, dst) in ts {
                let cof = r.restrict(&self.enc.assign(*a, *dst));
                acc = acc.or(&cof.and(&self.enc.loc_eq(*a, *src)));
            }
            r = acc;
        }
        r.and(&self.plant_en[e as usize])
            .and(&self.req_en[e as usize])
    }

    /// Successors of `s` by `e` (allowed by the requirements).
    fn post(&self, e: EventId, s: &Bdd) -> Bdd {
        let mut r = s
            .and(&self.plant_en[e as usize])
            .and(&self.req_en[e as usize]);
        for (a, ts) in &self.moves[e as usize] {
            let mut acc = self.enc.vars.mk_false();
            for (src, dst) in ts {
                let cof = r.restrict(&self.enc.assign(*a, *src));
                acc = acc.or(&cof.and(&self.enc.loc_eq(*a, *dst)));
            }
            r = acc;
        }
        r
    }
}

/// Run the symbolic engine.
pub fn run(p: &Problem) -> Symbolic {
    let enc = Encoding::new(p);
    let n_ev = p.events.len();
    let moves = moves_of(p);
    let mut cx = Ctx {
        p,
        enc,
        moves,
        plant_en: Vec::new(),
        req_en: Vec::new(),
    };
    for e in 0..n_ev as EventId {
        let pe = cx.enabled(Kind::Plant, e);
        let mut re = cx.enabled(Kind::Requirement, e);
        for n in p.needs.iter().filter(|n| n.event == e) {
            re = re.and(&cx.pred(&n.cond));
        }
        cx.plant_en.push(pe);
        cx.req_en.push(re);
    }
    let valid = cx.enc.valid();
    let mut marked = cx.enc.vars.mk_true();
    for (ai, a) in p.automata.iter().enumerate() {
        let mut any = cx.enc.vars.mk_false();
        for (l, m) in a.marked.iter().enumerate() {
            if *m {
                any = any.or(&cx.enc.loc_eq(ai, l as u32));
            }
        }
        marked = marked.and(&any);
    }
    let mut bad = cx.enc.vars.mk_false();
    for n in &p.never {
        bad = bad.or(&cx.pred(n));
    }
    let unc: Vec<EventId> = (0..n_ev as EventId)
        .filter(|e| !p.events[*e as usize].controllable)
        .collect();
    for &u in &unc {
        bad = bad.or(&cx.plant_en[u as usize].and_not(&cx.req_en[u as usize]));
    }
    let mut good = valid.and_not(&bad);
    let mut rounds = 0;
    loop {
        rounds += 1;
        // Nonblocking: the states of `good` that reach a marked state inside `good`.
        let mut z = good.and(&marked);
        loop {
            let mut next = z.clone();
            for e in 0..n_ev as EventId {
                next = next.or(&cx.pre(e, &z).and(&good));
            }
            if next == z {
                break;
            }
            z = next;
        }
        // Controllability: remove states with an uncontrollable move out of the kept set.
        let mut b = valid.and_not(&z);
        loop {
            let mut next = b.clone();
            for &u in &unc {
                next = next.or(&cx.pre(u, &b));
            }
            let next = next.and(&valid);
            if next == b {
                break;
            }
            b = next;
        }
        let new_good = valid.and_not(&b);
        if new_good == good {
            break;
        }
        good = new_good;
    }
    let init = cx.enc.state(&p.initial());
    let mut reach = cx.enc.vars.mk_false();
    if !init.and(&good).is_false() {
        reach = init;
        loop {
            let mut next = reach.clone();
            for e in 0..n_ev as EventId {
                next = next.or(&cx.post(e, &reach).and(&good));
            }
            if next == reach {
                break;
            }
            reach = next;
        }
    }
    Symbolic {
        enc: cx.enc,
        good,
        reach,
        plant_en: cx.plant_en,
        req_en: cx.req_en,
        rounds,
    }
}

/// Per-event pre-image of `good` restricted to `reach`, i.e. the states of the controlled
/// behaviour where `e` is allowed; used for guards and for counting transitions.
pub fn allowed_sets(p: &Problem, s: &Symbolic) -> Vec<Bdd> {
    let n_ev = p.events.len();
    let moves = moves_of(p);
    let cx = Ctx {
        p,
        enc: Encoding::new(p),
        moves,
        plant_en: s.plant_en.clone(),
        req_en: s.req_en.clone(),
    };
    (0..n_ev as EventId)
        .map(|e| cx.pre(e, &s.good).and(&s.reach))
        .collect()
}
