//! Native successor generation: the program's step function compiled to machine code.
//!
//! The explicit engine normally runs the IR's register code ([`statecheck_ir::Machine`]). A
//! [`Native`] generator is built by the [`SuccessorCompiler`] of [`crate::Options`] (in
//! practice `statecheck-native`: the C step function of the code generator, compiled and
//! loaded), and expands one packed state for a list of input vectors.
//!
//! The interpreter stays the reference: every run-time error is replayed by it (for the error
//! site and message), and the expander compares the two on a sample of states during every
//! search; a disagreement makes the run fall back to the interpreter (see `lib.rs`).

mod expand;

use crate::pack::Packer;
use crate::successors::{Build, CompiledSuccessors, SuccessorCompiler};
use statecheck_ir::assume::InputSpace;
use statecheck_ir::Program;
use std::sync::{Arc, OnceLock};
use std::time::{Duration, Instant};

/// A generator not yet built: the build step, and when its preparation started.
pub(crate) struct Pending {
    build: Build,
    started: Instant,
}

impl Pending {
    /// Prepare a generator for `program` packed by `packer`.
    pub fn new(compiler: &dyn SuccessorCompiler, program: &Program, packer: &Packer) -> Pending {
        let started = Instant::now();
        Pending {
            build: compiler.prepare(program, packer),
            started,
        }
    }

    /// Build (compile, or find in a cache, and load).
    pub fn build(self) -> Result<Native, String> {
        let generator = (self.build)()?;
        Ok(Native {
            generator,
            build_time: self.started.elapsed(),
        })
    }
}

/// A built successor generator.
pub(crate) struct Native {
    generator: Box<dyn CompiledSuccessors>,
    /// Time to generate, compile and load it.
    pub build_time: Duration,
}

impl Native {
    /// [`CompiledSuccessors::expand`].
    pub fn expand(
        &self,
        state: &[u64],
        vectors: &[i64],
        idx: &[u32],
        out: &mut [u64],
        status: &mut [i32],
        covers: &mut [u8],
    ) -> bool {
        self.generator
            .expand(state, vectors, idx, out, status, covers)
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
