//! LTL to generalised Büchi automata by the tableau of Gerth, Peled, Vardi and Wolper
//! ("Simple on-the-fly automatic verification of linear temporal logic", 1995), with
//! simplifications: the formula is put in negation normal form and rewritten (`X true = true`,
//! `F F a = F a`, `G G a = G a`, `a U false = false`, constants folded), tableau nodes with
//! contradictory literals are dropped, and completed nodes with equal `Old` and `Next` sets
//! are merged (the algorithm's own merge). The expansion uses an explicit work stack, so a
//! deep formula cannot overflow the call stack.
//!
//! The automaton is state-labelled: a run reads position `i` in state `q_i` when the
//! position's letter satisfies `q_i`'s literals. Acceptance is generalised: one set per
//! `a U b` subformula (the states that do not promise it, or fulfil `b`).

use super::Ltl;
use crate::ExprId;
use std::collections::{BTreeSet, HashMap};

/// Most tableau nodes before the translation gives up.
pub const MAX_NODES: usize = 100_000;

/// A formula in negation normal form, interned.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum N {
    True,
    False,
    /// Atom index, polarity.
    Lit(u32, bool),
    And(u32, u32),
    Or(u32, u32),
    Next(u32),
    U(u32, u32),
    R(u32, u32),
}

#[derive(Default)]
struct Arena {
    nodes: Vec<N>,
    ids: HashMap<N, u32>,
}

impl Arena {
    fn get(&mut self, n: N) -> u32 {
        let n = self.simplify(n);
        if let Some(&i) = self.ids.get(&n) {
            return i;
        }
        let i = self.nodes.len() as u32;
        self.nodes.push(n);
        self.ids.insert(n, i);
        i
    }

    fn simplify(&self, n: N) -> N {
        let k = |i: u32| self.nodes[i as usize];
        match n {
            N::And(a, b) => match (k(a), k(b)) {
                (N::False, _) | (_, N::False) => N::False,
                (N::True, x) => x,
                (x, N::True) => x,
                _ if a == b => k(a),
                _ => N::And(a.min(b), a.max(b)),
            },
            N::Or(a, b) => match (k(a), k(b)) {
                (N::True, _) | (_, N::True) => N::True,
                (N::False, x) => x,
                (x, N::False) => x,
                _ if a == b => k(a),
                _ => N::Or(a.min(b), a.max(b)),
            },
            N::Next(a) => match k(a) {
                N::True => N::True,
                N::False => N::False,
                _ => n,
            },
            N::U(a, b) => match (k(a), k(b)) {
                (_, N::True) => N::True,
                (_, N::False) => N::False,
                (N::False, x) => x,
                // F F b = F b
                (N::True, N::U(t, _)) if k(t) == N::True => k(b),
                _ => n,
            },
            N::R(a, b) => match (k(a), k(b)) {
                (_, N::False) => N::False,
                (_, N::True) => N::True,
                (N::True, x) => x,
                // G G b = G b
                (N::False, N::R(f, _)) if k(f) == N::False => k(b),
                _ => n,
            },
            _ => n,
        }
    }

    /// The negation normal form of `f` (negated when `neg`); atoms are numbered by `atom`.
    fn nnf(&mut self, f: &Ltl, neg: bool, atom: &mut dyn FnMut(ExprId) -> u32) -> u32 {
        // Explicit stack: (formula, negated, phase); results on a value stack.
        enum Task<'a> {
            Visit(&'a Ltl, bool),
            Build(&'a Ltl, bool),
        }
        let mut tasks = vec![Task::Visit(f, neg)];
        let mut vals: Vec<u32> = Vec::new();
        while let Some(t) = tasks.pop() {
            match t {
                Task::Visit(f, neg) => match f {
                    Ltl::True => vals.push(self.get(if neg { N::False } else { N::True })),
                    Ltl::False => vals.push(self.get(if neg { N::True } else { N::False })),
                    Ltl::Atom(e) => {
                        let a = atom(*e);
                        vals.push(self.get(N::Lit(a, !neg)));
                    }
                    Ltl::Not(a) => tasks.push(Task::Visit(a, !neg)),
                    Ltl::Next(a) => {
                        tasks.push(Task::Build(f, neg));
                        tasks.push(Task::Visit(a, neg));
                    }
                    Ltl::And(a, b) | Ltl::Or(a, b) | Ltl::Until(a, b) | Ltl::Release(a, b) => {
                        tasks.push(Task::Build(f, neg));
                        tasks.push(Task::Visit(b, neg));
                        tasks.push(Task::Visit(a, neg));
                    }
                },
                Task::Build(f, neg) => {
                    let n = match f {
                        Ltl::Next(_) => {
                            let a = vals.pop().unwrap_or(0);
                            N::Next(a)
                        }
                        _ => {
                            let b = vals.pop().unwrap_or(0);
                            let a = vals.pop().unwrap_or(0);
                            match (f, neg) {
                                (Ltl::And(..), false) | (Ltl::Or(..), true) => N::And(a, b),
                                (Ltl::Or(..), false) | (Ltl::And(..), true) => N::Or(a, b),
                                (Ltl::Until(..), false) | (Ltl::Release(..), true) => N::U(a, b),
                                _ => N::R(a, b),
                            }
                        }
                    };
                    vals.push(self.get(n));
                }
            }
        }
        vals.pop().unwrap_or(0)
    }
}

/// A state of the automaton: the literals a position must satisfy.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct State {
    /// Atoms (bit `i` = atom `i`) that must hold.
    pub pos: u64,
    /// Atoms that must not hold.
    pub neg: u64,
}

impl State {
    /// True when a position with letter `l` can be read in this state.
    #[inline]
    pub fn admits(&self, l: u64) -> bool {
        l & self.pos == self.pos && l & self.neg == 0
    }
}

/// A generalised Büchi automaton with state labels.
#[derive(Clone, Debug)]
pub struct Buchi {
    /// States.
    pub states: Vec<State>,
    /// States a run may start in (reading position 0).
    pub initial: Vec<u32>,
    /// Successors of each state.
    pub succ: Vec<Vec<u32>>,
    /// Acceptance sets: `accepting[k][q]` is true when `q` is in set `k`. A run is accepted
    /// when it visits every set infinitely often.
    pub accepting: Vec<Vec<bool>>,
}

/// Why a translation failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TranslateError {
    /// More than 64 distinct atoms.
    TooManyAtoms,
    /// More than [`MAX_NODES`] tableau nodes.
    TooLarge,
}

struct Node {
    incoming: BTreeSet<u32>,
    new: Vec<u32>,
    old: BTreeSet<u32>,
    next: BTreeSet<u32>,
}

/// Marks the virtual initial node in `incoming`.
const INIT: u32 = u32::MAX;

/// The automaton of `f`; `atoms` lists the atoms, each numbered by its position (new atoms
/// are appended).
pub fn translate(f: &Ltl, atoms: &mut Vec<ExprId>) -> Result<Buchi, TranslateError> {
    let mut ar = Arena::default();
    let mut too_many = false;
    let root = ar.nnf(
        f,
        false,
        &mut |e| match atoms.iter().position(|&a| a == e) {
            Some(i) => i as u32,
            None => {
                atoms.push(e);
                if atoms.len() > 64 {
                    too_many = true;
                }
                (atoms.len() - 1) as u32
            }
        },
    );
    if too_many {
        return Err(TranslateError::TooManyAtoms);
    }
    let mut done: Vec<Node> = Vec::new();
    let mut index: HashMap<(BTreeSet<u32>, BTreeSet<u32>), usize> = HashMap::new();
    let mut stack = vec![Node {
        incoming: BTreeSet::from([INIT]),
        new: vec![root],
        old: BTreeSet::new(),
        next: BTreeSet::new(),
    }];
    let mut work = 0usize;
    while let Some(mut node) = stack.pop() {
        work += 1;
        if work > MAX_NODES * 16 || done.len() > MAX_NODES {
            return Err(TranslateError::TooLarge);
        }
        let Some(eta) = node.new.pop() else {
            let key = (node.old.clone(), node.next.clone());
            if let Some(&i) = index.get(&key) {
                done[i].incoming.extend(node.incoming);
                continue;
            }
            let id = done.len();
            index.insert(key, id);
            stack.push(Node {
                incoming: BTreeSet::from([id as u32]),
                new: node.next.iter().copied().collect(),
                old: BTreeSet::new(),
                next: BTreeSet::new(),
            });
            done.push(node);
            continue;
        };
        if node.old.contains(&eta) {
            stack.push(node);
            continue;
        }
        match ar.nodes[eta as usize] {
            N::False => {}
            N::True => {
                node.old.insert(eta);
                stack.push(node);
            }
            N::Lit(a, p) => {
                let contra = ar
                    .ids
                    .get(&N::Lit(a, !p))
                    .is_some_and(|c| node.old.contains(c));
                if !contra {
                    node.old.insert(eta);
                    stack.push(node);
                }
            }
            N::And(a, b) => {
                node.old.insert(eta);
                node.new.push(a);
                node.new.push(b);
                stack.push(node);
            }
            N::Next(a) => {
                node.old.insert(eta);
                node.next.insert(a);
                stack.push(node);
            }
            N::Or(a, b) | N::U(a, b) | N::R(a, b) => {
                node.old.insert(eta);
                let mut n2 = Node {
                    incoming: node.incoming.clone(),
                    new: node.new.clone(),
                    old: node.old.clone(),
                    next: node.next.clone(),
                };
                match ar.nodes[eta as usize] {
                    N::Or(..) => {
                        node.new.push(a);
                        n2.new.push(b);
                    }
                    N::U(..) => {
                        node.new.push(a);
                        node.next.insert(eta);
                        n2.new.push(b);
                    }
                    _ => {
                        node.new.push(b);
                        node.next.insert(eta);
                        n2.new.push(a);
                        n2.new.push(b);
                    }
                }
                stack.push(n2);
                stack.push(node);
            }
        }
    }
    let n = done.len();
    let mut states = Vec::with_capacity(n);
    let mut succ = vec![Vec::new(); n];
    let mut initial = Vec::new();
    for (q, node) in done.iter().enumerate() {
        let (mut pos, mut neg) = (0u64, 0u64);
        for &o in &node.old {
            if let N::Lit(a, p) = ar.nodes[o as usize] {
                if p {
                    pos |= 1 << a;
                } else {
                    neg |= 1 << a;
                }
            }
        }
        states.push(State { pos, neg });
        for &p in &node.incoming {
            if p == INIT {
                initial.push(q as u32);
            } else {
                succ[p as usize].push(q as u32);
            }
        }
    }
    let untils: Vec<(u32, u32)> = (0..ar.nodes.len() as u32)
        .filter_map(|i| match ar.nodes[i as usize] {
            N::U(_, b) => Some((i, b)),
            _ => None,
        })
        .collect();
    let accepting = untils
        .iter()
        .map(|&(u, b)| {
            done.iter()
                .map(|node| !node.old.contains(&u) || node.old.contains(&b))
                .collect()
        })
        .collect();
    for s in &mut succ {
        s.sort_unstable();
        s.dedup();
    }
    Ok(Buchi {
        states,
        initial,
        succ,
        accepting,
    })
}
