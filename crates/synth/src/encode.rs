//! Binary encoding of location vectors as BDD variables, and readable guards from BDDs.
//!
//! Each automaton's location is a group of bits (most significant first in the variable
//! order), the groups in instance order or in a given order ([`Encoding::with_order`]). Both engines express their results in this
//! encoding so that guard simplification is shared.

use crate::limits::Budget;
use crate::problem::Problem;
use crate::Error;
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
    /// The encoding of `p`'s automata, in instance order.
    pub fn new(p: &Problem) -> Encoding {
        let id: Vec<usize> = (0..p.automata.len()).collect();
        Encoding::with_order(p, &id)
    }

    /// The encoding with the automata's bit groups placed in `order` (a permutation of the
    /// automata, e.g. [`crate::order::force`]); each automaton's bits stay together.
    pub fn with_order(p: &Problem, order: &[usize]) -> Encoding {
        let widths: Vec<usize> = p
            .automata
            .iter()
            .map(|a| (usize::BITS - (a.locs.len().max(2) - 1).leading_zeros()) as usize)
            .collect();
        let total: usize = widths.iter().sum();
        let vars = BddVariableSet::new_anonymous(total as u16);
        let all = vars.variables();
        let mut bits = vec![Vec::new(); widths.len()];
        let mut at = 0;
        for &a in order {
            let w = widths[a];
            bits[a] = all[at..at + w].to_vec();
            at += w;
        }
        Encoding {
            vars,
            bits,
            sizes: p.automata.iter().map(|a| a.locs.len() as u32).collect(),
        }
    }

    /// Number of 64-bit words of a minterm ([`Encoding::minterm`]).
    pub fn minterm_words(&self) -> usize {
        (self.vars.num_vars() as usize).div_ceil(64).max(1)
    }

    /// Append the minterm of `locs` (for [`crate::build::from_minterms`]) to `out`.
    pub fn minterm(&self, locs: &[u32], out: &mut Vec<u64>) {
        let at = out.len();
        out.resize(at + self.minterm_words(), 0);
        for (a, &l) in locs.iter().enumerate() {
            let w = self.bits[a].len();
            for (i, v) in self.bits[a].iter().enumerate() {
                crate::build::set_bit(&mut out[at..], v.to_index(), (l >> (w - 1 - i)) & 1 == 1);
            }
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
        let none = Budget::new(&crate::Limits::default());
        // No limit can be hit without limits.
        self.simplify_until(on, off, &none, 0.0)
            .unwrap_or_else(|_| self.dnf_paths(on))
    }

    /// [`Encoding::simplify`] under `budget`: `Err` (phase `guards`, with `states` as the
    /// figure reached) as soon as a limit is hit, also inside the optimised DNF.
    pub fn simplify_until(
        &self,
        on: &Bdd,
        off: &Bdd,
        budget: &Budget,
        states: f64,
    ) -> Result<Formula, Error> {
        let check = || budget.check("guards", states, 0);
        let pos = self.eliminate(on, off, &check)?;
        let neg = self.eliminate(off, on, &check)?;
        let p = self.dnf(&pos, &check)?;
        let n = self.dnf(&neg, &check)?;
        Ok(if n.size() < p.size() {
            Formula { negated: true, ..n }
        } else {
            p
        })
    }

    fn eliminate(
        &self,
        on: &Bdd,
        off: &Bdd,
        check: &dyn Fn() -> Result<(), Error>,
    ) -> Result<Bdd, Error> {
        let mut g = on.clone();
        for bits in &self.bits {
            check()?;
            let cand = g.exists(bits);
            if cand.and(off).is_false() {
                g = cand;
            }
        }
        Ok(g)
    }

    /// The BDD's paths as clauses; past [`SMALL_DNF`] paths, the library's optimised DNF
    /// (prime-implicant style merging of cubes) instead, which is much shorter on large guards.
    /// `check` is polled between steps (and every [`POLL`] paths).
    fn dnf(&self, g: &Bdd, check: &dyn Fn() -> Result<(), Error>) -> Result<Formula, Error> {
        let mut paths: Vec<BddPartialValuation> = g.sat_clauses().take(SMALL_DNF + 1).collect();
        if paths.len() > SMALL_DNF {
            check()?;
            let opt = g._to_optimized_dnf(true, &|_: &[BddPartialValuation]| check())?;
            // The BDD's paths only when there are fewer of them (counted no further).
            let mut fewer = Vec::new();
            for (i, path) in g.sat_clauses().enumerate() {
                if i >= opt.len() {
                    fewer.clear();
                    break;
                }
                if i % POLL == 0 {
                    check()?;
                }
                fewer.push(path);
            }
            paths = if fewer.is_empty() { opt } else { fewer };
        }
        Ok(self.clauses(paths))
    }

    /// Every path of `g` as a clause (no simplification; no limit).
    fn dnf_paths(&self, g: &Bdd) -> Formula {
        self.clauses(g.sat_clauses().collect())
    }

    fn clauses(&self, paths: Vec<BddPartialValuation>) -> Formula {
        let mut clauses = Vec::new();
        for path in paths {
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

/// How many paths of a BDD are enumerated between two polls of the budget.
const POLL: usize = 1024;

/// Guards with at most this many BDD paths are printed path by path (short guards keep their
/// familiar form); longer ones go through [`Bdd::to_optimized_dnf`].
pub const SMALL_DNF: usize = 64;

/// Chains of at most this many operands are written flat (`a || b || c`); longer ones as a
/// balanced tree of parenthesised halves, so the parser's height limit (E0013) is never
/// reached: a chain of `n` operands is then about `2·log2(n)` levels deep.
pub const FLAT_CHAIN: usize = 64;

/// `parts` joined by `op` (`" || "`, `" && "`): flat when short, balanced when long.
pub fn chain(parts: &[String], op: &str) -> String {
    if parts.len() <= FLAT_CHAIN {
        return parts.join(op);
    }
    // Iterative pairing, level by level: no recursion on the input's size.
    let mut level: Vec<String> = parts.chunks(FLAT_CHAIN / 2).map(|c| c.join(op)).collect();
    while level.len() > 1 {
        level = level
            .chunks(2)
            .map(|c| match c {
                [a, b] => format!("({a}){op}({b})"),
                [a] => a.clone(),
                _ => String::new(),
            })
            .collect();
    }
    level.pop().unwrap_or_default()
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
                    chain(&atoms, " && ")
                })
                .collect();
            if cs.len() == 1 {
                cs[0].clone()
            } else {
                let cs: Vec<String> = cs
                    .iter()
                    .map(|c| {
                        if c.contains("&&") {
                            format!("({c})")
                        } else {
                            c.clone()
                        }
                    })
                    .collect();
                chain(&cs, " || ")
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
            _ => format!("({})", chain(&parts, " || ")),
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
        chain(&parts, " && ")
    }
}

#[cfg(test)]
mod tests {
    use super::chain;

    #[test]
    fn long_chains_are_balanced() {
        let parts: Vec<String> = (0..10_000).map(|i| format!("x{i}")).collect();
        let text = chain(&parts, " || ");
        // Every operand once, in order.
        let back: Vec<&str> = text
            .split(" || ")
            .map(|s| s.trim_matches(|c| c == '(' || c == ')'))
            .collect();
        assert_eq!(back.len(), 10_000);
        assert!(back.iter().zip(&parts).all(|(a, b)| a == b));
        // Parenthesis depth: 10 000 / 32 = 313 groups, paired 9 times.
        let (mut depth, mut max) = (0i32, 0i32);
        for c in text.chars() {
            match c {
                '(' => depth += 1,
                ')' => depth -= 1,
                _ => {}
            }
            max = max.max(depth);
        }
        assert_eq!(depth, 0);
        assert_eq!(max, 9);
        assert_eq!(chain(&parts[..3], " && "), "x0 && x1 && x2");
    }
}
