//! Counterexample reconstruction: a second breadth-first search that keeps every layer with
//! parent links, up to the layer of the deepest deciding transition, then a walk back from
//! each deciding transition's source state.
//!
//! The layers of a breadth-first search are sets fixed by the model, so the source state of a
//! transition found in layer `d` of the exploration is in layer `d` of this search, and the
//! walk back gives a shortest path to it.

use crate::expand::{Expander, Found};
use crate::pack::Key;
use crate::search::{search, End, Limits};
use crate::Limit;

/// For each property: the input vectors of a shortest counterexample, when one was found and
/// could be rebuilt (`Err` says why not). Properties without a finding get `Err("")`.
pub(crate) fn rebuild<K: Key>(
    exp: &Expander,
    found: &[Option<(u64, Found<K>)>],
    max_memory: Option<u64>,
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
    };
    let limits = Limits {
        max_memory,
        ..Limits::default()
    };
    let s = search::<K>(&plain, limits, Some(deepest), None);
    let failed = match &s.end {
        End::Limit(l @ Limit::Memory(_)) => {
            Some(format!("counterexample not rebuilt: {}", l.describe()))
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
            let Some((states, _)) = s.layers.get(*layer as usize) else {
                return Err("counterexample not rebuilt: layer missing (internal error)".into());
            };
            let Some(mut pos) = states.iter().position(|k| *k == f.parent) else {
                return Err("counterexample not rebuilt: state missing (internal error)".into());
            };
            let mut inputs = vec![u128::from(f.input)];
            for d in (1..=*layer as usize).rev() {
                let (parent, input) = s.layers[d].1[pos];
                inputs.push(u128::from(input));
                pos = parent as usize;
            }
            inputs.reverse();
            Ok(inputs.into_iter().map(|i| exp.space.decode(i)).collect())
        })
        .collect()
}
