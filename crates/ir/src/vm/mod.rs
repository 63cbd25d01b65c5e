//! The interpreter's fast path: the IR compiled once into flat register code.
//!
//! This is not a second semantics: it is a mechanical translation of [`Program::step`] and of
//! the property and assumption expressions, statement by statement and node by node, into
//! three-address instructions over one register file (the slots, then expression locals,
//! temporaries and constants). The tree evaluator in `interp.rs` stays the reference; tests run
//! both on the same inputs and compare.
//!
//! - `op.rs`: the instruction set;
//! - `compile.rs`: the translation (statements; `compile/cond.rs` conditions,
//!   `compile/value.rs` values, `compile/idioms.rs` the flag idioms);
//! - `interval.rs`: value intervals, to drop range checks that cannot fail;
//! - `peephole.rs`: jump threading and removal of useless jumps;
//! - `constprop.rs`: branches on registers of known value;
//! - `run.rs`: the instruction loop.
//!
//! # How it is fast
//!
//! `Machine::step` does not walk the IR: `ir/src/vm/compile.rs` translates the step (and the
//! property, assumption and active-state expressions) once into three-address instructions over
//! one register file (slots, then `let` locals, temporaries and constants), and
//! `ir/src/vm/run.rs` runs them in a `match` loop. The translation is mechanical and keeps the
//! tree evaluator's order of evaluation and of writes, so run-time errors (kind and site) and the
//! slots after an error are the same; what makes it fast is the instruction set (`vm/op.rs`,
//! 12-byte instructions): one variant per operator, immediates, compare-and-branch, branch-free
//! select and logical operators where the skipped operand cannot fail
//! (`a && b`, `if c then x else y` over leaves), the flag idioms (`r | (if c then K else 0)`,
//! `a && s == k`, `(x & K) != 0`, `x == k1 || x == k2 || ..` as one set test, masks such as
//! `r & (K ^ (if c then .. else 0))` folded into the constant branch), fused range check and
//! store, and error sites kept beside the code rather than in it. Around it: small and
//! single-use procedures are inlined, range checks that an interval analysis proves cannot fail are
//! dropped (`vm/interval.rs`; it assumes nothing about slot values), values are reused within a
//! statement, jumps are threaded (also past a conditional jump whose outcome the jump implies, as
//! in the second test of an absent event), a one-case switch becomes a compare-and-branch, and
//! branches on registers of known value are folded (`vm/peephole.rs`, `vm/constprop.rs`). The
//! loop indexes registers unchecked and walks the instructions with a pointer (the other `unsafe`
//! of the library code: the visited set's prefetch hint, and loading and calling the native
//! successor generator, `native/src/lib.rs`): `Code::validate` asserts the invariants when
//! compiling. Consumers that
//! evaluate an expression many times prepare it once (`Program::prepare`, `Machine::holds`).
//! Programs with more than 65 536 registers run on the reference evaluator. Tests: every model in
//! `tests/` and `examples/`, 3000 random programs of random IR (`vm/random_programs.rs`), and
//! targeted tests per optimisation; `cargo bench -p statecheck-ir --bench step` measures it.

mod compile;
mod constprop;
mod interval;
mod op;
mod peephole;
#[cfg(test)]
mod random_programs;
mod run;
#[cfg(test)]
mod tests;

pub(crate) use op::{Op, Reg};
pub(crate) use run::run;

use crate::program::*;
use std::collections::HashMap;

impl Program {
    /// The compiled form the interpreter runs, built once and kept in the program's
    /// [`RunCache`].
    pub(crate) fn code(&self) -> &Code {
        match self.run_cache.get_or_init(|| Code::compile(self)) {
            Some(code) => code,
            // `code` is the only function that fills the cache, always with a `Code`.
            None => unreachable!("the run cache holds the program's `Code`"),
        }
    }
}

/// A compiled expression: run from `start` to its `End`, result in `reg`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Segment {
    /// First instruction.
    pub start: u32,
    /// The register holding the value after `End`.
    pub reg: Reg,
}

/// The compiled form of a program.
#[derive(Clone, Debug)]
pub(crate) struct Code {
    /// False when the program has too many registers for [`Reg`]: the machine then runs the
    /// reference evaluator.
    pub runnable: bool,
    /// The instructions.
    pub ops: Vec<Op>,
    /// The run-time check site of each instruction (`u32::MAX` for those that cannot fail).
    pub sites: Vec<SiteId>,
    /// Switch tables: `[end, case 0, .., case len-1]` each.
    pub tables: Vec<u32>,
    /// Bounds of the range checks.
    pub bounds: Vec<(i64, i64)>,
    /// Initial register file: slots' initial values, zeros, and the constants.
    pub init_regs: Vec<i64>,
    /// Depth of the return stack the code needs.
    pub max_depth: usize,
    /// Entry point of one tick.
    pub step: u32,
    /// Compiled property/assumption/active-state expressions by expression id.
    pub exprs: HashMap<ExprId, Segment>,
}

impl Code {
    /// Compile a program.
    pub(crate) fn compile(p: &Program) -> Code {
        let max_depth = max_call_depth(p) + 1;
        match compile::compile(p) {
            Some(mut c) => {
                peephole::optimise(&mut c);
                // Each round turns at least one conditional jump into a `Jmp`: it terminates.
                while constprop::fold_branches(&mut c) {
                    peephole::optimise(&mut c);
                }
                let code = Code {
                    runnable: true,
                    ops: c.ops,
                    sites: c.sites,
                    tables: c.tables,
                    bounds: c.bounds,
                    init_regs: c.init_regs,
                    step: c.step,
                    max_depth,
                    exprs: c
                        .exprs
                        .into_iter()
                        .map(|(e, (start, reg))| (e, Segment { start, reg }))
                        .collect(),
                };
                code.validate();
                code
            }
            None => Code {
                runnable: false,
                ops: Vec::new(),
                sites: Vec::new(),
                tables: Vec::new(),
                bounds: Vec::new(),
                init_regs: p.slots.iter().map(|s| s.init).collect(),
                step: 0,
                max_depth,
                exprs: HashMap::new(),
            },
        }
    }

    /// Assert the invariants that make the instruction loop's unchecked accesses sound (see
    /// `run.rs`): every register operand, jump target, segment start, switch table entry and
    /// bounds index in range, and the code ending with `End` or `Ret`.
    fn validate(&self) {
        let n_regs = self.init_regs.len();
        let n_ops = self.ops.len() as u32;
        assert_eq!(self.sites.len(), self.ops.len());
        assert!(self.step < n_ops);
        for seg in self.exprs.values() {
            assert!(seg.start < n_ops && (seg.reg as usize) < n_regs);
        }
        for (pc, op) in self.ops.iter().enumerate() {
            let mut op = *op;
            op.for_each_reg(|r| assert!((*r as usize) < n_regs, "register {r} at {pc}"));
            if let Some(t) = op.target_mut() {
                assert!(*t < n_ops);
            }
            if let Op::Check { bounds, .. } | Op::CheckMov { bounds, .. } = op {
                assert!((bounds as usize) < self.bounds.len());
            }
            if let Some(r) = op.switch_entries() {
                assert!(self.tables[r].iter().all(|t| *t < n_ops));
            }
        }
        assert!(self
            .ops
            .last()
            .is_some_and(|op| matches!(op, Op::End | Op::Ret)));
    }
}

/// Deepest nesting of procedure calls in the IR (an upper bound for the compiled code, which
/// inlines some calls).
fn max_call_depth(p: &Program) -> usize {
    fn block(p: &Program, b: &[Stmt], memo: &mut Vec<Option<usize>>) -> usize {
        b.iter()
            .map(|s| match s {
                Stmt::If {
                    then, otherwise, ..
                } => block(p, then, memo).max(block(p, otherwise, memo)),
                Stmt::Switch { cases, .. } => {
                    cases.iter().map(|c| block(p, c, memo)).max().unwrap_or(0)
                }
                Stmt::Call(id) => 1 + proc_depth(p, *id, memo),
                _ => 0,
            })
            .max()
            .unwrap_or(0)
    }
    fn proc_depth(p: &Program, id: ProcId, memo: &mut Vec<Option<usize>>) -> usize {
        if let Some(d) = memo[id as usize] {
            return d;
        }
        memo[id as usize] = Some(0);
        let d = block(p, &p.procs[id as usize].body, memo);
        memo[id as usize] = Some(d);
        d
    }
    let mut memo = vec![None; p.procs.len()];
    block(p, &p.step, &mut memo)
}
