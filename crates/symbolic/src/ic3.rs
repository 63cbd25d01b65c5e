//! IC3 / property-directed reachability.
//!
//! Frames `F_0 = Init ⊆ F_1 ⊆ … ⊆ F_k` over-approximate the states reachable in at most `i`
//! steps; each is a set of clauses (negated cubes of latch values), stored once at the highest
//! level it holds ("delta" encoding) and in one incremental solver per level. Bad states of the
//! frontier are blocked recursively through proof obligations; an obligation already excluded
//! by a stored clause (syntactic containment) is skipped. Predecessors are lifted to sub-cubes
//! by ternary simulation ([`crate::ternary`]). A blocked cube is generalized by the solver's
//! failed assumptions and then by dropping literals one at a time (MIC), those of latches that
//! occur least in earlier clauses first (ABC's flop priorities), one query per try (no joins
//! with the predecessors that refute it, and no counterexamples to generalization: on the FAM
//! circuits both cost more than they saved). Clauses are pushed forward after
//! each frontier, shrunk to the solver's core when they move, and clauses a new one subsumes
//! are dropped; when a frame becomes empty, the clauses above it are an inductive invariant
//! that excludes the bad states.
//!
//! Only latches in the cone of influence of the bad output and the constraints appear in cubes.

use crate::aig::{Aig, Lit};
use crate::engine::{Invariant, Limits, Outcome};
use crate::sat::{SLit, Solver, Start, Unroller};
use crate::ternary::Ternary;
use std::collections::{BinaryHeap, HashSet};

/// A cube: latch values, sorted by latch index.
type Cube = Vec<(usize, bool)>;

/// Latches in the cone of influence of the bad outputs and constraints.
pub fn coi_latches(aig: &Aig) -> Vec<usize> {
    let seen = aig.cone();
    (0..aig.latches.len())
        .filter(|&i| seen[aig.latches[i].var as usize])
        .collect()
}

/// Is the sorted cube `a` a subset of the sorted cube `b`?
fn subset(a: &Cube, b: &Cube) -> bool {
    if a.len() > b.len() {
        return false;
    }
    let mut it = b.iter();
    a.iter().all(|x| it.by_ref().any(|y| y == x))
}

/// Dead activation literals after which a solver is rebuilt from its clauses: their satisfied
/// clauses stay in the watch lists and slow every later propagation (ABC recycles likewise).
const RECYCLE: usize = 400;

struct Frame<'a> {
    s: Solver,
    u: Unroller<'a>,
    /// Activation literals used and disabled since the solver was built.
    dead: usize,
}

impl<'a> Frame<'a> {
    /// The transition relation over free current states, constraints not yet added.
    fn new(aig: &'a Aig) -> Frame<'a> {
        Frame {
            s: Solver::plain(),
            u: Unroller::new(aig, Start::Free),
            dead: 0,
        }
    }
}

/// What one IC3 run did, for benchmarks and tuning.
#[derive(Clone, Copy, Debug, Default)]
pub struct Ic3Stats {
    /// Frames opened.
    pub frames: usize,
    /// Relative-induction queries (blocking, generalization, pushing).
    pub queries: usize,
    /// Of those, satisfiable ones.
    pub sat_answers: usize,
    /// Predecessors lifted.
    pub lifts: usize,
    /// Proof obligations popped.
    pub obligations: usize,
    /// Obligations skipped because a stored clause already excluded them.
    pub contained: usize,
    /// Clauses learned by blocking.
    pub clauses: usize,
    /// Clause push attempts, and successful ones.
    pub pushes: (usize, usize),
}

struct Ic3<'a> {
    st: Ic3Stats,
    /// Clauses known to hold in every reachable state (given by the caller), in every frame.
    lemmas: Invariant,
    aig: &'a Aig,
    bad: Lit,
    coi: Vec<usize>,
    /// `frames[i]`: cubes blocked exactly up to level `i`.
    frames: Vec<Vec<Cube>>,
    solvers: Vec<Frame<'a>>,
    limits: &'a Limits,
    /// The predecessor found by the last satisfiable [`Ic3::relative`] query (lifted).
    pred: Cube,
    /// The transition relation alone, for lifting predecessors to sub-cubes.
    lifter: Frame<'a>,
    /// How many learned clauses mention each latch: generalization drops the literals of rare
    /// latches first.
    prio: Vec<u32>,
    /// Ternary simulation, for lifting predecessors.
    ternary: Ternary<'a>,
}

#[derive(PartialEq, Eq, PartialOrd, Ord)]
struct Obligation {
    /// Negated level, so that the max-heap pops the lowest level first.
    neg_level: i64,
    cube: Cube,
}

/// Whether a satisfiable [`Ic3::relative`] query must leave its predecessor in `Ic3::pred`.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Pred {
    /// No: the caller only needs the answer (pushing clauses, trying a generalization), so
    /// the lifting is saved.
    Unused,
    /// Yes, lifted to a sub-cube (proof obligations).
    Lifted,
}

enum Block {
    Blocked,
    Cex,
    Stopped(String),
}

/// Decide `aig.bad[0]` with IC3; a proof comes with the inductive invariant.
pub fn ic3(aig: &Aig, limits: &Limits) -> Outcome {
    ic3_with_stats(aig, limits).0
}

/// [`ic3`], given `lemmas`: clauses over `aig`'s latches that hold in every reachable state
/// and together are inductive (the invariants of other properties of the same circuit, under
/// the same constraints). Every frame starts with them, on the current and the next state, so
/// a proof need not rediscover them; the invariant of a proof includes them.
pub fn ic3_with_lemmas(aig: &Aig, limits: &Limits, lemmas: &Invariant) -> Outcome {
    run_ic3(aig, limits, lemmas, &mut Ic3Frames::default()).0
}

/// [`ic3_with_lemmas`], resumed from the frames `saved` that an earlier attempt on the same
/// circuit left when a limit stopped it (empty: from the start), and leaving its own there
/// when a limit stops it in turn (cleared when it decides). Sound because every clause of a
/// frame `F_i` holds in every state reachable within `i` steps, whatever the attempt that
/// learned it, and `lemmas` only add facts of every reachable state.
pub fn ic3_resume(
    aig: &Aig,
    limits: &Limits,
    lemmas: &Invariant,
    saved: &mut Ic3Frames,
) -> Outcome {
    run_ic3(aig, limits, lemmas, saved).0
}

/// [`ic3`], with what the run did.
pub fn ic3_with_stats(aig: &Aig, limits: &Limits) -> (Outcome, Ic3Stats) {
    run_ic3(aig, limits, &Vec::new(), &mut Ic3Frames::default())
}

/// The frames of an IC3 attempt that a limit stopped, from which a later attempt on the same
/// circuit resumes ([`ic3_resume`]).
#[derive(Clone, Debug, Default)]
pub struct Ic3Frames {
    /// `frames[i]`: cubes blocked exactly up to level `i` (at least two levels, or none).
    frames: Vec<Vec<Cube>>,
    /// How many learned clauses mention each latch.
    prio: Vec<u32>,
    /// The number of latches of the circuit they are about.
    latches: usize,
}

impl Ic3Frames {
    /// How many frames were opened (0: none saved).
    pub fn depth(&self) -> usize {
        self.frames.len()
    }
}

fn run_ic3(
    aig: &Aig,
    limits: &Limits,
    lemmas: &Invariant,
    saved: &mut Ic3Frames,
) -> (Outcome, Ic3Stats) {
    let Some(&bad) = aig.bad.first() else {
        return (Outcome::Proved(Some(Vec::new())), Ic3Stats::default());
    };
    let n = aig.latches.len();
    let coi = coi_latches(aig);
    // Every lemma, on the current and the next state: only a union of whole invariants is
    // inductive, and its next-state copy makes the relative-induction queries stronger (on
    // the FAM closed loop, keeping only the lemmas over the cone of influence and only on the
    // current state made IC3's last attempt at `master_failure_sequence` take 6 to 36 s of
    // CPU from one run to the next, against about 6 s with all of them).
    // Every lemma, on the current and the next state: only a union of whole invariants is
    // inductive, and the next-state copy strengthens the relative-induction queries (keeping
    // only the lemmas over the cone of influence, on the current state only, made IC3's last
    // attempt at the FAM closed loop's `master_failure_sequence` take 6 to 36 s of CPU from
    // one run to the next, against about 6 s with all of them).
    let lemmas: Invariant = lemmas
        .iter()
        .filter(|c| !c.is_empty() && c.iter().all(|&(j, _)| j < n))
        .cloned()
        .collect();
    let resumed = saved.latches == n && saved.frames.len() >= 2 && saved.prio.len() == n;
    let (frames, prio) = if resumed {
        (
            std::mem::take(&mut saved.frames),
            std::mem::take(&mut saved.prio),
        )
    } else {
        (Vec::new(), vec![0; n])
    };
    let mut m = Ic3 {
        lemmas,
        st: Ic3Stats::default(),
        aig,
        bad,
        coi,
        frames,
        solvers: Vec::new(),
        limits,
        pred: Vec::new(),
        lifter: Frame::new(aig),
        prio,
        ternary: Ternary::new(aig),
    };
    let r = if resumed { m.resume() } else { m.run() };
    m.st.frames = m.frames.len();
    // The frontier is the last frame; every level below it has no bad state, so no trace of
    // at most that many frames reaches the bad output.
    let cleared = m.frames.len().saturating_sub(1);
    *saved = match &r {
        Err(_) if m.frames.len() >= 2 => Ic3Frames {
            frames: std::mem::take(&mut m.frames),
            prio: std::mem::take(&mut m.prio),
            latches: n,
        },
        _ => Ic3Frames::default(),
    };
    let outcome = match r {
        Ok(Some(inv)) => Outcome::Proved(Some(inv)),
        Ok(None) => match crate::bmc::bmc(aig, limits) {
            // A counterexample exists: find a shortest one.
            Outcome::Bounded(_) => Outcome::unknown_after("counterexample not rebuilt", cleared),
            o => o,
        },
        Err(why) => Outcome::unknown_after(why, cleared),
    };
    (outcome, m.st)
}

impl<'a> Ic3<'a> {
    fn new_frame(&mut self) {
        let level = self.solvers.len();
        self.frames.push(Vec::new());
        let f = self.build_solver(level);
        self.solvers.push(f);
    }

    /// A solver for `F_level`: the constraints, the initial states at level 0, the property
    /// below the frontier, and every clause stored at `level` or above.
    fn build_solver(&self, level: usize) -> Frame<'a> {
        let mut f = Frame::new(self.aig);
        for &c in &self.aig.constraints {
            let x = f.u.lit(&mut f.s, c, 0);
            f.s.add(&[x]);
        }
        for cl in &self.lemmas {
            let now: Vec<SLit> = cl
                .iter()
                .map(|&(j, v)| latch_lit(self.aig, &mut f, j, v, false))
                .collect();
            f.s.add(&now);
            let next: Vec<SLit> = cl
                .iter()
                .map(|&(j, v)| latch_lit(self.aig, &mut f, j, v, true))
                .collect();
            f.s.add(&next);
        }
        if level == 0 {
            for &j in &self.coi {
                let l = &self.aig.latches[j];
                if let Some(b) = l.init {
                    let x = f.u.lit(&mut f.s, Lit::var_lit(l.var), 0);
                    f.s.add(&[if b { x } else { !x }]);
                }
            }
        }
        if level + 1 < self.frames.len() {
            let nb = !f.u.lit(&mut f.s, self.bad, 0);
            f.s.add(&[nb]);
        }
        for cubes in &self.frames[level.max(1)..] {
            for cube in cubes {
                let cl: Vec<SLit> = cube
                    .iter()
                    .map(|&(j, v)| latch_lit(self.aig, &mut f, j, !v, false))
                    .collect();
                f.s.add(&cl);
            }
        }
        f
    }

    /// Rebuild `level`'s solver when too many disabled activation clauses slow it down.
    fn recycle(&mut self, level: usize) {
        if self.solvers[level].dead > RECYCLE {
            self.solvers[level] = self.build_solver(level);
        }
    }

    fn cur(&mut self, level: usize, j: usize, v: bool) -> SLit {
        latch_lit(self.aig, &mut self.solvers[level], j, v, false)
    }

    fn next(&mut self, level: usize, j: usize, v: bool) -> SLit {
        latch_lit(self.aig, &mut self.solvers[level], j, v, true)
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

    /// The input values of the last model of `level`'s solver.
    fn model_inputs(&mut self, level: usize) -> Vec<bool> {
        let f = &mut self.solvers[level];
        f.u.inputs(&mut f.s, 0)
    }

    /// Shrink the state `full` (stepping with inputs `ins` into `target`, or a bad state when
    /// `target` is `None`) to a sub-cube every state of which, with the same inputs, satisfies
    /// the constraints and steps into `target` (is bad), by ternary simulation.
    /// Sound for counterexamples: every state of the lifted cube has the transition.
    fn lift(&mut self, full: Cube, ins: &[bool], target: Option<&Cube>) -> Cube {
        let aig = self.aig;
        let mut required: Vec<Lit> = aig.constraints.clone();
        match target {
            Some(t) => required.extend(t.iter().map(|&(j, v)| aig.latches[j].next.xor(!v))),
            None => required.push(self.bad),
        }
        self.st.lifts += 1;
        match self.ternary.lift(&full, ins, &required) {
            Some(c) => c,
            // The solver's model does not give the required values: cannot happen when the
            // model is right; lift by SAT instead, which keeps the full state if it must.
            None => self.lift_by_sat(full, ins, target),
        }
    }

    /// [`Ic3::lift`] by a SAT query: the literals of `full` that the unsatisfiability of
    /// "constraints and target (bad) with these values" depends on.
    fn lift_by_sat(&mut self, full: Cube, ins: &[bool], target: Option<&Cube>) -> Cube {
        let aig = self.aig;
        if self.lifter.dead > RECYCLE {
            self.lifter = Frame::new(aig);
        }
        let f = &mut self.lifter;
        let act = f.s.fresh();
        f.dead += 1;
        let mut cl: Vec<SLit> = vec![!act];
        for &c in &aig.constraints {
            cl.push(!f.u.lit(&mut f.s, c, 0));
        }
        match target {
            Some(t) => {
                for &(j, v) in t {
                    let x = f.u.lit(&mut f.s, aig.latches[j].next, 0);
                    cl.push(if v { !x } else { x });
                }
            }
            None => cl.push(!f.u.lit(&mut f.s, self.bad, 0)),
        }
        f.s.add(&cl);
        let mut assumps = vec![act];
        for (k, &var) in aig.inputs.iter().enumerate() {
            let x = f.u.lit(&mut f.s, Lit::var_lit(var), 0);
            assumps.push(if ins.get(k).copied().unwrap_or(false) {
                x
            } else {
                !x
            });
        }
        let first_state = assumps.len();
        for &(j, v) in &full {
            let x = f.u.lit(&mut f.s, Lit::var_lit(aig.latches[j].var), 0);
            assumps.push(if v { x } else { !x });
        }
        let lifted = match f.s.solve(&assumps) {
            Some(false) => {
                let failed: HashSet<SLit> = f.s.failed().into_iter().collect();
                let keep: Vec<bool> = assumps[first_state..]
                    .iter()
                    .map(|x| failed.contains(x))
                    .collect();
                full.iter()
                    .zip(keep)
                    .filter(|(_, k)| *k)
                    .map(|(l, _)| *l)
                    .collect()
            }
            // Cannot happen when the model is right; the full state is always sound.
            _ => full,
        };
        f.s.add(&[!act]);
        lifted
    }

    fn solve(&mut self, level: usize, assumps: &[SLit]) -> Result<bool, String> {
        if let Some(why) = self.limits.expired() {
            return Err(why);
        }
        self.solvers[level]
            .s
            .solve(assumps)
            .ok_or_else(|| self.limits.why_interrupted())
    }

    /// Is `¬cube` inductive relative to `F_level`? On success, the literals of `cube` the
    /// answer depends on (a sub-cube); on failure, with `want`, the lifted predecessor is left
    /// in `self.pred`.
    fn relative(&mut self, level: usize, cube: &Cube, want: Pred) -> Result<Option<Cube>, String> {
        self.recycle(level);
        let act = self.solvers[level].s.fresh();
        self.solvers[level].dead += 1;
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
        self.st.queries += 1;
        let sat = match self.solve(level, &assumps) {
            Ok(sat) => {
                self.st.sat_answers += usize::from(sat);
                sat
            }
            Err(why) => {
                self.solvers[level].s.add(&[!act]);
                return Err(why);
            }
        };
        let res = if sat {
            // Read the predecessor before the solver changes state.
            if want == Pred::Lifted {
                let full = self.model_cube(level);
                let ins = self.model_inputs(level);
                self.pred = self.lift(full, &ins, Some(cube));
            }
            None
        } else {
            let failed: HashSet<SLit> = self.solvers[level].s.failed().into_iter().collect();
            Some(
                map.iter()
                    .filter(|(x, _)| failed.contains(x))
                    .map(|(_, l)| *l)
                    .collect(),
            )
        };
        // Only now: adding a clause ends the model the predecessor was read from.
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

    /// Shrink a cube blocked relative to `F_level` (`core`: the literals its unsatisfiability
    /// used) to a small sub-cube that stays blocked and excludes the initial states: drop one
    /// literal at a time (MIC), the literals of the latches with the lowest priority first, each
    /// try strengthened by [`Ic3::down`].
    fn generalize(&mut self, level: usize, cube: &Cube, core: Cube) -> Result<Cube, String> {
        let mut g = self.fix_init(core, cube);
        let mut tried: Vec<(usize, bool)> = Vec::new();
        loop {
            let next = g
                .iter()
                .enumerate()
                .filter(|(_, l)| !tried.contains(l))
                .min_by_key(|(_, l)| self.prio[l.0])
                .map(|(i, _)| i);
            let Some(pos) = next else {
                return Ok(g);
            };
            tried.push(g[pos]);
            let mut t = g.clone();
            t.remove(pos);
            if let Some(c) = self.down(level, t)? {
                g = c;
            }
        }
    }

    /// `cand` shrunk to the literals its blocking relative to `F_level` used, if it is blocked
    /// and excludes the initial states. One query, without lifting a predecessor when it is
    /// not blocked: `down`'s joins with the predecessors that refute a try (Bradley's down,
    /// several queries and a ternary lift per try, most of them refuted on the FAM circuits)
    /// cost more than the more general clauses saved. On the master + 1 FAM closed loop, IC3
    /// after signal correspondence used 4.8 s of CPU instead of 15.0 s on
    /// `master_failure_sequence` (30 frames against 40), 0.6 s instead of 3.3 s on
    /// `master_failure_before_stall`, 0.9 s instead of 3.0 s on
    /// `master_no_normal_run_on_failure`, 3.0 s instead of 7.0 s on
    /// `master_target_outside_ends_only_calibrating` (ABC's `pdr` generalizes likewise).
    /// Counterexamples to generalization are not blocked either: blocking up to three of them
    /// per try made IC3 slower on the same circuits.
    fn down(&mut self, level: usize, cand: Cube) -> Result<Option<Cube>, String> {
        if cand.is_empty() || self.intersects_init(&cand) {
            return Ok(None);
        }
        Ok(self
            .relative(level, &cand, Pred::Unused)?
            .map(|core| self.fix_init(core, &cand)))
    }

    /// Add the clause `¬g`, known to hold in `F_from`, to every frame up to the highest one where
    /// it stays inductive; that level.
    fn add_blocked(&mut self, g: Cube, from: usize) -> Result<usize, String> {
        let mut at = from;
        let top = self.frames.len() - 1;
        while at < top && self.relative(at, &g, Pred::Unused)?.is_some() {
            at += 1;
        }
        self.st.clauses += 1;
        for &(j, _) in &g {
            self.prio[j] += 1;
        }
        // Stored clauses `¬c` with `g ⊆ c` are implied by `¬g` in every frame up to `at`.
        for lv in 1..=at {
            self.frames[lv].retain(|c| !subset(&g, c));
        }
        for lv in 1..=at {
            self.add_clause(lv, &g);
        }
        self.frames[at].push(g);
        Ok(at)
    }

    fn block(&mut self, cube: Cube, level: usize) -> Result<Block, String> {
        let mut q = BinaryHeap::new();
        q.push(Obligation {
            neg_level: -(level as i64),
            cube,
        });
        while let Some(ob) = q.pop() {
            let l = (-ob.neg_level) as usize;
            self.st.obligations += 1;
            if self.intersects_init(&ob.cube) {
                return Ok(Block::Cex);
            }
            if l == 0 {
                return Ok(Block::Cex);
            }
            if let Some(why) = self.limits.expired() {
                return Ok(Block::Stopped(why));
            }
            // Already excluded from `F_l` by a stored clause: no query, and the same states are
            // blocked one level above that clause's, as after a successful block.
            let top = self.frames.len() - 1;
            if let Some(lv) = (l..=top)
                .rev()
                .find(|&lv| self.frames[lv].iter().any(|c| subset(c, &ob.cube)))
            {
                self.st.contained += 1;
                if lv < top {
                    q.push(Obligation {
                        neg_level: -((lv + 1) as i64),
                        cube: ob.cube,
                    });
                }
                continue;
            }
            match self.relative(l - 1, &ob.cube, Pred::Lifted)? {
                None => {
                    let pred = std::mem::take(&mut self.pred);
                    q.push(Obligation {
                        neg_level: -((l - 1) as i64),
                        cube: pred,
                    });
                    q.push(ob);
                }
                Some(core) => {
                    let g = self.generalize(l - 1, &ob.cube, core)?;
                    // Push the clause as far as it stays relatively inductive.
                    let at = self.add_blocked(g, l)?;
                    let top = self.frames.len() - 1;
                    // Block the same states one level further up now, as PDR does: a cube
                    // that reaches the bad states will be met again at the next frontier.
                    if at < top {
                        q.push(Obligation {
                            neg_level: -((at + 1) as i64),
                            cube: ob.cube,
                        });
                    }
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
        self.frontiers()
    }

    /// [`Ic3::run`] from saved frames (at least two): one solver per level, built from them.
    fn resume(&mut self) -> Result<Option<Invariant>, String> {
        for level in 0..self.frames.len() {
            let f = self.build_solver(level);
            self.solvers.push(f);
        }
        self.frontiers()
    }

    /// Block the bad states at each frontier and push clauses, until a frame is inductive.
    fn frontiers(&mut self) -> Result<Option<Invariant>, String> {
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
                let full = self.model_cube(k);
                let ins = self.model_inputs(k);
                let cube = self.lift(full, &ins, None);
                match self.block(cube, k)? {
                    Block::Blocked => {}
                    Block::Cex => return Ok(None),
                    Block::Stopped(why) => return Err(why),
                }
            }
            // F_k excludes the bad states now: the property is part of it, which strengthens
            // every relative-induction query against it (ABC's "property as hypothesis").
            let nb = {
                let f = &mut self.solvers[k];
                !f.u.lit(&mut f.s, self.bad, 0)
            };
            self.solvers[k].s.add(&[nb]);
            self.new_frame();
            let top = self.frames.len() - 1;
            for i in 1..top {
                let mut cubes = std::mem::take(&mut self.frames[i]).into_iter();
                let mut stay = Vec::new();
                while let Some(c) = cubes.next() {
                    self.st.pushes.0 += 1;
                    let pushed = match self.relative(i, &c, Pred::Unused) {
                        Ok(p) => p,
                        Err(why) => {
                            // Keep this clause and those not yet tried, for a resumed attempt.
                            stay.push(c);
                            stay.extend(cubes);
                            self.frames[i] = stay;
                            return Err(why);
                        }
                    };
                    if let Some(core) = pushed {
                        self.st.pushes.1 += 1;
                        // The core is inductive relative to `F_i` too (ABC's pushing likewise
                        // shrinks a clause that moves); it subsumes clauses of `F_{i+1}`.
                        let c = self.fix_init(core, &c);
                        self.frames[i + 1].retain(|d| !subset(&c, d));
                        self.add_clause(i + 1, &c);
                        self.frames[i + 1].push(c);
                    } else {
                        stay.push(c);
                    }
                }
                self.frames[i] = stay;
                if self.frames[i].is_empty() {
                    // The frames' clauses are inductive relative to the lemmas, which are
                    // inductive themselves: together they are the invariant (lemmas last).
                    let mut inv: Invariant = self.frames[i + 1..]
                        .iter()
                        .flatten()
                        .map(|c| c.iter().map(|&(j, v)| (j, !v)).collect())
                        .collect();
                    inv.extend(self.lemmas.iter().cloned());
                    return Ok(Some(inv));
                }
            }
        }
    }
}

/// The literal of `f`'s solver saying latch `j` has value `v`, in the current state or, with
/// `next`, in the next one (its next-state function).
fn latch_lit(aig: &Aig, f: &mut Frame<'_>, j: usize, v: bool, next: bool) -> SLit {
    let l = &aig.latches[j];
    let x = if next {
        f.u.lit(&mut f.s, l.next, 0)
    } else {
        f.u.lit(&mut f.s, Lit::var_lit(l.var), 0)
    };
    if v {
        x
    } else {
        !x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-hot shift register of four latches (latch 0 reset true, each next latch copies
    /// the previous one, latch 0 becomes false): by hand, no two latches ever hold together.
    fn chain(bad: (usize, usize)) -> Aig {
        let mut g = Aig::new();
        let l: Vec<Lit> = (0..4).map(|i| g.latch(Some(i == 0), None)).collect();
        g.set_next(0, Lit::FALSE);
        for i in 1..4 {
            g.set_next(i, l[i - 1]);
        }
        let b = g.and(l[bad.0], l[bad.1]);
        g.bad = vec![b];
        g.bad_names = vec![None];
        g
    }

    #[test]
    fn a_proof_given_another_proofs_invariant_keeps_it_and_checks() {
        let a = chain((0, 1));
        let Outcome::Proved(Some(lemmas)) = ic3(&a, &Limits::default()) else {
            panic!("latches 0 and 1 never hold together");
        };
        let b = chain((1, 2));
        let Outcome::Proved(Some(inv)) = ic3_with_lemmas(&b, &Limits::default(), &lemmas) else {
            panic!("latches 1 and 2 never hold together");
        };
        // The lemmas come last, unchanged, and the whole is an inductive invariant of `b`
        // that excludes its bad states (the independent certificate check).
        assert!(inv.ends_with(&lemmas));
        assert!(crate::cert::check(&b, &inv).is_ok());
    }

    /// A shift register of `n` latches, latch 0 reset true and then false, each next latch
    /// copying the previous one: by hand, latch `i` holds exactly in tick `i`.
    fn shift(n: usize, bad: Lit) -> (Aig, Vec<Lit>) {
        let mut g = Aig::new();
        let l: Vec<Lit> = (0..n).map(|i| g.latch(Some(i == 0), None)).collect();
        g.set_next(0, Lit::FALSE);
        for i in 1..n {
            g.set_next(i, l[i - 1]);
        }
        g.bad = vec![bad];
        g.bad_names = vec![None];
        (g, l)
    }

    #[test]
    fn a_stopped_attempt_resumes_from_its_frames_to_a_checked_proof() {
        let (mut g, l) = shift(6, Lit::FALSE);
        // Latches 1 and 4 never hold together (they hold in ticks 1 and 4 only).
        g.bad = vec![g.and(l[1], l[4])];
        let mut saved = Ic3Frames::default();
        let stopped = Limits {
            max_depth: Some(1),
            ..Limits::default()
        };
        let out = ic3_resume(&g, &stopped, &Vec::new(), &mut saved);
        assert!(matches!(out, Outcome::Unknown { .. }), "{out:?}");
        // Frames 0..=2 were open when the depth bound stopped it.
        assert_eq!(saved.depth(), 3);
        let Outcome::Proved(Some(inv)) =
            ic3_resume(&g, &Limits::default(), &Vec::new(), &mut saved)
        else {
            panic!("latches 1 and 4 never hold together");
        };
        assert!(crate::cert::check(&g, &inv).is_ok());
        assert_eq!(saved.depth(), 0, "a decided attempt leaves no frames");
    }

    #[test]
    fn an_unknown_reports_the_frames_below_its_frontier_as_cleared() {
        let mut g = shift(6, Lit::FALSE).0;
        // By hand: latch 5 holds first in tick 5, so the shortest trace to it has 6 frames and
        // no engine may claim more than 5 frames cleared.
        g.bad = vec![Lit::var_lit(g.latches[5].var)];
        for d in 0..5 {
            let bound = Limits {
                max_depth: Some(d),
                ..Limits::default()
            };
            match ic3(&g, &bound) {
                // Stopped opening frontier d + 1: frames 0..=d cleared. Or its obligations
                // found a longer trace at an earlier frontier, which BMC could not rebuild
                // within the bound: the frames below that frontier are cleared. Never more
                // than the 5 frames the shortest trace allows.
                Outcome::Unknown { why, cleared } => {
                    if why.starts_with("depth bound") {
                        assert_eq!(cleared, d + 1, "bound {d}");
                    } else {
                        assert!(cleared <= d + 1, "bound {d}: {why}, {cleared}");
                    }
                    assert!(cleared <= 5, "bound {d}: {cleared}");
                }
                // IC3's obligations may find the trace before the bound stops it.
                Outcome::Reached(t) => assert_eq!(t.inputs.len(), 6, "bound {d}"),
                out => panic!("bound {d}: {out:?}"),
            }
        }
    }

    #[test]
    fn a_resumed_attempt_still_finds_a_counterexample() {
        let mut g = shift(6, Lit::FALSE).0;
        // Latch 5 holds in tick 5: the bad output is reached in the sixth frame.
        g.bad = vec![Lit::var_lit(g.latches[5].var)];
        let mut saved = Ic3Frames::default();
        // Stopped as it opens its second frontier (IC3's obligations may find a trace longer
        // than its frontier, so a later bound would let it see this one).
        let stopped = Limits {
            max_depth: Some(0),
            ..Limits::default()
        };
        let out = ic3_resume(&g, &stopped, &Vec::new(), &mut saved);
        assert!(matches!(out, Outcome::Unknown { .. }), "{out:?}");
        assert_eq!(saved.depth(), 2, "{out:?}");
        match ic3_resume(&g, &Limits::default(), &Vec::new(), &mut saved) {
            Outcome::Reached(t) => {
                assert_eq!(t.inputs.len(), 6);
                assert!(crate::scorr::replays(&g, &t));
            }
            out => panic!("latch 5 holds in tick 5, got {out:?}"),
        }
    }
}
