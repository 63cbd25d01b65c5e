//! Binary encoding of location vectors as BDD variables, and readable guards from BDDs.
//!
//! Each automaton's location is a little-endian group of bits (most significant first in the
//! variable order), the groups in instance order. Both engines express their results in this
//! encoding so that guard simplification is shared.

use crate::problem::Problem;
use biodivine_lib_bdd::{Bdd, BddPartialValuation, BddValuation, BddVariable, BddVariableSet};

/// The BDD variables of a problem's location vectors.
pub struct Encoding {
    /// The variable set.
    pub vars: BddVariableSet,
    /// Bits of each automaton, most significant first.
    pub bits: Vec<Vec<BddVariable>>,
    /// Number of locations of each automaton.
    pub sizes: Vec<u32>,
}

impl Encoding {
    /// The encoding of `p`'s automata.
    pub fn new(p: &Problem) -> Encoding {
        let widths: Vec<usize> = p
            .automata
            .iter()
            .map(|a| (usize::BITS - (a.locs.len().max(2) - 1).leading_zeros()) as usize)
            .collect();
        let total: usize = widths.iter().sum();
        let vars = BddVariableSet::new_anonymous(total as u16);
        let all = vars.variables();
        let mut bits = Vec::new();
        let mut at = 0;
        for w in widths {
            bits.push(all[at..at + w].to_vec());
            at += w;
        }
        Encoding {
            vars,
            bits,
            sizes: p.automata.iter().map(|a| a.locs.len() as u32).collect(),
        }
    }

    /// The assignment of automaton `a`'s bits for location `l`.
    pub fn assign(&self, a: usize, l: u32) -> Vec<(BddVariable, bool)> {
        let w = self.bits[a].len();
        self.bits[a]
            .iter()
            .enumerate()
            .map(|(i, v)| (*v, (l >> (w - 1 - i)) & 1 == 1))
            .collect()
    }

    /// `loc(a) == l`.
    pub fn loc_eq(&self, a: usize, l: u32) -> Bdd {
        self.vars
            .mk_conjunctive_clause(&BddPartialValuation::from_values(&self.assign(a, l)))
    }

    /// Every automaton's bits encode one of its locations.
    pub fn valid(&self) -> Bdd {
        let mut v = self.vars.mk_true();
        for a in 0..self.bits.len() {
            let mut any = self.vars.mk_false();
            for l in 0..self.sizes[a] {
                any = any.or(&self.loc_eq(a, l));
            }
            v = v.and(&any);
        }
        v
    }

    /// The single state `locs`.
    pub fn state(&self, locs: &[u32]) -> Bdd {
        let vals: Vec<(BddVariable, bool)> = locs
            .iter()
            .enumerate()
            .flat_map(|(a, &l)| self.assign(a, l))
            .collect();
        self.vars
            .mk_conjunctive_clause(&BddPartialValuation::from_values(&vals))
    }

    /// A set of states (a disjunction of minterms; for the explicit engine's results).
    pub fn set<'a>(&self, states: impl Iterator<Item = &'a [u32]>) -> Bdd {
        let clauses: Vec<BddPartialValuation> = states
            .map(|locs| {
                let vals: Vec<(BddVariable, bool)> = locs
                    .iter()
                    .enumerate()
                    .flat_map(|(a, &l)| self.assign(a, l))
                    .collect();
                BddPartialValuation::from_values(&vals)
            })
            .collect();
        self.vars.mk_dnf(&clauses)
    }

    /// Is `locs` in `set`?
    pub fn contains(&self, set: &Bdd, locs: &[u32]) -> bool {
        let mut val = BddValuation::all_false(self.vars.num_vars());
        for (a, &l) in locs.iter().enumerate() {
            for (v, b) in self.assign(a, l) {
                val.set_value(v, b);
            }
        }
        set.eval_in(&val)
    }

    /// A simplified predicate that is true on `on` and false on `off` (both within the care
    /// set `on ∪ off`): automata whose locations do not matter are quantified away greedily,
    /// then the shorter of the predicate and its negation's DNF is kept.
    pub fn simplify(&self, on: &Bdd, off: &Bdd) -> Formula {
        let pos = self.eliminate(on, off);
        let neg = self.eliminate(off, on);
        let p = self.dnf(&pos);
        let n = self.dnf(&neg);
        if n.size() < p.size() {
            Formula { negated: true, ..n }
        } else {
            p
        }
    }

    fn eliminate(&self, on: &Bdd, off: &Bdd) -> Bdd {
        let mut g = on.clone();
        for bits in &self.bits {
            let cand = g.exists(bits);
            if cand.and(off).is_false() {
                g = cand;
            }
        }
        g
    }

    fn dnf(&self, g: &Bdd) -> Formula {
        let mut clauses = Vec::new();
        for path in g.sat_clauses() {
            let mut clause = Vec::new();
            for (a, bits) in self.bits.iter().enumerate() {
                if bits.iter().all(|v| path.get_value(*v).is_none()) {
                    continue;
                }
                let locs: Vec<u32> = (0..self.sizes[a])
                    .filter(|&l| {
                        self.assign(a, l)
                            .iter()
                            .all(|(v, b)| path.get_value(*v).is_none_or(|x| x == *b))
                    })
                    .collect();
                if locs.len() as u32 != self.sizes[a] {
                    clause.push(Atom {
                        aut: a as u32,
                        locs,
                    });
                }
            }
            clauses.push(clause);
        }
        Formula {
            negated: false,
            clauses,
        }
    }
}

/// `aut` is in one of `locs`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Atom {
    /// The automaton.
    pub aut: u32,
    /// Its allowed locations (a proper, possibly empty, subset).
    pub locs: Vec<u32>,
}

/// A guard in disjunctive normal form over location atoms, possibly negated as a whole.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Formula {
    /// `!( … )` around the DNF.
    pub negated: bool,
    /// Disjunction of conjunctions; no clauses is `false`, an empty clause is `true`.
    pub clauses: Vec<Vec<Atom>>,
}

impl Formula {
    /// Number of atoms (a size measure).
    pub fn size(&self) -> usize {
        self.clauses.iter().map(|c| c.len().max(1)).sum()
    }

    /// Evaluate on a location vector.
    pub fn eval(&self, locs: &[u32]) -> bool {
        let v = self
            .clauses
            .iter()
            .any(|c| c.iter().all(|a| a.locs.contains(&locs[a.aut as usize])));
        v != self.negated
    }

    /// Render with `at(aut, loc)` as the text of "automaton `aut` is at `loc`"; `sizes` are
    /// the automata's location counts (to write the shorter of a set and its complement).
    pub fn render(&self, sizes: &[u32], at: &dyn Fn(u32, u32) -> String) -> String {
        let dnf = if self.clauses.is_empty() {
            "false".to_string()
        } else if self.clauses.iter().any(|c| c.is_empty()) {
            "true".to_string()
        } else {
            let cs: Vec<String> = self
                .clauses
                .iter()
                .map(|c| {
                    let atoms: Vec<String> = c.iter().map(|a| atom(a, sizes, at)).collect();
                    atoms.join(" && ")
                })
                .collect();
            if cs.len() == 1 {
                cs[0].clone()
            } else {
                cs.iter()
                    .map(|c| {
                        if c.contains("&&") {
                            format!("({c})")
                        } else {
                            c.clone()
                        }
                    })
                    .collect::<Vec<_>>()
                    .join(" || ")
            }
        };
        match (self.negated, dnf.as_str()) {
            (false, _) => dnf,
            (true, "true") => "false".into(),
            (true, "false") => "true".into(),
            (true, _) => format!("!({dnf})"),
        }
    }
}

fn atom(a: &Atom, sizes: &[u32], at: &dyn Fn(u32, u32) -> String) -> String {
    let n = sizes[a.aut as usize];
    let complement: Vec<u32> = (0..n).filter(|l| !a.locs.contains(l)).collect();
    if a.locs.len() <= complement.len() {
        let parts: Vec<String> = a.locs.iter().map(|&l| at(a.aut, l)).collect();
        match parts.len() {
            0 => "false".into(),
            1 => parts[0].clone(),
            _ => format!("({})", parts.join(" || ")),
        }
    } else {
        let parts: Vec<String> = complement
            .iter()
            .map(|&l| {
                let t = at(a.aut, l);
                match t.split_once(" == ") {
                    Some((x, y)) => format!("{x} != {y}"),
                    None => format!("!{t}"),
                }
            })
            .collect();
        parts.join(" && ")
    }
}
