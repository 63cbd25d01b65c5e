//! Compiled successor generation, as a plug-in: the explicit engine defines what it needs
//! from a compiled step function, and another crate (`statecheck-native`: the C code
//! generator's step function, compiled by the system's C compiler and loaded) provides it.
//! The engine itself does no I/O and runs the interpreter whenever no generator is given.

use crate::pack::Packer;
use statecheck_ir::Program;

/// A compiled successor generator for one program and one state packing.
pub trait CompiledSuccessors: Send + Sync {
    /// Expand the packed state `state` for the input vectors `vectors[idx[k]]` (each
    /// `Program::inputs.len()` values): `status[k]` is 0 and `out[k * words ..][..words]` the
    /// packed successor, or `status[k]` is the run-time error's status (the generated C's
    /// `sc_status`). Coverage items hit set their byte in `covers`. False (and nothing done)
    /// when a slice is too short for the call.
    fn expand(
        &self,
        state: &[u64],
        vectors: &[i64],
        idx: &[u32],
        out: &mut [u64],
        status: &mut [i32],
        covers: &mut [u8],
    ) -> bool;
}

/// The step that builds a generator: it owns all it needs, so it can run on another thread.
pub type Build = Box<dyn FnOnce() -> Result<Box<dyn CompiledSuccessors>, String> + Send>;

/// Something that compiles successor generators.
pub trait SuccessorCompiler: Send + Sync + std::fmt::Debug {
    /// Generate, on the calling thread, what building a generator for `program` packed by
    /// `packer` needs, and return the (slow) build step.
    fn prepare(&self, program: &Program, packer: &Packer) -> Build;
}
