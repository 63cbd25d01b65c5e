//! Bounded model checking: unroll from the reset state one frame at a time, so the first
//! trace found is a shortest one.

use crate::aig::Aig;
use crate::engine::{Limits, Outcome, Trace};
use crate::sat::{Solver, Start, Unroller};

/// Look for a shortest trace to `aig.bad[0]` under `aig.constraints`.
pub fn bmc(aig: &Aig, limits: &Limits) -> Outcome {
    let Some(&bad) = aig.bad.first() else {
        return Outcome::Proved(None);
    };
    let mut s = Solver::new();
    let mut u = Unroller::new(aig, Start::Reset);
    let mut k = 0;
    loop {
        if limits.max_depth.is_some_and(|d| k >= d) {
            return Outcome::Bounded(k);
        }
        if let Some(why) = limits.expired() {
            return Outcome::unknown_after(why, k);
        }
        for &c in &aig.constraints {
            let x = u.lit(&mut s, c, k);
            s.add(&[x]);
        }
        let b = u.lit(&mut s, bad, k);
        match s.solve(&[b]) {
            Some(true) => return Outcome::Reached(extract(&mut u, &mut s, k)),
            Some(false) => {
                s.add(&[!b]);
            }
            None => return Outcome::unknown_after(limits.why_interrupted(), k),
        }
        k += 1;
    }
}

/// The trace of frames `0..=k` in the solver's model.
pub(crate) fn extract(u: &mut Unroller, s: &mut Solver, k: usize) -> Trace {
    Trace {
        init: u.latches(s, 0),
        inputs: (0..=k).map(|t| u.inputs(s, t)).collect(),
    }
}

/// Why [`bmc_many`] returned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ManyEnd {
    /// Every bad output was reached or given up by the caller.
    Done,
    /// No trace of at most this many frames reaches the bad outputs still open.
    Bounded(usize),
    /// A limit stopped the search; the text says which.
    Stopped(String),
}

/// Bounded model checking of every bad output of `aig` in one unrolling: frame by frame, each
/// output still open (`open(j)` is asked before every query, so an output another engine
/// decided is dropped) is queried in turn, and `found(j, trace)` gets a shortest trace to
/// output `j` the moment it is found. One unrolling serves all outputs: the run costs the
/// deepest trace's unrolling once, not once per output. Each query obeys `limits` and, while
/// it runs, `stop_of(j)` as well (so a long query on an output another engine has just
/// decided is abandoned). `cleared(j, k)` is told each time no trace of at most `k` frames
/// reaches output `j`.
pub fn bmc_many(
    aig: &Aig,
    limits: &Limits,
    open: &dyn Fn(usize) -> bool,
    stop_of: &dyn Fn(usize) -> Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    cleared: &dyn Fn(usize, usize),
    found: &mut dyn FnMut(usize, Trace),
) -> ManyEnd {
    let mut done = vec![false; aig.bad.len()];
    let mut s = Solver::new();
    let mut u = Unroller::new(aig, Start::Reset);
    let mut k = 0;
    loop {
        if !(0..aig.bad.len()).any(|j| !done[j] && open(j)) {
            return ManyEnd::Done;
        }
        if limits.max_depth.is_some_and(|d| k >= d) {
            return ManyEnd::Bounded(k);
        }
        if let Some(why) = limits.expired() {
            return ManyEnd::Stopped(why);
        }
        for &c in &aig.constraints {
            let x = u.lit(&mut s, c, k);
            s.add(&[x]);
        }
        for (j, &bad) in aig.bad.iter().enumerate() {
            if done[j] || !open(j) {
                continue;
            }
            let b = u.lit(&mut s, bad, k);
            let mut lim = limits.clone();
            if let Some(flag) = stop_of(j) {
                lim.stop = Some(flag);
            }
            match crate::sat::with_limits(&lim, || s.solve(&[b])) {
                Some(true) => {
                    done[j] = true;
                    found(j, extract(&mut u, &mut s, k));
                }
                // No trace reaches output j in frame k: a fact of every trace, which also
                // helps the queries of the other outputs.
                Some(false) => {
                    s.add(&[!b]);
                    cleared(j, k + 1);
                }
                // Interrupted by the run's limits, or by output j's own flag (decided
                // elsewhere; or the solver failed): j is given up, the others go on.
                None => {
                    if let Some(why) = limits.expired() {
                        return ManyEnd::Stopped(why);
                    }
                    done[j] = true;
                }
            }
        }
        k += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aig::Lit;

    /// A one-hot shift register of six latches: latch `i` holds in frame `i` only (latch 0 is
    /// reset true, every next latch copies the previous one, latch 0 becomes false). Bad
    /// outputs: latch 5, latch 2, and latches 0 and 1 together (never: one-hot).
    fn chain() -> Aig {
        let mut g = Aig::new();
        let l: Vec<Lit> = (0..6)
            .map(|i| g.latch(Some(i == 0), Some(format!("l{i}"))))
            .collect();
        g.set_next(0, Lit::FALSE);
        for i in 1..6 {
            g.set_next(i, l[i - 1]);
        }
        let both = g.and(l[0], l[1]);
        g.bad = vec![l[5], l[2], both];
        g.bad_names = vec![None; 3];
        g
    }

    #[test]
    fn one_unrolling_finds_each_output_at_its_own_shortest_depth() {
        let g = chain();
        let lim = Limits {
            max_depth: Some(10),
            ..Limits::default()
        };
        let mut got = Vec::new();
        let deepest = std::sync::Mutex::new(vec![0; 3]);
        let end = bmc_many(
            &g,
            &lim,
            &|_| true,
            &|_| None,
            &|j, k| deepest.lock().expect("not poisoned")[j] = k,
            &mut |j, t| got.push((j, t.inputs.len())),
        );
        // By hand: latch 2 holds in frame 2 (a 3-frame trace), latch 5 in frame 5 (6 frames),
        // found in depth order; the third output is never reached, so the search ends at the
        // depth bound.
        assert_eq!(got, vec![(1, 3), (0, 6)]);
        assert_eq!(end, ManyEnd::Bounded(10));
        // Cleared up to the frame before each trace's last; the unreachable one to the bound.
        assert_eq!(*deepest.lock().expect("not poisoned"), vec![5, 2, 10]);
    }

    #[test]
    fn outputs_no_longer_open_are_not_asked() {
        let g = chain();
        let mut got = Vec::new();
        // Only output 1 is wanted: once found, nothing is open and the search ends.
        let end = bmc_many(
            &g,
            &Limits::default(),
            &|j| j == 1,
            &|_| None,
            &|_, _| {},
            &mut |j, t| got.push((j, t.inputs.len())),
        );
        assert_eq!(got, vec![(1, 3)]);
        assert_eq!(end, ManyEnd::Done);
    }
}
