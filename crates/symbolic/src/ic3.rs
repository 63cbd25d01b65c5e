//! IC3 / property-directed reachability.
//!
//! Frames `F_0 = Init ⊆ F_1 ⊆ … ⊆ F_k` over-approximate the states reachable in at most `i`
//! steps; each is a set of clauses (negated cubes of latch values), stored once at the highest
//! level it holds ("delta" encoding) and in one incremental solver per level. Bad states of the
//! frontier are blocked recursively through proof obligations; a blocked cube is generalized by
//! the solver's failed assumptions and then by dropping literals one at a time (MIC without
//! counterexamples to generalization) while it stays inductive relative to its frame and keeps
//! excluding the initial states. Clauses are pushed forward after each frontier; when a frame
//! becomes empty, the clauses above it are an inductive invariant that excludes the bad states.
//!
//! Only latches in the cone of influence of the bad output and the constraints appear in cubes.

use crate::aig::{Aig, Lit};
use crate::engine::{Invariant, Limits, Outcome};
use crate::sat::{Solver, Start, Unroller};
use rustsat::types::Lit as SLit;
use std::collections::BinaryHeap;

/// A cube: latch values, sorted by latch index.
type Cube = Vec<(usize, bool)>;

/// Latches in the cone of influence of the bad outputs and constraints.
pub fn coi_latches(aig: &Aig) -> Vec<usize> {
    let seen = aig.cone();
    (0..aig.latches.len())
        .filter(|&i| seen[aig.latches[i].var as usize])
        .collect()
}

struct Frame<'a> {
    s: Solver,
    u: Unroller<'a>,
}

struct Ic3<'a> {
    aig: &'a Aig,
    bad: Lit,
    coi: Vec<usize>,
    /// `frames[i]`: cubes blocked exactly up to level `i`.
    frames: Vec<Vec<Cube>>,
    solvers: Vec<Frame<'a>>,
    limits: &'a Limits,
    /// The predecessor found by the last satisfiable [`Ic3::relative`] query.
    pred: Cube,
}

#[derive(PartialEq, Eq, PartialOrd, Ord)]
struct Obligation {
    /// Negated level, so that the max-heap pops the lowest level first.
    neg_level: i64,
    cube: Cube,
}

enum Block {
    Blocked,
    Cex,
    Stopped(String),
}

/// Decide `aig.bad[0]` with IC3; a proof comes with the inductive invariant.
pub fn ic3(aig: &Aig, limits: &Limits) -> Outcome {
    let Some(&bad) = aig.bad.first() else {
        return Outcome::Proved(Some(Vec::new()));
    };
    let mut m = Ic3 {
        aig,
        bad,
        coi: coi_latches(aig),
        frames: Vec::new(),
        solvers: Vec::new(),
        limits,
        pred: Vec::new(),
    };
    match m.run() {
        Ok(Some(inv)) => Outcome::Proved(Some(inv)),
        Ok(None) => match crate::bmc::bmc(aig, limits) {
            // A counterexample exists: find a shortest one.
            Outcome::Bounded(_) => Outcome::Unknown("counterexample not rebuilt".into()),
            o => o,
        },
        Err(why) => Outcome::Unknown(why),
    }
}

impl<'a> Ic3<'a> {
    fn new_frame(&mut self) {
        let level = self.solvers.len();
        let mut s = Solver::new();
        let mut u = Unroller::new(self.aig, Start::Free);
        for &c in &self.aig.constraints {
            let x = u.lit(&mut s, c, 0);
            s.add(&[x]);
        }
        if level == 0 {
            for &j in &self.coi {
                let l = &self.aig.latches[j];
                if let Some(b) = l.init {
                    let x = u.lit(&mut s, Lit::var_lit(l.var), 0);
                    s.add(&[if b { x } else { !x }]);
                }
            }
        }
        self.solvers.push(Frame { s, u });
        self.frames.push(Vec::new());
    }

    fn cur(&mut self, level: usize, j: usize, v: bool) -> SLit {
        let f = &mut self.solvers[level];
        let x = f.u.lit(&mut f.s, Lit::var_lit(self.aig.latches[j].var), 0);
        if v {
            x
        } else {
            !x
        }
    }

    fn next(&mut self, level: usize, j: usize, v: bool) -> SLit {
        let f = &mut self.solvers[level];
        let x = f.u.lit(&mut f.s, self.aig.latches[j].next, 0);
        if v {
            x
        } else {
            !x
        }
    }

    fn add_clause(&mut self, level: usize, cube: &Cube) {
        let cl: Vec<SLit> = cube.iter().map(|&(j, v)| self.cur(level, j, !v)).collect();
        self.solvers[level].s.add(&cl);
    }

    fn intersects_init(&self, cube: &Cube) -> bool {
        cube.iter()
            .all(|&(j, v)| self.aig.latches[j].init.is_none_or(|b| b == v))
    }

    fn model_cube(&mut self, level: usize) -> Cube {
        let coi = self.coi.clone();
        coi.into_iter()
            .map(|j| {
                let x = self.cur(level, j, true);
                (j, self.solvers[level].s.value(x))
            })
            .collect()
    }

    fn solve(&mut self, level: usize, assumps: &[SLit]) -> Result<bool, String> {
        if let Some(why) = self.limits.expired() {
            return Err(why);
        }
        self.solvers[level]
            .s
            .solve(assumps)
            .ok_or_else(|| "the SAT solver failed".to_string())
    }

    /// Is `¬cube` inductive relative to `F_level`? On success, the literals of `cube` the
    /// answer depends on (a sub-cube); on failure the solver holds a predecessor.
    fn relative(&mut self, level: usize, cube: &Cube) -> Result<Option<Cube>, String> {
        let act = self.solvers[level].s.fresh();
        let mut cl: Vec<SLit> = vec![!act];
        for &(j, v) in cube {
            cl.push(self.cur(level, j, !v));
        }
        self.solvers[level].s.add(&cl);
        let mut assumps = vec![act];
        let mut map = Vec::with_capacity(cube.len());
        for &(j, v) in cube {
            let x = self.next(level, j, v);
            assumps.push(x);
            map.push((x, (j, v)));
        }
        let sat = self.solve(level, &assumps)?;
        let res = if sat {
            // Read the predecessor before the solver changes state.
            self.pred = self.model_cube(level);
            None
        } else {
            let failed = self.solvers[level].s.failed();
            Some(
                map.iter()
                    .filter(|(x, _)| failed.contains(x))
                    .map(|(_, l)| *l)
                    .collect(),
            )
        };
        self.solvers[level].s.add(&[!act]);
        Ok(res)
    }

    /// Make `sub` (a sub-cube of `full`) exclude the initial states again by adding back a
    /// literal of `full` that contradicts them.
    fn fix_init(&self, mut sub: Cube, full: &Cube) -> Cube {
        if self.intersects_init(&sub) {
            if let Some(l) = full
                .iter()
                .find(|&&(j, v)| self.aig.latches[j].init == Some(!v))
            {
                sub.push(*l);
                sub.sort_unstable();
            }
        }
        sub
    }

    fn generalize(&mut self, level: usize, cube: Cube, core: Cube) -> Result<Cube, String> {
        let mut g = self.fix_init(core, &cube);
        let mut i = 0;
        while i < g.len() {
            let mut t = g.clone();
            t.remove(i);
            if t.is_empty() || self.intersects_init(&t) {
                i += 1;
                continue;
            }
            match self.relative(level, &t)? {
                Some(c) => {
                    let c = self.fix_init(c, &t);
                    // Keep the position: the literals before `i` were already tried.
                    let before = g[..i].iter().filter(|l| c.contains(l)).count();
                    g = c;
                    i = before;
                }
                None => i += 1,
            }
        }
        Ok(g)
    }

    fn block(&mut self, cube: Cube, level: usize) -> Result<Block, String> {
        let mut q = BinaryHeap::new();
        q.push(Obligation {
            neg_level: -(level as i64),
            cube,
        });
        while let Some(ob) = q.pop() {
            let l = (-ob.neg_level) as usize;
            if self.intersects_init(&ob.cube) {
                return Ok(Block::Cex);
            }
            if l == 0 {
                return Ok(Block::Cex);
            }
            if let Some(why) = self.limits.expired() {
                return Ok(Block::Stopped(why));
            }
            match self.relative(l - 1, &ob.cube)? {
                None => {
                    let pred = std::mem::take(&mut self.pred);
                    q.push(Obligation {
                        neg_level: -((l - 1) as i64),
                        cube: pred,
                    });
                    q.push(ob);
                }
                Some(core) => {
                    let g = self.generalize(l - 1, ob.cube.clone(), core)?;
                    // Push the clause as far as it stays relatively inductive.
                    let mut at = l;
                    let top = self.frames.len() - 1;
                    while at < top && self.relative(at, &g)?.is_some() {
                        at += 1;
                    }
                    for lv in 1..=at {
                        self.add_clause(lv, &g);
                    }
                    self.frames[at].push(g);
                }
            }
        }
        Ok(Block::Blocked)
    }

    /// `Some(invariant)` on a proof, `None` when a counterexample exists.
    fn run(&mut self) -> Result<Option<Invariant>, String> {
        self.new_frame();
        // A bad transition from an initial state.
        let b = {
            let f = &mut self.solvers[0];
            f.u.lit(&mut f.s, self.bad, 0)
        };
        if self.solve(0, &[b])? {
            return Ok(None);
        }
        self.new_frame();
        loop {
            let k = self.frames.len() - 1;
            if self.limits.max_depth.is_some_and(|d| k > d) {
                return Err(format!("depth bound {k} reached"));
            }
            loop {
                let b = {
                    let f = &mut self.solvers[k];
                    f.u.lit(&mut f.s, self.bad, 0)
                };
                if !self.solve(k, &[b])? {
                    break;
                }
                let cube = self.model_cube(k);
                match self.block(cube, k)? {
                    Block::Blocked => {}
                    Block::Cex => return Ok(None),
                    Block::Stopped(why) => return Err(why),
                }
            }
            self.new_frame();
            let top = self.frames.len() - 1;
            for i in 1..top {
                let cubes = std::mem::take(&mut self.frames[i]);
                let mut stay = Vec::new();
                for c in cubes {
                    if self.relative(i, &c)?.is_some() {
                        self.add_clause(i + 1, &c);
                        self.frames[i + 1].push(c);
                    } else {
                        stay.push(c);
                    }
                }
                self.frames[i] = stay;
                if self.frames[i].is_empty() {
                    let inv = self.frames[i + 1..]
                        .iter()
                        .flatten()
                        .map(|c| c.iter().map(|&(j, v)| (j, !v)).collect())
                        .collect();
                    return Ok(Some(inv));
                }
            }
        }
    }
}
