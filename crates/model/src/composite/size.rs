//! The number of chart instances a system flattens to, computed before flattening from each
//! component's own count (memoised, so linear in the file even when the hierarchy multiplies
//! to billions), so a system too big to flatten is refused at once (E0174) with its count.

use super::MAX_INSTANCES;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;
use std::collections::HashMap;

/// The leaf instances of `body`, saturating; a component met again while its own count is
/// being computed (a cycle, reported by the flattening) counts 0.
fn count<'a>(
    body: &'a ast::System,
    comps: &HashMap<&'a str, &'a ast::Component>,
    memo: &mut HashMap<&'a str, Option<u64>>,
    depth: usize,
) -> u64 {
    let mut total: u64 = 0;
    for inst in &body.instances {
        // A chart instance array's length is checked later (at most 4096 elements); an
        // array of components has a literal length by now (`component_params.rs`).
        let n = match &inst.count {
            Some(ast::Expr::Int(n, _)) => (*n).clamp(1, i64::MAX) as u64,
            _ => 1,
        };
        let each = match comps.get(inst.chart.name.as_str()) {
            None => 1,
            Some(c) => match memo.get(c.name.name.as_str()) {
                Some(Some(k)) => *k,
                Some(None) => 0,
                None if depth > super::MAX_DEPTH => 0,
                None => {
                    memo.insert(c.name.name.as_str(), None);
                    let k = count(&c.body, comps, memo, depth + 1);
                    memo.insert(c.name.name.as_str(), Some(k));
                    k
                }
            },
        };
        total = total.saturating_add(n.saturating_mul(each));
    }
    total
}

/// True (after reporting E0174 to `diags`, when given) when `body` flattens to more than
/// [`MAX_INSTANCES`] chart instances.
pub(super) fn too_big<'a>(
    body: &'a ast::System,
    comps: &HashMap<&'a str, &'a ast::Component>,
    memo: &mut HashMap<&'a str, Option<u64>>,
    diags: Option<&mut Vec<Diagnostic>>,
) -> bool {
    let n = count(body, comps, memo, 0);
    if n <= MAX_INSTANCES as u64 {
        return false;
    }
    let Some(diags) = diags else {
        return true;
    };
    let shown = if n == u64::MAX {
        "more than 18446744073709551614".to_string()
    } else {
        n.to_string()
    };
    diags.push(
        Diagnostic::error(
            "E0174",
            format!(
                "`{}` flattens to {shown} chart instances, more than the limit of {MAX_INSTANCES}",
                body.name.name
            ),
            body.name.span,
        )
        .with_label("too many instances once its components are flattened")
        .with_hint(
            "components multiply: each instance of a component holds all of its instances; \
             nest fewer levels or fewer instances per component",
        ),
    );
    true
}
