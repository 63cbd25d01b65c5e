//! Counterexample reconstruction: a second breadth-first search that keeps every layer with
//! parent links, up to the layer of the deepest deciding transition, then a walk back from
//! each deciding transition's source state.
//!
//! The layers of a breadth-first search are sets fixed by the model, so the source state of a
//! transition found in layer `d` of the exploration is in layer `d` of this search, and the
//! walk back gives a shortest path to it.
//!
//! The reconstruction gets what is left of the run's time budget: when it runs out, the
//! findings stand (the exploration found them) but their counterexamples are reported missing,
//! with the reason.

use crate::expand::{Expander, Found};
use crate::pack::Key;
use crate::search::{search, End, Limits};
use crate::Limit;
use std::time::Duration;

/// For each property: the input vectors of a shortest counterexample through the state it was
/// found from (as long as the layer it was found in, or shorter after a bitstate search),
/// when one was found and could be rebuilt within `max_memory` and the time `budget` (`Err` says why not). Properties
/// without a finding get `Err("")`.
pub(crate) fn rebuild<K: Key>(
    exp: &Expander,
    found: &[Option<(u64, Found<K>)>],
    max_memory: Option<u64>,
    budget: Option<Duration>,
) -> Vec<Result<Vec<Vec<i64>>, String>> {
    let Some(deepest) = found.iter().flatten().map(|(d, _)| *d).max() else {
        return found.iter().map(|_| Err(String::new())).collect();
    };
    let plain = Expander {
        program: exp.program,
        packer: exp.packer,
        space: exp.space,
        specs: &[],
        coverage: false,
        native: exp.native,
        reduce: exp.reduce,
        sym: exp.sym,
    };
    if deepest > 0 && budget.is_some_and(|b| b.is_zero()) {
        let why = "counterexample not rebuilt: the time limit was used up by the exploration";
        return found
            .iter()
            .map(|f| {
                Err(if f.is_some() {
                    why.into()
                } else {
                    String::new()
                })
            })
            .collect();
    }
    let limits = Limits {
        max_memory,
        timeout: budget,
        ..Limits::default()
    };
    let s = search::<K>(&plain, limits, Some(deepest), None);
    let failed = match &s.end {
        End::Limit(l @ Limit::Memory(_)) => {
            Some(format!("counterexample not rebuilt: {}", l.describe()))
        }
        End::Limit(Limit::Time(_)) => {
            Some("counterexample not rebuilt: the time limit ran out while rebuilding it".into())
        }
        _ => None,
    };
    found
        .iter()
        .map(|f| {
            let Some((layer, f)) = f else {
                return Err(String::new());
            };
            if let Some(why) = &failed {
                return Err(why.clone());
            }
            if s.layers.len() <= *layer as usize {
                return Err("counterexample not rebuilt: layer missing (internal error)".into());
            }
            // The parent's shortest depth. An exact search holds each state once, at its
            // shortest depth, which is the layer it was found in: that layer is searched first.
            // A bitstate search may have taken the parent for visited where it was first
            // reached and found it later (`bitstate.rs`): then it is in an earlier layer, and
            // the counterexample is shorter.
            let find = |d: usize| Some((d, s.layers[d].0.iter().position(|k| *k == f.parent)?));
            let at = find(*layer as usize).or_else(|| (0..*layer as usize).find_map(find));
            let Some((shortest, mut pos)) = at else {
                return Err("counterexample not rebuilt: state missing (internal error)".into());
            };
            let mut inputs = vec![u128::from(f.input)];
            for d in (1..=shortest).rev() {
                let (parent, input) = s.layers[d].1[pos];
                inputs.push(u128::from(input));
                pos = parent as usize;
            }
            inputs.reverse();
            Ok(inputs.into_iter().map(|i| exp.space.vector(i)).collect())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pack::Packer;
    use statecheck_ir::assume::InputSpace;

    /// A counter that one event increments; the invariant fails when it reaches 5.
    fn program() -> statecheck_ir::Program {
        let text = "chart C {\n  input event inc;\n  output c: int[0..9] = 0;\n  initial S;\n  state S {\n    on inc [c < 9] / { c += 1; };\n  }\n}\nsystem Sys {\n  instance k: C;\n  invariant small: k.c < 5;\n}\n";
        let (file, _) = statecheck_syntax::parse(text);
        let (model, diags) = statecheck_model::check(&file);
        assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
        let sys = model.system("Sys").expect("system");
        statecheck_ir::lower(&model, sys).expect("lowers")
    }

    #[test]
    fn the_time_budget_bounds_reconstruction() {
        let p = program();
        let packer = Packer::new(&p);
        let mut space = InputSpace::new(&p);
        space.solve_static(&p);
        let mut specs = crate::props::all(&p);
        let mut init = statecheck_ir::Machine::new(&p);
        crate::props::mark_per_state(&p, &mut specs, |c| crate::expand::decides(&mut init, c));
        let exp = Expander {
            program: &p,
            packer: &packer,
            space: &space,
            specs: &specs,
            coverage: false,
            native: None,
            reduce: None,
            sym: None,
        };
        let s = search::<u64>(&exp, Limits::default(), None, None);
        // Tick 0 starts the chart; ticks 1..5 increment: c == 5 after tick 5, the 6th tick,
        // taken from a state of layer 5.
        assert_eq!(s.found[0].as_ref().map(|f| f.0), Some(5));
        let ok = rebuild::<u64>(&exp, &s.found, None, None);
        assert_eq!(ok[0].as_ref().map(Vec::len), Ok(6));
        // No time left after the exploration: nothing is searched, the reason is given.
        let none = rebuild::<u64>(&exp, &s.found, None, Some(Duration::ZERO));
        let why = none[0].as_ref().err().cloned().unwrap_or_default();
        assert!(why.contains("time limit"), "{why}");
        // A budget smaller than any block of the search: it stops after the first block
        // (layer 0) instead of going on to layer 5.
        let short = rebuild::<u64>(&exp, &s.found, None, Some(Duration::from_nanos(1)));
        let why = short[0].as_ref().err().cloned().unwrap_or_default();
        assert!(why.contains("time limit"), "{why}");
    }
}
