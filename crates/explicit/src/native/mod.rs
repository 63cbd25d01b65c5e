//! Native successor generation: the program's step function compiled to machine code.
//!
//! The explicit engine normally runs the IR's register code ([`statecheck_ir::Machine`]). A
//! [`Native`] generator is the same program translated by the C code generator (the code
//! `statecheck gen c` ships, so what is checked is what runs), wrapped by [`glue`] in a
//! function that expands one packed state for a list of input vectors, compiled by the
//! system's C compiler ([`build`]) and loaded as a shared library.
//!
//! The interpreter stays the reference: every run-time error is replayed by it (for the error
//! site and message), and the expander compares the two on a sample of states during every
//! search; a disagreement makes the run fall back to the interpreter (see `lib.rs`).

mod build;
mod expand;
mod glue;

use crate::inputs::InputSpace;
use crate::pack::Packer;
use statecheck_ir::Program;
use std::sync::{Arc, OnceLock};
use std::time::{Duration, Instant};

/// `sc_expand` of [`glue::source`].
type ExpandFn =
    unsafe extern "C" fn(*const u64, *const i64, *const u32, u32, *mut u64, *mut i32, *mut u8);

/// A generated successor generator, not yet compiled: all that compiling needs, owned, so that
/// it can be compiled on another thread.
pub(crate) struct Pending {
    source: String,
    words: usize,
    n_inputs: usize,
    covers: usize,
    started: Instant,
}

impl Pending {
    /// Generate the C source for `program` packed by `packer`.
    pub fn new(program: &Program, packer: &Packer) -> Pending {
        let started = Instant::now();
        Pending {
            source: glue::source(program, packer),
            words: packer.words,
            n_inputs: program.inputs.len(),
            covers: program.covers.len(),
            started,
        }
    }

    /// Compile (or find in the cache) and load.
    pub fn build(self) -> Result<Native, String> {
        let path = build::library(&self.source)?;
        let (lib, expand) = load(&path)?;
        Ok(Native {
            _lib: lib,
            expand,
            words: self.words,
            n_inputs: self.n_inputs,
            covers: self.covers,
            build_time: self.started.elapsed(),
        })
    }
}

/// A loaded native successor generator.
pub(crate) struct Native {
    /// Keeps the code of `expand` mapped.
    _lib: libloading::Library,
    expand: ExpandFn,
    words: usize,
    n_inputs: usize,
    covers: usize,
    /// Time to generate, compile and load it.
    pub build_time: Duration,
}

/// Load `sc_expand` from the library at `path`.
#[allow(unsafe_code)] // Loading a library runs its initialisers: ours is generated C without any.
fn load(path: &std::path::Path) -> Result<(libloading::Library, ExpandFn), String> {
    let fail = |e: libloading::Error| format!("cannot load {}: {e}", path.display());
    // SAFETY: the library is the one `build` compiled from our generated source, which has no
    // initialisers, and `sc_expand` has exactly the signature of `ExpandFn`.
    unsafe {
        let lib = libloading::Library::new(path).map_err(fail)?;
        let f: ExpandFn = *lib.get::<ExpandFn>(b"sc_expand\0").map_err(fail)?;
        Ok((lib, f))
    }
}

impl Native {
    /// Expand the packed state `state` for the input vectors `vectors[idx[k]]` (each
    /// `n_inputs` values): `status[k]` is 0 and `out[k * words ..][..words]` the packed
    /// successor, or `status[k]` is the run-time error's status. Coverage items hit set their
    /// byte in `covers`. False (and nothing done) when a slice is too short for the call.
    #[allow(unsafe_code)] // The call into the generated code, after every bound is checked.
    pub fn expand(
        &self,
        state: &[u64],
        vectors: &[i64],
        idx: &[u32],
        out: &mut [u64],
        status: &mut [i32],
        covers: &mut [u8],
    ) -> bool {
        let n_vectors = vectors
            .len()
            .checked_div(self.n_inputs)
            .unwrap_or(usize::MAX);
        let fits = state.len() >= self.words
            && out.len() >= idx.len() * self.words
            && status.len() >= idx.len()
            && covers.len() >= self.covers.max(1)
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

/// Most input values listed for native expansion (8 MiB); wider input spaces stay with the
/// interpreter, which enumerates them without a list.
const MAX_LISTED_VALUES: u128 = 1 << 20;

/// The native generator of one run: ready once compiled (possibly on another thread, so the
/// search switches to it between blocks), with the input vectors it expands.
pub(crate) struct NativeRun {
    /// The generator, once compiled and loaded.
    ready: Arc<OnceLock<Native>>,
    /// Why there is none, if compiling failed.
    failed: Arc<OnceLock<String>>,
    /// Every input vector allowed by the input-only assumes, flat.
    pub vectors: Vec<i64>,
    /// `0 .. number of vectors`.
    pub all: Vec<u32>,
    /// The first disagreement with the interpreter, if any.
    disagreement: OnceLock<String>,
    /// One state in this many (by position in its layer) is expanded by the interpreter too
    /// and compared; 0: none.
    pub sample: u32,
}

impl NativeRun {
    /// A run for `space`'s input vectors, comparing one state in `sample` with the
    /// interpreter; `None` when there are too many vectors to list.
    pub fn new(space: &InputSpace, sample: u32) -> Option<NativeRun> {
        let n = space.slots.len();
        let (vectors, count) = match space.listed() {
            Some((flat, count)) => (flat.to_vec(), count),
            None => {
                let values = space.count.checked_mul(n.max(1) as u128)?;
                if values > MAX_LISTED_VALUES {
                    return None;
                }
                let count = usize::try_from(space.count).ok()?;
                let mut v = vec![0i64; n];
                let mut flat = Vec::with_capacity(count * n);
                space.first(&mut v);
                for _ in 0..count {
                    flat.extend_from_slice(&v);
                    space.advance(&mut v);
                }
                (flat, count)
            }
        };
        Some(NativeRun {
            ready: Arc::default(),
            failed: Arc::default(),
            vectors,
            all: (0..u32::try_from(count).ok()?).collect(),
            disagreement: OnceLock::new(),
            sample,
        })
    }

    /// The generator, when it is ready.
    pub fn ready(&self) -> Option<&Native> {
        self.ready.get()
    }

    /// Why compiling failed, if it did.
    pub fn failure(&self) -> Option<&str> {
        self.failed.get().map(String::as_str)
    }

    /// Compile `pending` on this thread.
    pub fn build_now(&self, pending: Pending) {
        store(&self.ready, &self.failed, pending.build());
    }

    /// Compile `pending` on a thread of its own; the search picks the generator up when ready.
    pub fn build_in_background(&self, pending: Pending) {
        let (ready, failed) = (Arc::clone(&self.ready), Arc::clone(&self.failed));
        let spawned = std::thread::Builder::new()
            .name("statecheck-cc".into())
            .spawn(move || store(&ready, &failed, pending.build()));
        if let Err(e) = spawned {
            let _ = self
                .failed
                .set(format!("cannot start the compiler thread: {e}"));
        }
    }

    /// Record that the generator disagreed with the interpreter (the first report is kept).
    pub fn disagree(&self, what: String) {
        let _ = self.disagreement.set(what);
    }

    /// The first disagreement with the interpreter, if any.
    pub fn disagreement(&self) -> Option<&str> {
        self.disagreement.get().map(String::as_str)
    }
}

/// Keep a build's generator, or why there is none.
fn store(ready: &OnceLock<Native>, failed: &OnceLock<String>, built: Result<Native, String>) {
    match built {
        Ok(n) => {
            let _ = ready.set(n);
        }
        Err(e) => {
            let _ = failed.set(e);
        }
    }
}
