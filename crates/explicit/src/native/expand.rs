//! Expanding a chunk of states with the native generator.
//!
//! Per state: the state-only assumes and the assumes mixing state and inputs are evaluated by
//! the interpreter (they choose the input vectors), then one call of the generated code runs
//! every chosen tick. Per-transition properties (which read the tick's inputs) are evaluated
//! by the interpreter on each successor with its inputs. A tick that stops with a run-time
//! error, and every tick of one state in [`NativeRun::sample`] (by position in its layer), is
//! run again by the interpreter: its result is the one recorded, and a
//! difference is reported as a disagreement.

use super::{Native, NativeRun};
use crate::expand::{push_successor, ChunkOut, Expander, Open, Tick};
use crate::pack::Key;

/// Scratch space of one chunk.
struct Scratch {
    /// The source state's packed words.
    words: Vec<u64>,
    /// The source state's slot values.
    state: Vec<i64>,
    /// A successor's slot values (for per-transition properties).
    post: Vec<i64>,
    /// Packing scratch for the interpreter's successors.
    pack: Vec<u64>,
    /// The chosen input vectors, when mixed assumes or the input abstraction choose.
    idx: Vec<u32>,
    /// Transitions each chosen vector stands for (the input abstraction's group sizes).
    weight: Vec<u64>,
    /// Packed successors, `words` per chosen vector.
    succ: Vec<u64>,
    /// Status per chosen vector.
    status: Vec<i32>,
    /// Coverage bytes.
    covers: Vec<u8>,
}

impl Expander<'_> {
    /// [`Expander::chunk`] with the native generator; the per-transition properties of `open`
    /// read only the state after the tick and the tick's inputs.
    pub(crate) fn chunk_native<K: Key>(
        &self,
        native: &Native,
        run: &NativeRun,
        states: &[K],
        first_pos: usize,
        mut open: Open,
    ) -> ChunkOut<K> {
        let p = self.program;
        let sp = self.space;
        let w = self.packer.words;
        let n = sp.slots.len();
        let count = run.all.len();
        let mut m = self.machine();
        let mut out = ChunkOut::with_room(states.len(), count as u128);
        let mixed = self.prepared(&sp.mixed_assumes);
        let state_assumes = self.prepared(&sp.state_assumes);
        let mut s = Scratch {
            words: vec![0; w],
            state: vec![0; p.n_state],
            post: vec![0; p.n_state],
            pack: vec![0; w],
            idx: Vec::with_capacity(count),
            weight: Vec::with_capacity(count),
            succ: vec![0; count * w],
            status: vec![0; count],
            covers: vec![0; p.covers.len().max(1)],
        };
        let mut walker = self.reduce.filter(|r| r.cost.worth()).map(|r| r.walker(p));
        let mut tally = crate::reduce::Tally::new();
        for (j, key) in states.iter().enumerate() {
            let pos = (first_pos + j) as u32;
            key.to_words(&mut s.words);
            let unpacked = !state_assumes.is_empty() || !mixed.is_empty() || walker.is_some();
            if unpacked {
                self.packer.unpack(key, &mut s.pack, &mut s.state);
                m.load_state(&s.state);
                if !state_assumes.iter().all(|a| m.holds(*a)) {
                    continue;
                }
            }
            tally.begin();
            let groups = match (self.reduce, walker.as_mut()) {
                (Some(r), Some(w)) => {
                    let g = r.groups(w, sp, &s.state);
                    tally.walked(g.as_ref().map_or(0, |g| (count - g.first.len()) as u64));
                    g
                }
                _ => None,
            };
            let list: &[u32] = if mixed.is_empty() && groups.is_none() {
                &run.all
            } else {
                s.idx.clear();
                s.weight.clear();
                let (chosen, sizes): (&[u32], Option<&[u64]>) = match &groups {
                    Some(g) => (&g.first, Some(&g.size)),
                    None => (&run.all, None),
                };
                for (k, &v) in chosen.iter().enumerate() {
                    let at = v as usize * n;
                    if !mixed.is_empty() {
                        m.load(&s.state, &run.vectors[at..at + n]);
                        if !mixed.iter().all(|a| m.holds(*a)) {
                            continue;
                        }
                    }
                    s.idx.push(v);
                    s.weight.push(sizes.map_or(1, |w| w[k]));
                }
                &s.idx
            };
            if groups.is_some() {
                out.transitions += s.weight.iter().sum::<u64>() - s.idx.len() as u64;
            }
            if !native.expand(
                &s.words,
                &run.vectors,
                list,
                &mut s.succ,
                &mut s.status,
                &mut s.covers,
            ) {
                run.disagree("the native generator was called with mismatched buffers".into());
            }
            let sample = run.sample != 0 && pos.is_multiple_of(run.sample);
            if (sample || s.status[..list.len()].iter().any(|&st| st != 0)) && !unpacked {
                self.packer.unpack(key, &mut s.pack, &mut s.state);
            }
            for (k, &v) in list.iter().enumerate() {
                out.transitions += 1;
                let t = Tick { key, pos, input: v };
                let status = s.status[k];
                let native_succ = K::from_words(&s.succ[k * w..k * w + w]);
                if status == 0 && !sample {
                    if !open.watch.is_empty() {
                        // The open per-transition properties read the state after the tick
                        // and the tick's inputs only.
                        self.packer.unpack(&native_succ, &mut s.pack, &mut s.post);
                        let at = v as usize * n;
                        m.load(&s.post, &run.vectors[at..at + n]);
                        self.watch(&mut m, &t, &mut open, &mut out);
                    }
                    push_successor(native_succ, &t, &mut out);
                    continue;
                }
                // The interpreter decides: errors (for their site) and the sampled states.
                let at = v as usize * n;
                m.load(&s.state, &run.vectors[at..at + n]);
                match m.step() {
                    Err(e) => {
                        if status == 0 {
                            run.disagree(format!(
                                "at layer position {pos}, input vector {v}: the interpreter stops with {:?}, the native code does not",
                                e.kind
                            ));
                        }
                        self.record_error(e, &t, &mut open, &mut out);
                    }
                    Ok(()) => {
                        self.watch(&mut m, &t, &mut open, &mut out);
                        let succ: K = self.packer.pack(m.state(), &mut s.pack);
                        if status != 0 || succ != native_succ {
                            run.disagree(format!(
                                "at layer position {pos}, input vector {v}: the native code gives status {status} and a different successor"
                            ));
                        }
                        push_successor(succ, &t, &mut out);
                    }
                }
            }
            tally.stepped(list.len() as u64);
        }
        if let Some(r) = self.reduce {
            r.cost.record(&tally);
        }
        if self.coverage {
            let mut counts: Vec<u64> = s.covers.iter().map(|&b| u64::from(b)).collect();
            counts.truncate(p.covers.len());
            if let Some(c) = m.coverage() {
                counts.iter_mut().zip(c).for_each(|(a, b)| *a += b);
            }
            out.coverage = Some(counts);
        }
        out
    }
}
