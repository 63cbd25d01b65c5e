//! The SAT solver (CaDiCaL through `cadical-sys`, which compiles the bundled C++ source with
//! the system's C++ compiler: no libclang, no cmake) and the Tseitin encoding of AIG time frames.

use crate::aig::{Aig, Lit, Node};
use crate::engine::Limits;
use cadical_sys::{CaDiCal, Status, Terminator};
use std::cell::RefCell;

thread_local! {
    /// The limits of the computation running on this thread, which every solver of the
    /// thread obeys inside `solve` (through its terminator), so that one long SAT call cannot
    /// overrun a deadline or ignore a stop flag.
    static ACTIVE: RefCell<Option<Limits>> = const { RefCell::new(None) };
}

/// Run `f` with every SAT call on this thread interrupted once `limits` expire (an
/// interrupted call answers "unknown", which the engines turn into an `unknown` verdict or a
/// less general but sound step). Nested calls restore the outer limits on return.
pub fn with_limits<R>(limits: &Limits, f: impl FnOnce() -> R) -> R {
    let prev = ACTIVE.with(|a| a.replace(Some(limits.clone())));
    let r = f();
    ACTIVE.with(|a| *a.borrow_mut() = prev);
    r
}

/// Asks the thread's active limits, one call in [`CHECK_EVERY`] (CaDiCaL calls it in its
/// inner loop).
struct LimitTerminator {
    calls: u32,
}

/// How often the terminator reads the clock.
const CHECK_EVERY: u32 = 64;

impl Terminator for LimitTerminator {
    fn terminated(&mut self) -> bool {
        self.calls = self.calls.wrapping_add(1);
        if !self.calls.is_multiple_of(CHECK_EVERY) {
            return false;
        }
        ACTIVE.with(|a| {
            a.try_borrow()
                .is_ok_and(|l| l.as_ref().is_some_and(|l| l.expired().is_some()))
        })
    }
}

/// Bytes CaDiCaL allocates per variable of room in its per-variable tables, internal
/// (two watch lists, values, phases, scores, links, flags, trail data) and external (the
/// variable maps): measured on the FAM closed loop's unrolling, whose tables grew from 2^19
/// to 2^20 variables with the resident set going from 211 to 300 MiB (about 170 bytes per
/// added variable of room), rounded up.
const BYTES_PER_VAR: u64 = 192;

/// A solver literal: variable `v` (0-based) is CaDiCaL's variable `v + 1`, negative when the
/// literal is negated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SLit(i32);

impl SLit {
    /// The positive literal of variable `v` (0-based).
    pub fn positive(v: u32) -> SLit {
        // Variable indices stay far below `i32::MAX`: every one is a node of an encoded frame.
        SLit(i32::try_from(v + 1).unwrap_or(i32::MAX))
    }

    /// The literal's variable (0-based).
    pub fn var(self) -> u32 {
        self.0.unsigned_abs() - 1
    }

    fn dimacs(self) -> i32 {
        self.0
    }
}

impl std::ops::Not for SLit {
    type Output = SLit;
    fn not(self) -> SLit {
        SLit(-self.0)
    }
}

/// An incremental SAT solver.
pub struct Solver {
    s: CaDiCal,
    vars: u32,
    /// How many variables CaDiCaL has been told of (`resize`); its bounded variable addition
    /// (`factor`) may only introduce variables above them.
    declared: u32,
    t: SLit,
    /// The variables CaDiCaL's per-variable tables have room for (its `vsize`, which it
    /// doubles as variables are declared past it).
    room: u32,
    /// A growth of the tables was refused by the memory limit: clauses are no longer added
    /// and every `solve` answers "unknown" (the engines then report the memory limit).
    over: bool,
    /// The assumptions of the last `solve`, for `failed`.
    assumed: Vec<SLit>,
    /// The last answer: `val` and `failed` may only be asked in the matching state.
    last: Option<bool>,
}

impl Default for Solver {
    fn default() -> Self {
        Solver::new()
    }
}

impl Solver {
    /// A fresh solver with a constant-true variable.
    pub fn new() -> Solver {
        let mut c = CaDiCal::new();
        // Silent whatever the environment says (`set` of "quiet" is allowed in any state).
        c.set("quiet", 1);
        Solver::with(c)
    }

    /// A solver without pre- and inprocessing, for the many small incremental queries of IC3
    /// (variable elimination then only costs model reconstruction on every call).
    pub fn plain() -> Solver {
        let mut c = CaDiCal::new();
        c.set("quiet", 1);
        // Returns false only for an unknown configuration name; the default one is sound.
        let _ = c.configure("plain");
        // "Lucky" phase checks try eight trivial assignments by full propagation before every
        // call: on thousands of small incremental queries over a large formula they cost more
        // than the search itself. (Returns false only for an unknown option name.)
        let _ = c.set("lucky", 0);
        Solver::with(c)
    }

    fn with(mut c: CaDiCal) -> Solver {
        c.connect_terminator(LimitTerminator { calls: 0 });
        let mut s = Solver {
            s: c,
            vars: 0,
            declared: 0,
            t: SLit::positive(0),
            room: 0,
            over: false,
            assumed: Vec::new(),
            last: None,
        };
        s.t = s.fresh();
        s.add(&[s.t]);
        s
    }

    /// The constant true literal.
    pub fn tru(&self) -> SLit {
        self.t
    }

    /// A new variable's positive literal.
    pub fn fresh(&mut self) -> SLit {
        let l = SLit::positive(self.vars);
        self.vars += 1;
        l
    }

    /// Declares the variables handed out since the last call. When they pass the room of
    /// CaDiCaL's per-variable tables, which it then doubles at once (hundreds of MB on a large
    /// unrolling, out of sight of any probe between two frames), the memory limit is asked
    /// first with the bytes about to be allocated; if they would pass it, nothing is declared
    /// and the solver is [`Solver::over`] the limit.
    fn declare(&mut self) {
        if self.declared >= self.vars || self.over {
            return;
        }
        if self.vars >= self.room {
            // CaDiCaL's `enlarge`: the first size is one more than the variables, then it
            // doubles until they fit.
            let mut room = if self.room == 0 {
                self.vars.saturating_add(1)
            } else {
                self.room.saturating_mul(2)
            };
            while room <= self.vars && room < u32::MAX {
                room = room.saturating_mul(2);
            }
            let extra = u64::from(room - self.room) * BYTES_PER_VAR;
            if crate::engine::memory_exceeded_by(extra) {
                self.over = true;
                return;
            }
            self.room = room;
        }
        self.s.resize(i32::try_from(self.vars).unwrap_or(i32::MAX));
        self.declared = self.vars;
    }

    /// Whether the memory limit refused this solver's growth (then it answers "unknown").
    pub fn over(&self) -> bool {
        self.over
    }

    /// Add a clause.
    pub fn add(&mut self, clause: &[SLit]) {
        self.declare();
        self.last = None;
        if self.over {
            return;
        }
        match clause {
            [a] => self.s.clause1(a.dimacs()),
            [a, b] => self.s.clause2(a.dimacs(), b.dimacs()),
            [a, b, c] => self.s.clause3(a.dimacs(), b.dimacs(), c.dimacs()),
            _ => {
                for l in clause {
                    self.s.add(l.dimacs());
                }
                self.s.add(0);
            }
        }
    }

    /// Solve under assumptions: `Some(true)` satisfiable, `Some(false)` unsatisfiable, `None`
    /// when the solver failed.
    pub fn solve(&mut self, assumps: &[SLit]) -> Option<bool> {
        self.declare();
        if self.over {
            self.last = None;
            return None;
        }
        self.assumed.clear();
        self.assumed.extend_from_slice(assumps);
        for l in assumps {
            self.s.assume(l.dimacs());
        }
        self.last = match self.s.solve() {
            Status::SATISFIABLE => Some(true),
            Status::UNSATISFIABLE => Some(false),
            Status::UNKNOWN => None,
        };
        self.last
    }

    /// A literal's value in the last model (false when unassigned or when the last answer was
    /// not a model).
    pub fn value(&mut self, l: SLit) -> bool {
        self.last == Some(true) && l.var() < self.declared && self.s.val(l.dimacs()) > 0
    }

    /// The assumptions (as given) that the last unsatisfiable answer depends on.
    pub fn failed(&mut self) -> Vec<SLit> {
        if self.last != Some(false) {
            return Vec::new();
        }
        let assumed = std::mem::take(&mut self.assumed);
        let core = assumed
            .iter()
            .copied()
            .filter(|l| self.s.failed(l.dimacs()))
            .collect();
        self.assumed = assumed;
        core
    }
}

/// How latches are encoded in frame 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Start {
    /// At their reset values (uninitialized latches free).
    Reset,
    /// Free.
    Free,
}

/// Time frames of an AIG in one solver, encoded lazily (only the cones that are asked for).
pub struct Unroller<'a> {
    aig: &'a Aig,
    start: Start,
    frames: Vec<Vec<Option<SLit>>>,
}

impl<'a> Unroller<'a> {
    /// An unrolling of `aig` with frame 0 as `start` says.
    pub fn new(aig: &'a Aig, start: Start) -> Unroller<'a> {
        Unroller {
            aig,
            start,
            frames: Vec::new(),
        }
    }

    /// The graph.
    pub fn aig(&self) -> &'a Aig {
        self.aig
    }

    /// The solver literal of `l` in frame `t`.
    pub fn lit(&mut self, s: &mut Solver, l: Lit, t: usize) -> SLit {
        let v = self.var(s, l.var(), t);
        if l.is_neg() {
            !v
        } else {
            v
        }
    }

    fn slot(&mut self, v: u32, t: usize) -> Option<SLit> {
        while self.frames.len() <= t {
            self.frames.push(vec![None; self.aig.nodes.len()]);
        }
        self.frames[t][v as usize]
    }

    fn var(&mut self, s: &mut Solver, v: u32, t: usize) -> SLit {
        if let Some(x) = self.slot(v, t) {
            return x;
        }
        // Iterative post-order over the cone (AIG chains can be thousands deep).
        let mut stack: Vec<(u32, usize, bool)> = vec![(v, t, false)];
        while let Some((v, t, expanded)) = stack.pop() {
            if self.slot(v, t).is_some() {
                continue;
            }
            let node = self.aig.nodes[v as usize];
            let x = match node {
                Node::False => !s.tru(),
                Node::Input(_) => s.fresh(),
                Node::Latch(i) => {
                    let latch = &self.aig.latches[i as usize];
                    if t == 0 {
                        match (self.start, latch.init) {
                            (Start::Reset, Some(b)) => {
                                if b {
                                    s.tru()
                                } else {
                                    !s.tru()
                                }
                            }
                            _ => s.fresh(),
                        }
                    } else {
                        let n = latch.next;
                        match self.slot(n.var(), t - 1) {
                            Some(x) => {
                                if n.is_neg() {
                                    !x
                                } else {
                                    x
                                }
                            }
                            None => {
                                stack.push((v, t, false));
                                stack.push((n.var(), t - 1, false));
                                continue;
                            }
                        }
                    }
                }
                Node::And(a, b) => {
                    let (xa, xb) = (self.slot(a.var(), t), self.slot(b.var(), t));
                    match (xa, xb) {
                        (Some(xa), Some(xb)) => {
                            let xa = if a.is_neg() { !xa } else { xa };
                            let xb = if b.is_neg() { !xb } else { xb };
                            let o = s.fresh();
                            s.add(&[!o, xa]);
                            s.add(&[!o, xb]);
                            s.add(&[o, !xa, !xb]);
                            o
                        }
                        _ => {
                            debug_assert!(!expanded, "children encoded before the gate");
                            stack.push((v, t, true));
                            if xa.is_none() {
                                stack.push((a.var(), t, false));
                            }
                            if xb.is_none() {
                                stack.push((b.var(), t, false));
                            }
                            continue;
                        }
                    }
                }
            };
            self.frames[t][v as usize] = Some(x);
        }
        self.slot(v, t).unwrap_or(!s.tru())
    }

    /// The values of the inputs in frame `t` of the last model (unencoded inputs: false).
    pub fn inputs(&mut self, s: &mut Solver, t: usize) -> Vec<bool> {
        let ins = &self.aig.inputs;
        ins.iter()
            .map(|&v| self.slot(v, t).is_some_and(|x| s.value(x)))
            .collect()
    }

    /// The values of the latches in frame `t` of the last model (unencoded latches: their reset
    /// value, or false).
    pub fn latches(&mut self, s: &mut Solver, t: usize) -> Vec<bool> {
        let ls: Vec<(u32, Option<bool>)> =
            self.aig.latches.iter().map(|l| (l.var, l.init)).collect();
        ls.into_iter()
            .map(|(v, init)| match self.slot(v, t) {
                Some(x) => s.value(x),
                None => init.unwrap_or(false),
            })
            .collect()
    }
}
