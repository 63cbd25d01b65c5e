//! The instruction set of the register code.
//!
//! One variant per operator (no second dispatch on an operator field), register-immediate forms
//! for constant operands, compare-and-branch, a branch-free select, and a fused range check and
//! store. An instruction is 12 bytes; run-time error sites are not stored in the instruction
//! but in [`Code::sites`](super::Code::sites), indexed like the instructions, and read only when
//! an instruction fails.

/// A register index. Programs with more registers run on the reference evaluator.
pub(crate) type Reg = u16;

/// One instruction. `d` is the destination, `a`, `b`, `c` are source registers, `imm` an
/// immediate operand and `t` a jump target (an instruction index).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Op {
    /// `d = a + b`, overflow checked.
    Add { d: Reg, a: Reg, b: Reg },
    /// `d = a - b`, overflow checked.
    Sub { d: Reg, a: Reg, b: Reg },
    /// `d = a * b`, overflow checked.
    Mul { d: Reg, a: Reg, b: Reg },
    /// `d = a / b` (division by zero and overflow checked).
    Div { d: Reg, a: Reg, b: Reg },
    /// `d = a % b` (division by zero and overflow checked).
    Rem { d: Reg, a: Reg, b: Reg },
    /// `d = a << b` (shift amount and overflow checked).
    Shl { d: Reg, a: Reg, b: Reg },
    /// `d = a >> b` (shift amount checked).
    Shr { d: Reg, a: Reg, b: Reg },
    /// `d = a & b`.
    And { d: Reg, a: Reg, b: Reg },
    /// `d = a | b`.
    Or { d: Reg, a: Reg, b: Reg },
    /// `d = a ^ b`.
    Xor { d: Reg, a: Reg, b: Reg },
    /// `d = min(a, b)`.
    Min { d: Reg, a: Reg, b: Reg },
    /// `d = max(a, b)`.
    Max { d: Reg, a: Reg, b: Reg },
    /// `d = (a == b)`.
    Eq { d: Reg, a: Reg, b: Reg },
    /// `d = (a != b)`.
    Ne { d: Reg, a: Reg, b: Reg },
    /// `d = (a < b)`.
    Lt { d: Reg, a: Reg, b: Reg },
    /// `d = (a <= b)`.
    Le { d: Reg, a: Reg, b: Reg },
    /// `d = (a != 0 && b != 0)`, both operands already evaluated.
    LAnd { d: Reg, a: Reg, b: Reg },
    /// `d = (a != 0 || b != 0)`, both operands already evaluated.
    LOr { d: Reg, a: Reg, b: Reg },
    /// `d = (a != 0 && b == imm)`.
    LAndEqI { d: Reg, a: Reg, b: Reg, imm: i32 },
    /// `d = (a != 0 && b != imm)`.
    LAndNeI { d: Reg, a: Reg, b: Reg, imm: i32 },
    /// `d = (a in set)`: `0 <= a < 32` and bit `a` of `set` is 1.
    InSet { d: Reg, a: Reg, set: u32 },
    /// `d = a + imm`, overflow checked.
    AddI { d: Reg, a: Reg, imm: i32 },
    /// `d = a & imm`.
    AndI { d: Reg, a: Reg, imm: i32 },
    /// `d = a | imm`.
    OrI { d: Reg, a: Reg, imm: i32 },
    /// `d = a ^ imm`.
    XorI { d: Reg, a: Reg, imm: i32 },
    /// `d = (a == imm)`.
    EqI { d: Reg, a: Reg, imm: i32 },
    /// `d = (a != imm)`.
    NeI { d: Reg, a: Reg, imm: i32 },
    /// `d = (a < imm)`.
    LtI { d: Reg, a: Reg, imm: i32 },
    /// `d = (a <= imm)`.
    LeI { d: Reg, a: Reg, imm: i32 },
    /// `d = (a > imm)`.
    GtI { d: Reg, a: Reg, imm: i32 },
    /// `d = (a >= imm)`.
    GeI { d: Reg, a: Reg, imm: i32 },
    /// `d = a`.
    Mov { d: Reg, a: Reg },
    /// `d = imm`.
    MovI { d: Reg, imm: i32 },
    /// `d = (a == 0)`.
    Not { d: Reg, a: Reg },
    /// `d = !a` (bitwise).
    BitNot { d: Reg, a: Reg },
    /// `d = -a`, overflow checked.
    Neg { d: Reg, a: Reg },
    /// `d = |a|`, overflow checked.
    Abs { d: Reg, a: Reg },
    /// `d = if c != 0 { a } else { b }`, without a branch.
    Sel { d: Reg, c: Reg, a: Reg, b: Reg },
    /// `d = a | (if c != 0 { x } else { y })`, without a branch.
    OrSel {
        d: Reg,
        a: Reg,
        c: Reg,
        x: Reg,
        y: Reg,
    },
    /// Fail unless `lo <= a <= hi`, bounds in [`Code::bounds`](super::Code::bounds).
    Check { a: Reg, bounds: u32 },
    /// Fail unless `lo <= a <= hi`, then `d = a`.
    CheckMov { d: Reg, a: Reg, bounds: u32 },
    /// Jump if `a == 0`.
    Jz { a: Reg, t: u32 },
    /// Jump if `a != 0`.
    Jnz { a: Reg, t: u32 },
    /// Jump if `a == b`.
    JEq { a: Reg, b: Reg, t: u32 },
    /// Jump if `a != b`.
    JNe { a: Reg, b: Reg, t: u32 },
    /// Jump if `a < b`.
    JLt { a: Reg, b: Reg, t: u32 },
    /// Jump if `a <= b`.
    JLe { a: Reg, b: Reg, t: u32 },
    /// Jump if `a == imm`.
    JEqI { a: Reg, imm: i32, t: u32 },
    /// Jump if `a != imm`.
    JNeI { a: Reg, imm: i32, t: u32 },
    /// Jump if `a < imm`.
    JLtI { a: Reg, imm: i32, t: u32 },
    /// Jump if `a <= imm`.
    JLeI { a: Reg, imm: i32, t: u32 },
    /// Jump if `a > imm`.
    JGtI { a: Reg, imm: i32, t: u32 },
    /// Jump if `a >= imm`.
    JGeI { a: Reg, imm: i32, t: u32 },
    /// Jump if `0 <= a < 32` and bit `a` of `set` is 1.
    JIn { a: Reg, set: u32, t: u32 },
    /// Jump unless `0 <= a < 32` and bit `a` of `set` is 1.
    JNotIn { a: Reg, set: u32, t: u32 },
    /// Jump if `a & imm != 0`.
    JAnyI { a: Reg, imm: i32, t: u32 },
    /// Jump if `a & imm == 0`.
    JNoneI { a: Reg, imm: i32, t: u32 },
    /// Jump.
    Jmp { t: u32 },
    /// Jump through the table at [`Code::tables`](super::Code::tables)`[table..]`: `[end,
    /// case 0, .., case len-1]`; to `end` when `a` is not a case.
    Switch { a: Reg, len: u16, table: u32 },
    /// Call the code at `t`, returning to the next instruction.
    Call { t: u32 },
    /// Return from a call.
    Ret,
    /// Count a coverage item.
    Cover { id: u32 },
    /// End of a segment.
    End,
}

impl Op {
    /// Apply `f` to every register operand (the destination first, then the sources).
    pub(crate) fn for_each_reg(&mut self, mut f: impl FnMut(&mut Reg)) {
        use Op::*;
        match self {
            Add { d, a, b }
            | Sub { d, a, b }
            | Mul { d, a, b }
            | Div { d, a, b }
            | Rem { d, a, b }
            | Shl { d, a, b }
            | Shr { d, a, b }
            | And { d, a, b }
            | Or { d, a, b }
            | Xor { d, a, b }
            | Min { d, a, b }
            | Max { d, a, b }
            | Eq { d, a, b }
            | Ne { d, a, b }
            | Lt { d, a, b }
            | Le { d, a, b }
            | LAnd { d, a, b }
            | LOr { d, a, b }
            | LAndEqI { d, a, b, .. }
            | LAndNeI { d, a, b, .. } => {
                f(d);
                f(a);
                f(b);
            }
            AddI { d, a, .. }
            | AndI { d, a, .. }
            | OrI { d, a, .. }
            | XorI { d, a, .. }
            | EqI { d, a, .. }
            | NeI { d, a, .. }
            | LtI { d, a, .. }
            | LeI { d, a, .. }
            | GtI { d, a, .. }
            | GeI { d, a, .. }
            | InSet { d, a, .. }
            | Mov { d, a }
            | Not { d, a }
            | BitNot { d, a }
            | Neg { d, a }
            | Abs { d, a }
            | CheckMov { d, a, .. } => {
                f(d);
                f(a);
            }
            MovI { d, .. } => f(d),
            OrSel { d, a, c, x, y } => {
                f(d);
                f(a);
                f(c);
                f(x);
                f(y);
            }
            Sel { d, c, a, b } => {
                f(d);
                f(c);
                f(a);
                f(b);
            }
            Check { a, .. }
            | Jz { a, .. }
            | Jnz { a, .. }
            | JEqI { a, .. }
            | JNeI { a, .. }
            | JLtI { a, .. }
            | JLeI { a, .. }
            | JGtI { a, .. }
            | JGeI { a, .. }
            | JIn { a, .. }
            | JNotIn { a, .. }
            | JAnyI { a, .. }
            | JNoneI { a, .. }
            | Switch { a, .. } => f(a),
            JEq { a, b, .. } | JNe { a, b, .. } | JLt { a, b, .. } | JLe { a, b, .. } => {
                f(a);
                f(b);
            }
            Jmp { .. } | Call { .. } | Ret | Cover { .. } | End => {}
        }
    }

    /// The register the instruction writes, if any.
    pub(crate) fn dest(&self) -> Option<Reg> {
        let mut op = *self;
        let mut first = None;
        // `for_each_reg` visits the destination first.
        op.for_each_reg(|r| {
            first.get_or_insert(*r);
        });
        match self {
            Op::Check { .. }
            | Op::Jz { .. }
            | Op::Jnz { .. }
            | Op::JEq { .. }
            | Op::JNe { .. }
            | Op::JLt { .. }
            | Op::JLe { .. }
            | Op::JEqI { .. }
            | Op::JNeI { .. }
            | Op::JLtI { .. }
            | Op::JLeI { .. }
            | Op::JGtI { .. }
            | Op::JGeI { .. }
            | Op::JIn { .. }
            | Op::JNotIn { .. }
            | Op::JAnyI { .. }
            | Op::JNoneI { .. }
            | Op::Switch { .. } => None,
            _ => first,
        }
    }

    /// The jump or call target, if the instruction has one (switch tables are separate).
    pub(crate) fn target_mut(&mut self) -> Option<&mut u32> {
        use Op::*;
        match self {
            Jz { t, .. }
            | Jnz { t, .. }
            | JEq { t, .. }
            | JNe { t, .. }
            | JLt { t, .. }
            | JLe { t, .. }
            | JEqI { t, .. }
            | JNeI { t, .. }
            | JLtI { t, .. }
            | JLeI { t, .. }
            | JGtI { t, .. }
            | JGeI { t, .. }
            | JIn { t, .. }
            | JNotIn { t, .. }
            | JAnyI { t, .. }
            | JNoneI { t, .. }
            | Jmp { t }
            | Call { t } => Some(t),
            _ => None,
        }
    }

    /// The indices of a switch's table entries (its end, then its cases) in
    /// [`Code::tables`](super::Code::tables).
    pub(crate) fn switch_entries(&self) -> Option<std::ops::Range<usize>> {
        match *self {
            Op::Switch { len, table, .. } => {
                Some(table as usize..table as usize + 1 + len as usize)
            }
            _ => None,
        }
    }

    /// True for a conditional jump (which reads registers and has no other effect).
    pub(crate) fn is_cond_jump(&self) -> bool {
        use Op::*;
        matches!(
            self,
            Jz { .. }
                | Jnz { .. }
                | JEq { .. }
                | JNe { .. }
                | JLt { .. }
                | JLe { .. }
                | JEqI { .. }
                | JNeI { .. }
                | JLtI { .. }
                | JLeI { .. }
                | JGtI { .. }
                | JGeI { .. }
                | JIn { .. }
                | JNotIn { .. }
                | JAnyI { .. }
                | JNoneI { .. }
        )
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn an_instruction_is_twelve_bytes() {
        assert_eq!(std::mem::size_of::<super::Op>(), 12);
    }
}
