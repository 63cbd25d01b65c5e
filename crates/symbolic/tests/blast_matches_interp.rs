//! The bit-blasted circuit must do exactly what the interpreter does.
//!
//! For every model in `tests/` and `examples/` (every system of each), random input sequences
//! run through `Machine::step` and through a concrete simulation of the AIG (its own latches,
//! from its reset state): after every tick the decoded latches equal the machine's state, the
//! error outputs say exactly which built-in property the machine's error violates (or none),
//! and the assumption and property outputs equal the interpreter's reading of them.

use statecheck_ir::{lower, Machine, PropertyKind};
use statecheck_symbolic::aig::lit_val;
use statecheck_symbolic::blast::blast;
use std::path::{Path, PathBuf};

fn models(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            models(&p, out);
        } else if p.extension().is_some_and(|e| e == "sc") {
            out.push(p);
        }
    }
}

fn holds(m: &mut Machine, e: u32) -> bool {
    matches!(m.eval(e), Ok(v) if v != 0)
}

#[test]
fn circuit_matches_the_interpreter_on_every_model() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    models(&root.join("tests"), &mut files);
    models(&root.join("examples"), &mut files);
    let mut rng = 11u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    let builtins = ["no_range_overflow", "no_division_by_zero", "no_bad_shift"];
    let (mut systems, mut ticks, mut errors) = (0, 0, 0);
    for f in &files {
        let src = std::fs::read_to_string(f).expect("readable");
        // Follow imports (examples/fam's models import lib/).
        let program = statecheck_model::imports::load_with(&f.to_string_lossy(), src, |k| {
            std::fs::read_to_string(k).ok()
        });
        let (model, d2) = statecheck_model::check(&program.file);
        if program.diags.iter().chain(&d2).any(|d| d.is_error()) {
            continue;
        }
        for sys in &model.systems {
            let Ok(p) = lower(&model, sys) else { continue };
            systems += 1;
            let bl = blast(&p);
            let g = &bl.aig;
            for _run in 0..20 {
                let mut m = Machine::new(&p);
                let mut latches = g.reset_state();
                for tick in 0..60 {
                    let mut ins = vec![false; g.inputs.len()];
                    let mut vals = Vec::new();
                    for (k, inp) in p.inputs.iter().enumerate() {
                        let s = &p.slots[inp.slot as usize];
                        // Favour the bounds (where the errors are), else uniform.
                        let r = next();
                        let v = match r % 4 {
                            0 => s.lo,
                            1 => s.hi,
                            _ => s.lo + ((r >> 2) % ((s.hi - s.lo + 1) as u64)) as i64,
                        };
                        m.set(inp.slot, v);
                        vals.push(v);
                        let enc = &bl.inputs[k];
                        for (b, x) in enc.bits.iter().zip(enc.encode(v)) {
                            ins[g.nodes[b.var() as usize].input_index()] = x;
                        }
                    }
                    let sim = g.simulate(&ins, &latches);
                    let at = format!("{}: system {}: tick {tick}", f.display(), sys.name);
                    for (k, inp) in p.inputs.iter().enumerate() {
                        assert_eq!(
                            bl.post[inp.slot as usize].value(&sim),
                            i128::from(vals[k]),
                            "{at}: input decoding"
                        );
                    }
                    let want_assume = p.assumes.iter().all(|a| holds(&mut m, *a));
                    assert_eq!(lit_val(&sim, bl.assume), want_assume, "{at}: assume");
                    let outcome = m.step();
                    ticks += 1;
                    match &outcome {
                        Err(e) => {
                            errors += 1;
                            let k = builtins
                                .iter()
                                .position(|b| *b == e.kind.builtin_property())
                                .expect("a built-in");
                            for (j, l) in bl.errs.iter().enumerate() {
                                assert_eq!(lit_val(&sim, *l), j == k, "{at}: error {e:?}");
                            }
                            break;
                        }
                        Ok(()) => {
                            for l in &bl.errs {
                                assert!(!lit_val(&sim, *l), "{at}: spurious error output");
                            }
                        }
                    }
                    for (i, s) in bl.state.iter().enumerate() {
                        let nv: Vec<bool> = s
                            .bits
                            .iter()
                            .map(|l| {
                                if l.var() == 0 {
                                    return l.is_neg();
                                }
                                let li = g.nodes[l.var() as usize].latch_index();
                                lit_val(&sim, g.latches[li].next)
                            })
                            .collect();
                        let mut v: i128 = 0;
                        for (j, b) in nv.iter().enumerate() {
                            if *b {
                                v |= 1 << j;
                            }
                        }
                        let w = nv.len();
                        if (v >> (w - 1)) & 1 == 1 {
                            v -= 1 << w;
                        }
                        assert_eq!(
                            v,
                            i128::from(m.state()[i]),
                            "{at}: slot {}",
                            p.slots[i].name
                        );
                    }
                    for (pi, prop) in p.properties.iter().enumerate() {
                        let want = match &prop.kind {
                            PropertyKind::Invariant { expr, assuming } => {
                                assuming.is_none_or(|a| holds(&mut m, a)) && !holds(&mut m, *expr)
                            }
                            PropertyKind::Reachable { expr } => holds(&mut m, *expr),
                            PropertyKind::Respond { ok, .. }
                            | PropertyKind::Observer { ok, .. } => !holds(&mut m, *ok),
                        };
                        assert_eq!(
                            lit_val(&sim, bl.props[pi].bad),
                            want,
                            "{at}: property {}",
                            prop.name
                        );
                    }
                    latches = g.latches.iter().map(|l| lit_val(&sim, l.next)).collect();
                }
            }
        }
    }
    assert!(systems >= 10, "only {systems} systems checked");
    eprintln!("{systems} systems, {ticks} ticks, {errors} run-time errors compared");
}
