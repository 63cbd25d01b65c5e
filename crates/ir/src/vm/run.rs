//! The instruction loop.
//!
//! One `match` per instruction; operands are read before the destination is written, so an
//! instruction may name the same register as source and destination. Failing instructions
//! build their error in cold functions, off the hot path. The return stack is the caller's
//! (the machine's, allocated once), at least [`Code::max_depth`] deep.

use super::op::Op;
use super::Code;
use crate::error::{op_fault, RuntimeError, RuntimeErrorKind as K};
use statecheck_syntax::ast::BinOp;

/// The error of the instruction before `next` (the loop has moved past it).
#[cold]
#[inline(never)]
fn fail(code: &Code, next: usize, kind: K) -> Box<RuntimeError> {
    Box::new(RuntimeError {
        kind,
        site: code.sites[next - 1],
    })
}

/// `a op b` for the operators with several failure modes, through the shared definition;
/// `next` is the index after the instruction.
#[cold]
#[inline(never)]
fn slow_binary(
    code: &Code,
    next: usize,
    op: BinOp,
    a: i64,
    b: i64,
) -> Result<i64, Box<RuntimeError>> {
    statecheck_model::ops::binary(op, a, b).map_err(|e| op_fault(e, code.sites[next - 1]))
}

/// `0 <= v < 32` and bit `v` of `set` is 1.
#[inline(always)]
fn in_set(v: i64, set: u32) -> bool {
    (v as u64) < 32 && (set >> v) & 1 != 0
}

/// Run a segment from `start` until its `End`.
#[inline(never)]
pub(crate) fn run(
    code: &Code,
    regs: &mut [i64],
    stack: &mut [u32],
    cov: Option<&mut [u64]>,
    start: u32,
) -> Result<(), Box<RuntimeError>> {
    exec(code, regs, stack, cov, start, |_| {})
}

/// [`run`], counting how often each instruction executes (for tests and profiling).
#[cfg(test)]
pub(crate) fn run_counting(
    code: &Code,
    regs: &mut [i64],
    start: u32,
    counts: &mut [u64],
) -> Result<(), Box<RuntimeError>> {
    let mut stack = vec![0; code.max_depth];
    exec(code, regs, &mut stack, None, start, |pc| counts[pc] += 1)
}

/// The loop; `trace` sees the index of every instruction before it executes.
///
/// Register and instruction accesses are unchecked (the bounds checks cost about a fifth of
/// the instructions executed); the invariants that make this sound are established when the
/// code is compiled (`Code::validate`) and when this function starts.
#[inline(always)]
#[allow(unsafe_code)] // Unchecked indexing only, justified at each use (`SAFETY:`).
fn exec(
    code: &Code,
    regs: &mut [i64],
    stack: &mut [u32],
    mut cov: Option<&mut [u64]>,
    start: u32,
    mut trace: impl FnMut(usize),
) -> Result<(), Box<RuntimeError>> {
    // The invariants that make the unchecked accesses below sound. `Code::validate` asserted,
    // when the code was compiled, that every register operand is below
    // `code.init_regs.len()`, that every jump target and segment start is below
    // `code.ops.len()`, and that the last instruction is `End` or `Ret`.
    let ops = &code.ops[..];
    assert!(regs.len() == code.init_regs.len() && (start as usize) < ops.len());
    let tables = &code.tables[..];
    let mut sp = 0usize;
    // The instruction pointer is a pointer rather than an index: fetching through it saves
    // the index arithmetic of every dispatch. It always points into `ops`.
    let base = ops.as_ptr();
    // SAFETY: `start < ops.len()` (asserted above).
    let mut pc: *const Op = unsafe { base.add(start as usize) };
    // The index of the instruction `pc` points to.
    macro_rules! index {
        () => {
            // SAFETY: `pc` and `base` point into the same slice, `pc` at or after `base`.
            unsafe { pc.offset_from(base) as usize }
        };
    }
    // Continue at instruction `t`.
    macro_rules! goto {
        ($t:expr) => {{
            let t = $t as usize;
            debug_assert!(t < ops.len());
            // SAFETY: `t < ops.len()`: a validated jump target, switch table entry or return
            // address (the index after a `Call`, which is never last).
            pc = unsafe { base.add(t) };
        }};
    }
    macro_rules! r {
        ($x:expr) => {
            *{
                let i = $x as usize;
                debug_assert!(i < regs.len());
                // SAFETY: `i` is a register operand of a validated instruction, so
                // `i < code.init_regs.len() == regs.len()` (asserted above).
                unsafe { regs.get_unchecked_mut(i) }
            }
        };
    }
    macro_rules! checked {
        ($v:expr) => {
            match $v {
                Some(v) => v,
                None => return Err(fail(code, index!(), K::Overflow)),
            }
        };
    }
    macro_rules! jump_if {
        ($cond:expr, $t:expr) => {
            if $cond {
                goto!($t);
            }
        };
    }
    loop {
        trace(index!());
        debug_assert!(index!() < ops.len());
        // SAFETY: `pc` points into `ops`: at `start` (checked above), a validated jump target
        // or return address (the index after a `Call`, which is never last), or after an
        // instruction that is not last (the last one, `End` or `Ret`, does not fall through).
        // Matched through the reference, so that each arm loads only its own operands (a copy
        // made the dispatch decode every field of every instruction).
        let op = unsafe { &*pc };
        // SAFETY: at most one past the end of `ops` (and then never dereferenced: see above).
        pc = unsafe { pc.add(1) };
        match *op {
            Op::Add { d, a, b } => r!(d) = checked!(r!(a).checked_add(r!(b))),
            Op::Sub { d, a, b } => r!(d) = checked!(r!(a).checked_sub(r!(b))),
            Op::Mul { d, a, b } => r!(d) = checked!(r!(a).checked_mul(r!(b))),
            Op::Div { d, a, b } => r!(d) = slow_binary(code, index!(), BinOp::Div, r!(a), r!(b))?,
            Op::Rem { d, a, b } => r!(d) = slow_binary(code, index!(), BinOp::Rem, r!(a), r!(b))?,
            Op::Shl { d, a, b } => r!(d) = slow_binary(code, index!(), BinOp::Shl, r!(a), r!(b))?,
            Op::Shr { d, a, b } => r!(d) = slow_binary(code, index!(), BinOp::Shr, r!(a), r!(b))?,
            Op::And { d, a, b } => r!(d) = r!(a) & r!(b),
            Op::Or { d, a, b } => r!(d) = r!(a) | r!(b),
            Op::Xor { d, a, b } => r!(d) = r!(a) ^ r!(b),
            Op::Min { d, a, b } => r!(d) = r!(a).min(r!(b)),
            Op::Max { d, a, b } => r!(d) = r!(a).max(r!(b)),
            Op::Eq { d, a, b } => r!(d) = (r!(a) == r!(b)) as i64,
            Op::Ne { d, a, b } => r!(d) = (r!(a) != r!(b)) as i64,
            Op::Lt { d, a, b } => r!(d) = (r!(a) < r!(b)) as i64,
            Op::Le { d, a, b } => r!(d) = (r!(a) <= r!(b)) as i64,
            Op::LAnd { d, a, b } => r!(d) = ((r!(a) != 0) & (r!(b) != 0)) as i64,
            Op::LOr { d, a, b } => r!(d) = ((r!(a) != 0) | (r!(b) != 0)) as i64,
            Op::LAndEqI { d, a, b, imm } => r!(d) = ((r!(a) != 0) & (r!(b) == imm as i64)) as i64,
            Op::LAndNeI { d, a, b, imm } => r!(d) = ((r!(a) != 0) & (r!(b) != imm as i64)) as i64,
            Op::InSet { d, a, set } => r!(d) = in_set(r!(a), set) as i64,
            Op::AddI { d, a, imm } => r!(d) = checked!(r!(a).checked_add(imm as i64)),
            Op::AndI { d, a, imm } => r!(d) = r!(a) & imm as i64,
            Op::OrI { d, a, imm } => r!(d) = r!(a) | imm as i64,
            Op::XorI { d, a, imm } => r!(d) = r!(a) ^ imm as i64,
            Op::EqI { d, a, imm } => r!(d) = (r!(a) == imm as i64) as i64,
            Op::NeI { d, a, imm } => r!(d) = (r!(a) != imm as i64) as i64,
            Op::LtI { d, a, imm } => r!(d) = (r!(a) < imm as i64) as i64,
            Op::LeI { d, a, imm } => r!(d) = (r!(a) <= imm as i64) as i64,
            Op::GtI { d, a, imm } => r!(d) = (r!(a) > imm as i64) as i64,
            Op::GeI { d, a, imm } => r!(d) = (r!(a) >= imm as i64) as i64,
            Op::Mov { d, a } => r!(d) = r!(a),
            Op::MovI { d, imm } => r!(d) = imm as i64,
            Op::Not { d, a } => r!(d) = (r!(a) == 0) as i64,
            Op::BitNot { d, a } => r!(d) = !r!(a),
            Op::Neg { d, a } => r!(d) = checked!(r!(a).checked_neg()),
            Op::Abs { d, a } => r!(d) = checked!(r!(a).checked_abs()),
            Op::Sel { d, c, a, b } => {
                let (x, y) = (r!(a), r!(b));
                r!(d) = if r!(c) != 0 { x } else { y };
            }
            Op::OrSel { d, a, c, x, y } => {
                let (v, x, y) = (r!(a), r!(x), r!(y));
                r!(d) = v | if r!(c) != 0 { x } else { y };
            }
            Op::Check { a, bounds } => {
                let v = r!(a);
                // SAFETY: `Code::validate` asserted `bounds < code.bounds.len()`.
                let (lo, hi) = *unsafe { code.bounds.get_unchecked(bounds as usize) };
                if v < lo || v > hi {
                    return Err(fail(code, index!(), K::Range { value: v, lo, hi }));
                }
            }
            Op::CheckMov { d, a, bounds } => {
                let v = r!(a);
                // SAFETY: `Code::validate` asserted `bounds < code.bounds.len()`.
                let (lo, hi) = *unsafe { code.bounds.get_unchecked(bounds as usize) };
                if v < lo || v > hi {
                    return Err(fail(code, index!(), K::Range { value: v, lo, hi }));
                }
                r!(d) = v;
            }
            Op::Jz { a, t } => jump_if!(r!(a) == 0, t),
            Op::Jnz { a, t } => jump_if!(r!(a) != 0, t),
            Op::JEq { a, b, t } => jump_if!(r!(a) == r!(b), t),
            Op::JNe { a, b, t } => jump_if!(r!(a) != r!(b), t),
            Op::JLt { a, b, t } => jump_if!(r!(a) < r!(b), t),
            Op::JLe { a, b, t } => jump_if!(r!(a) <= r!(b), t),
            Op::JEqI { a, imm, t } => jump_if!(r!(a) == imm as i64, t),
            Op::JNeI { a, imm, t } => jump_if!(r!(a) != imm as i64, t),
            Op::JLtI { a, imm, t } => jump_if!(r!(a) < imm as i64, t),
            Op::JLeI { a, imm, t } => jump_if!(r!(a) <= imm as i64, t),
            Op::JGtI { a, imm, t } => jump_if!(r!(a) > imm as i64, t),
            Op::JGeI { a, imm, t } => jump_if!(r!(a) >= imm as i64, t),
            Op::JIn { a, set, t } => jump_if!(in_set(r!(a), set), t),
            Op::JNotIn { a, set, t } => jump_if!(!in_set(r!(a), set), t),
            Op::JAnyI { a, imm, t } => jump_if!(r!(a) & imm as i64 != 0, t),
            Op::JNoneI { a, imm, t } => jump_if!(r!(a) & imm as i64 == 0, t),
            Op::Jmp { t } => goto!(t),
            Op::Switch { a, len, table } => {
                let v = r!(a) as u64;
                let k = if v < len as u64 { 1 + v as usize } else { 0 };
                debug_assert!(table as usize + k < tables.len());
                // SAFETY: `k <= len`, and `Code::validate` asserted that the switch's entries
                // `table..=table + len` are in `code.tables`.
                goto!(*unsafe { tables.get_unchecked(table as usize + k) });
            }
            Op::Call { t } => {
                stack[sp] = index!() as u32;
                sp += 1;
                goto!(t);
            }
            Op::Ret => {
                sp -= 1;
                goto!(stack[sp]);
            }
            Op::Cover { id } => {
                if let Some(c) = cov.as_deref_mut() {
                    c[id as usize] += 1;
                }
            }
            Op::End => return Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::in_set;

    #[test]
    fn membership_covers_exactly_0_to_31() {
        assert!(in_set(0, 1));
        assert!(in_set(31, 1 << 31));
        assert!(!in_set(30, 1 << 31));
        assert!(!in_set(32, u32::MAX));
        assert!(!in_set(-1, u32::MAX));
        assert!(!in_set(i64::MIN, u32::MAX));
        assert!(!in_set(i64::MAX, u32::MAX));
    }
}
