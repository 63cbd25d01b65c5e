//! Native successor generation for the explicit engine.
//!
//! [`CCompiler`] implements [`statecheck_explicit::SuccessorCompiler`]: the program's step
//! function as the C code generator emits it (the code `statecheck gen c` ships, so what is
//! checked is what runs), wrapped by [`glue`] in `sc_expand`, which expands one packed state
//! for a list of input vectors; [`build`] compiles it with the system's C compiler into a
//! shared library kept in the user's private cache, and [`Library`] loads and calls it.
//!
//! This crate is the one place below the CLI that writes files, runs a program and loads
//! code; the engine itself stays free of I/O and compares this generator with the interpreter
//! during every search.

mod build;
mod glue;

pub use build::kill_compilers;

use statecheck_explicit::pack::Packer;
use statecheck_explicit::successors::{Build, CompiledSuccessors, SuccessorCompiler};
use statecheck_ir::Program;

/// `sc_expand` of [`glue::source`].
type ExpandFn =
    unsafe extern "C" fn(*const u64, *const i64, *const u32, u32, *mut u64, *mut i32, *mut u8);

/// Builds native successor generators with the system's C compiler (`$CC`, else `cc`).
#[derive(Clone, Copy, Debug, Default)]
pub struct CCompiler;

impl SuccessorCompiler for CCompiler {
    fn prepare(&self, program: &Program, packer: &Packer) -> Build {
        let source = glue::source(program, packer);
        let shape = Shape {
            words: packer.words,
            n_inputs: program.inputs.len(),
            covers: program.covers.len(),
        };
        Box::new(move || {
            let path = build::library(&source)?;
            let lib = Library::load(&path, shape)?;
            Ok(Box::new(lib) as Box<dyn CompiledSuccessors>)
        })
    }
}

/// The sizes a call of `sc_expand` reads and writes.
#[derive(Clone, Copy, Debug)]
struct Shape {
    words: usize,
    n_inputs: usize,
    covers: usize,
}

/// A loaded native successor generator.
pub struct Library {
    /// Keeps the code of `expand` mapped.
    _lib: libloading::Library,
    expand: ExpandFn,
    shape: Shape,
}

impl Library {
    /// Load `sc_expand` from the library at `path`.
    #[allow(unsafe_code)] // Loading a library runs its initialisers: ours is generated C without any.
    fn load(path: &std::path::Path, shape: Shape) -> Result<Library, String> {
        let fail = |e: libloading::Error| format!("cannot load {}: {e}", path.display());
        // SAFETY: the library is the one `build` compiled from our generated source, which has
        // no initialisers, in a directory only this user can write, and `sc_expand` has exactly
        // the signature of `ExpandFn`.
        unsafe {
            let lib = libloading::Library::new(path).map_err(fail)?;
            let expand: ExpandFn = *lib.get::<ExpandFn>(b"sc_expand\0").map_err(fail)?;
            Ok(Library {
                _lib: lib,
                expand,
                shape,
            })
        }
    }
}

impl CompiledSuccessors for Library {
    #[allow(unsafe_code)] // The call into the generated code, after every bound is checked.
    fn expand(
        &self,
        state: &[u64],
        vectors: &[i64],
        idx: &[u32],
        out: &mut [u64],
        status: &mut [i32],
        covers: &mut [u8],
    ) -> bool {
        let Shape {
            words,
            n_inputs,
            covers: n_covers,
        } = self.shape;
        let n_vectors = vectors.len().checked_div(n_inputs).unwrap_or(usize::MAX);
        let fits = state.len() >= words
            && out.len() >= idx.len() * words
            && status.len() >= idx.len()
            && covers.len() >= n_covers.max(1)
            && u32::try_from(idx.len()).is_ok()
            && idx.iter().all(|&i| (i as usize) < n_vectors);
        if !fits {
            return false;
        }
        // SAFETY: checked above: `sc_expand` reads at most `words` words of `state`, `n_inputs`
        // values at each `idx[k] * n_inputs` of `vectors`, and writes at most
        // `idx.len() * words` words of `out`, `idx.len()` statuses and bytes below the number
        // of coverage items of `covers`.
        unsafe {
            (self.expand)(
                state.as_ptr(),
                vectors.as_ptr(),
                idx.as_ptr(),
                idx.len() as u32,
                out.as_mut_ptr(),
                status.as_mut_ptr(),
                covers.as_mut_ptr(),
            );
        }
        true
    }
}
