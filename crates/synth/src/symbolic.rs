//! The symbolic engine: the same fixpoint as [`crate::explicit`], on BDDs over the bits of
//! the location vector (biodivine-lib-bdd), never enumerating product states.
//!
//! Choices (docs/synthesis.md, "Symbolic engine"):
//! - **Variable order**: static, from the FORCE heuristic over the automata's event-sharing
//!   hypergraph ([`crate::order`]), each automaton's bits together.
//! - **Images without next-state variables**: automata are deterministic, so the pre-image of
//!   a set `S` under event `e` substitutes, automaton by automaton, each of `e`'s transitions
//!   `src → dst` into `S` (`loc = src ∧ S[loc := dst]`, a cofactor); the post-image does the
//!   reverse. This is the transition relation partitioned per event and per automaton, with
//!   each automaton's next-state bits quantified as soon as its part is applied.
//! - **Reachable part only**: the forward reachable product (requirement-allowed moves,
//!   `never` states not expanded, as the explicit engine explores it) is computed first, and every
//!   fixpoint stays inside it; its size is the reported product size.
//! - **Chaining and frontiers**: each fixpoint applies the events one after the other to the
//!   growing set (chaining), and images are taken of the newly added states only.

use crate::encode::Encoding;
use crate::error::Error;
use crate::limits::Budget;
use crate::problem::{EventId, Kind, Pred, Problem};
use biodivine_lib_bdd::Bdd;

/// The result of the symbolic fixpoint.
pub struct Symbolic {
    /// The encoding the sets are expressed in.
    pub enc: Encoding,
    /// The reachable product (plant × requirements, bad states not expanded).
    pub product: Bdd,
    /// Kept states (after the fixpoint, within the reachable product).
    pub good: Bdd,
    /// Controlled reachable states (empty if the initial state is not kept).
    pub reach: Bdd,
    /// Per event: every plant automaton with it can take it.
    pub plant_en: Vec<Bdd>,
    /// Per event: the requirements (automata and `needs`) allow it.
    pub req_en: Vec<Bdd>,
    /// Fixpoint rounds (controllability + nonblocking) until stable.
    pub rounds: usize,
    /// The automata in the order of their bits ([`crate::order::force`] unless given).
    pub order: Vec<usize>,
}

/// The problem's transitions and enabling conditions as BDDs.
pub(crate) struct Ctx<'p> {
    p: &'p Problem,
    enc: Encoding,
    /// Per event, per automaton with it: its transitions `(src, dst)`, as `(loc = src,
    /// assignment of dst, loc = dst, assignment of src)`.
    moves: Vec<Vec<Vec<Step>>>,
    plant_en: Vec<Bdd>,
    req_en: Vec<Bdd>,
    /// Per event: `plant_en ∧ req_en`.
    en: Vec<Bdd>,
}

type Assign = Vec<(biodivine_lib_bdd::BddVariable, bool)>;

/// One transition of one automaton, prepared for images.
struct Step {
    at_src: Bdd,
    src: Assign,
    at_dst: Bdd,
    dst: Assign,
}

impl<'p> Ctx<'p> {
    fn new(p: &'p Problem, order: &[usize]) -> Ctx<'p> {
        let enc = Encoding::with_order(p, order);
        let mut moves: Vec<Vec<Vec<Step>>> = (0..p.events.len()).map(|_| Vec::new()).collect();
        for (ai, a) in p.automata.iter().enumerate() {
            for &e in &a.alphabet {
                let steps = (0..a.locs.len() as u32)
                    .filter_map(|l| a.step(l, e).map(|t| (l, t)))
                    .map(|(s, t)| Step {
                        at_src: enc.loc_eq(ai, s),
                        src: enc.assign(ai, s),
                        at_dst: enc.loc_eq(ai, t),
                        dst: enc.assign(ai, t),
                    })
                    .collect();
                moves[e as usize].push(steps);
            }
        }
        let mut cx = Ctx {
            p,
            enc,
            moves,
            plant_en: Vec::new(),
            req_en: Vec::new(),
            en: Vec::new(),
        };
        for e in 0..p.events.len() as EventId {
            let pe = cx.enabled(Kind::Plant, e);
            let mut re = cx.enabled(Kind::Requirement, e);
            for n in p.needs.iter().filter(|n| n.event == e) {
                re = re.and(&cx.pred(&n.cond));
            }
            cx.en.push(pe.and(&re));
            cx.plant_en.push(pe);
            cx.req_en.push(re);
        }
        cx
    }

    fn enabled(&self, kind: Kind, e: EventId) -> Bdd {
        let mut r = self.enc.vars.mk_true();
        for (ai, a) in self.p.automata.iter().enumerate() {
            if a.kind != kind || !a.has(e) {
                continue;
            }
            let mut any = self.enc.vars.mk_false();
            for l in 0..a.locs.len() as u32 {
                if a.step(l, e).is_some() {
                    any = any.or(&self.enc.loc_eq(ai, l));
                }
            }
            r = r.and(&any);
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
    pub(crate) fn pre(&self, e: EventId, s: &Bdd) -> Bdd {
        let mut r = s.clone();
        for steps in &self.moves[e as usize] {
            let mut acc = self.enc.vars.mk_false();
            for st in steps {
                let cof = r.restrict(&st.dst);
                if !cof.is_false() {
                    acc = acc.or(&cof.and(&st.at_src));
                }
            }
            r = acc;
            if r.is_false() {
                return r;
            }
        }
        r.and(&self.en[e as usize])
    }

    /// Successors of `s` by `e` (allowed by the requirements).
    fn post(&self, e: EventId, s: &Bdd) -> Bdd {
        let mut r = s.and(&self.en[e as usize]);
        for steps in &self.moves[e as usize] {
            if r.is_false() {
                return r;
            }
            let mut acc = self.enc.vars.mk_false();
            for st in steps {
                let cof = r.restrict(&st.src);
                if !cof.is_false() {
                    acc = acc.or(&cof.and(&st.at_dst));
                }
            }
            r = acc;
        }
        r
    }
}

fn bytes(sets: &[&Bdd]) -> u64 {
    sets.iter().map(|b| b.size() as u64 * 12).sum()
}

/// Least set containing `start` and closed under `step` within `within` (chaining: each
/// event's image is added before the next event's is taken; images of new states only).
fn closure(
    start: Bdd,
    events: &[EventId],
    within: &Bdd,
    budget: &Budget,
    phase: &'static str,
    mut step: impl FnMut(EventId, &Bdd) -> Bdd,
) -> Result<Bdd, Error> {
    let mut all = start.and(within);
    let mut frontier = all.clone();
    while !frontier.is_false() {
        let mut new = all.and_not(&all);
        for &e in events {
            let img = step(e, &frontier).and(within).and_not(&all);
            if !img.is_false() {
                all = all.or(&img);
                new = new.or(&img);
                frontier = frontier.or(&img);
            }
        }
        budget.check(phase, all.cardinality(), bytes(&[&all, &frontier]))?;
        frontier = new;
    }
    Ok(all)
}

/// Run the symbolic engine within `budget`, with the variable order of
/// [`crate::order::force`].
pub fn run(p: &Problem, budget: &Budget) -> Result<Symbolic, Error> {
    run_ordered(p, budget, &crate::order::force(p))
}

/// Run the symbolic engine with the automata's bits in `order` (a permutation of the
/// automata; for measuring orders).
pub fn run_ordered(p: &Problem, budget: &Budget, order: &[usize]) -> Result<Symbolic, Error> {
    let cx = Ctx::new(p, order);
    let n_ev = p.events.len();
    let all_events: Vec<EventId> = (0..n_ev as EventId).collect();
    let unc: Vec<EventId> = (0..n_ev as EventId)
        .filter(|e| !p.events[*e as usize].controllable)
        .collect();
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
    let mut never = cx.enc.vars.mk_false();
    for n in &p.never {
        never = never.or(&cx.pred(n));
    }
    let mut bad = never.clone();
    for &u in &unc {
        bad = bad.or(&cx.plant_en[u as usize].and_not(&cx.req_en[u as usize]));
    }
    let init = cx.enc.state(&p.initial());
    let valid = cx.enc.valid();
    // The reachable product: `never` states are reached but not expanded (as in the
    // explicit engine, whose count this is).
    let product = closure(
        init.clone(),
        &all_events,
        &valid,
        budget,
        "reachability",
        |e, s| cx.post(e, &s.and_not(&never)),
    )?;
    let mut good = product.and_not(&bad);
    let mut rounds = 0;
    loop {
        rounds += 1;
        // Controllability: remove the states with an uncontrollable move out of the kept set.
        let removed = closure(
            product.and_not(&good),
            &unc,
            &product,
            budget,
            "fixpoint",
            |u, s| cx.pre(u, s),
        )?;
        good = product.and_not(&removed);
        // Nonblocking: the states of `good` that reach a marked state inside `good`.
        let coreach = closure(
            good.and(&marked),
            &all_events,
            &good,
            budget,
            "fixpoint",
            |e, s| cx.pre(e, s),
        )?;
        if good.and_not(&coreach).is_false() {
            break;
        }
        good = coreach;
    }
    let reach = if init.and(&good).is_false() {
        cx.enc.vars.mk_false()
    } else {
        closure(init, &all_events, &good, budget, "fixpoint", |e, s| {
            cx.post(e, s)
        })?
    };
    Ok(Symbolic {
        product,
        good,
        reach,
        plant_en: cx.plant_en.clone(),
        req_en: cx.req_en.clone(),
        rounds,
        order: order.to_vec(),
        enc: cx.enc,
    })
}

/// Per event, the states of the controlled behaviour where the event is allowed and leads to
/// a kept state; used for guards and for counting transitions.
pub fn allowed_sets(p: &Problem, s: &Symbolic) -> Vec<Bdd> {
    let cx = Ctx::new(p, &s.order);
    (0..p.events.len() as EventId)
        .map(|e| cx.pre(e, &s.good).and(&s.reach))
        .collect()
}
