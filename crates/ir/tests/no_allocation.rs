//! The interpreter allocates nothing per step (an invariant of ARCHITECTURE.md): an allocator
//! that counts the calling thread's allocations sees none while the FAM plant runs ticks of
//! random inputs and its properties are evaluated.

use statecheck_ir::{lower, Machine, PropertyKind};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

thread_local! {
    static ALLOCATIONS: Cell<u64> = const { Cell::new(0) };
}

struct Counting;

// `GlobalAlloc` is an unsafe trait; this implementation only counts and forwards to `System`.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|n| n.set(n.get() + 1));
        // SAFETY: forwarded unchanged; the caller upholds `alloc`'s contract.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by `System` with `layout` (see `alloc`).
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn a_step_allocates_nothing() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/fam/fam.sc");
    let source = std::fs::read_to_string(path).expect("the FAM example is readable");
    // fam.sc imports the FAM chart from lib/: follow its imports.
    let program =
        statecheck_model::imports::load_with(path, source, |k| std::fs::read_to_string(k).ok());
    let (model, _) = statecheck_model::check(&program.file);
    let sys = model
        .systems
        .iter()
        .find(|s| !s.implicit)
        .expect("a system");
    let p = lower(&model, sys).expect("lowers");
    let mut m = Machine::new(&p);
    let invariants: Vec<_> = p
        .properties
        .iter()
        .filter_map(|prop| match prop.kind {
            PropertyKind::Invariant { expr, .. } => Some(expr),
            _ => None,
        })
        .collect();
    let mut rng = 42u64;
    let before = ALLOCATIONS.with(Cell::get);
    for _ in 0..20_000 {
        for inp in &p.inputs {
            let s = &p.slots[inp.slot as usize];
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            m.set(inp.slot, s.lo + (rng % ((s.hi - s.lo + 1) as u64)) as i64);
        }
        assert!(m.step().is_ok());
        for e in &invariants {
            assert!(m.eval(*e).is_ok());
        }
    }
    assert_eq!(ALLOCATIONS.with(Cell::get) - before, 0);
}
