//! Exploration on two threads as a pipeline: an *expanding* thread computes the successors of
//! states (unpacking, the plants' event masks, the automata's moves, `needs`, packing and
//! hashing), and this thread *numbers* them (the visited table, the store, the successor
//! lists). States are numbered in exactly the order one thread numbers them — the expanding
//! thread expands the states in the order they were numbered and hands each state's
//! successors back in that order — so the product, the supervisor and every figure are the
//! same with one thread or two (`crates/synth/tests/threads.rs`).
//!
//! The numbering thread sends each run of newly numbered states' keys (a copy of the new
//! part of the store) on an unbounded channel; the expanding thread sends batches of up to
//! [`STATES_PER_BATCH`] expanded states on a channel of [`BATCHES_IN_FLIGHT`] batches, so it
//! runs ahead by at most that much successor data. Neither thread waits for the other while
//! it has work: the expander flushes its batch whenever it runs out of keys, and the
//! numberer sends new keys after every batch. The keys waiting to be expanded are a second
//! copy of the frontier, counted in the engine's memory estimate.

use super::{Batch, Expander, Explored, Packing, Rules};
use crate::error::Error;
use crate::limits::Budget;
use crate::problem::Problem;
use std::sync::mpsc;

/// States per batch of successors handed from the expanding thread to the numbering one.
const STATES_PER_BATCH: usize = 512;

/// Batches the expanding thread may be ahead of the numbering one.
const BATCHES_IN_FLIGHT: usize = 8;

/// Explore the reachable product of `p` from the initial state already in `x` on two threads;
/// `flags` gets each state's flags in state order.
pub(super) fn explore(
    p: &Problem,
    pk: &Packing,
    rules: &Rules,
    x: &mut Explored,
    flags: &mut Vec<u8>,
    budget: &Budget,
) -> Result<(), Error> {
    let (keys_tx, keys_rx) = mpsc::channel::<Vec<u64>>();
    let (batch_tx, batch_rx) = mpsc::sync_channel::<Batch>(BATCHES_IN_FLIGHT);
    std::thread::scope(|scope| {
        scope.spawn(move || expand_all(Expander::new(p, pk, rules), keys_rx, batch_tx));
        number_all(x, flags, keys_tx, batch_rx, budget)
    })
}

/// The expanding thread: expands every key it receives, in order, and sends the successors
/// in batches; it ends when the numbering thread drops its end of either channel.
fn expand_all(mut ex: Expander<'_>, keys: mpsc::Receiver<Vec<u64>>, out: mpsc::SyncSender<Batch>) {
    let words = ex.pk.words;
    let mut batch = Batch::default();
    for run in keys {
        for key in run.chunks_exact(words) {
            ex.expand(key, &mut batch);
            if batch.flags.len() == STATES_PER_BATCH
                && out.send(std::mem::take(&mut batch)).is_err()
            {
                return;
            }
        }
        // Out of keys for now: hand over what is expanded, so that the numbering thread can
        // number it and send the next keys.
        if !batch.flags.is_empty() && out.send(std::mem::take(&mut batch)).is_err() {
            return;
        }
    }
}

/// The numbering thread: looks up every expanded state's successors in order, sends the keys
/// of the states found new, until every numbered state is expanded. Returning (also with a
/// limit) drops both channel ends, which ends the expanding thread.
fn number_all(
    x: &mut Explored,
    flags: &mut Vec<u8>,
    keys: mpsc::Sender<Vec<u64>>,
    batches: mpsc::Receiver<Batch>,
    budget: &Budget,
) -> Result<(), Error> {
    let words = x.words;
    let lost = || Error::supervisor("the expanding thread of the explicit engine stopped");
    keys.send(x.store[..words].to_vec()).map_err(|_| lost())?;
    let mut sent = 1usize;
    let mut next_check = 4096usize;
    while flags.len() < sent {
        let b = batches.recv().map_err(|_| lost())?;
        let before = x.count;
        for k in 0..b.flags.len() {
            // Read the next state's slots while this one's are looked up.
            if k + 1 < b.flags.len() {
                x.visited.touch(&b.hashes[b.state(k + 1)]);
            }
            x.add(&b, b.state(k), budget)?;
            flags.push(b.flags[k]);
        }
        if x.count > before {
            keys.send(x.store[before * words..x.count * words].to_vec())
                .map_err(|_| lost())?;
            sent = x.count;
        }
        if flags.len() >= next_check {
            next_check = flags.len() + 4096;
            let queued = (sent - flags.len()) as u64 * words as u64 * 8;
            budget.check("reachability", x.count as f64, x.bytes() + queued)?;
        }
    }
    Ok(())
}
