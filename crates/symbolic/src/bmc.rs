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
            return Outcome::Unknown(why);
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
            None => return Outcome::Unknown("the SAT solver failed".into()),
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
