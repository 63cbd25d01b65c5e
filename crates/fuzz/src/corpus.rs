//! The seed corpus: the repository's own models (`examples/`, `tests/`) and scenarios, AIGER
//! files exported from small models, and the committed seeds of `crates/fuzz/corpus/<target>/`
//! (hand-written corner cases and inputs that once failed).

use crate::targets::{Context, Target};
use std::path::{Path, PathBuf};

/// One seed: its bytes and the context program it belongs to (scenario target).
#[derive(Clone, Debug)]
pub struct Seed {
    /// Index into [`Context::programs`] (0 for the other targets).
    pub ctx: usize,
    /// The input.
    pub bytes: Vec<u8>,
}

/// Files under `dir` (recursively, sorted) whose name ends with one of `exts`.
fn files(dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    let mut v: Vec<PathBuf> = rd.flatten().map(|e| e.path()).collect();
    v.sort();
    for p in v {
        let name = p.file_name().map(|n| n.to_string_lossy().into_owned());
        let name = name.unwrap_or_default();
        if p.is_dir() {
            if !(name.starts_with('.') || name.starts_with("target") || name == "node_modules") {
                files(&p, exts, out);
            }
        } else if exts.iter().any(|e| name.ends_with(e)) {
            out.push(p);
        }
    }
}

/// Largest seed file read (bytes).
const MAX_SEED: u64 = 64 * 1024;

fn read(p: &Path) -> Option<Vec<u8>> {
    let meta = std::fs::metadata(p).ok()?;
    if meta.len() > MAX_SEED {
        return None;
    }
    std::fs::read(p).ok()
}

/// Every system of the model file `path` (text `src`, its imports read relative to it).
fn lower_all(path: &Path, src: &str) -> Vec<statecheck_ir::Program> {
    let program =
        statecheck_model::imports::load_with(&path.to_string_lossy(), src.to_string(), |k| {
            std::fs::read_to_string(k).ok()
        });
    let (model, d2) = statecheck_model::check(&program.file);
    if program.diags.iter().chain(&d2).any(|d| d.is_error()) {
        return Vec::new();
    }
    model
        .systems
        .iter()
        .filter_map(|s| statecheck_ir::lower(&model, s).ok())
        .collect()
}

/// The model a scenario file belongs to: the `.sc` file in its folder or the folder above
/// whose name is the longest prefix of the scenario's name, else the one named after the
/// folder (`examples/fam/scenarios/x.scn` → `examples/fam/fam.sc`).
fn model_of(scn: &Path) -> Option<PathBuf> {
    let stem = scn.file_stem()?.to_string_lossy().into_owned();
    let dir = scn.parent()?;
    let mut best: Option<(usize, PathBuf)> = None;
    for d in [Some(dir), dir.parent()].into_iter().flatten() {
        let dname = d.file_name().map(|n| n.to_string_lossy().into_owned());
        let Ok(rd) = std::fs::read_dir(d) else {
            continue;
        };
        let mut v: Vec<PathBuf> = rd.flatten().map(|e| e.path()).collect();
        v.sort();
        for p in v
            .into_iter()
            .filter(|p| p.extension().is_some_and(|e| e == "sc"))
        {
            let s = p.file_stem().map(|n| n.to_string_lossy().into_owned());
            let s = s.unwrap_or_default();
            let score = if stem.starts_with(&s) {
                s.len() + 1
            } else if dname.as_deref() == Some(s.as_str()) {
                1
            } else {
                0
            };
            if score > 0 && best.as_ref().is_none_or(|b| score > b.0) {
                best = Some((score, p));
            }
        }
    }
    best.map(|b| b.1)
}

/// The context and seeds of `target`, from the repository at `root`.
pub fn load(target: Target, root: &Path) -> (Context, Vec<Seed>) {
    let mut ctx = Context::default();
    let mut seeds = Vec::new();
    let own = root.join("crates/fuzz/corpus").join(target.name());
    let mut paths = Vec::new();
    match target {
        Target::Check | Target::Fmt => {
            files(&root.join("examples"), &[".sc"], &mut paths);
            files(&root.join("tests"), &[".sc"], &mut paths);
            files(&own, &[".sc"], &mut paths);
            seeds.extend(
                paths
                    .iter()
                    .filter_map(|p| read(p))
                    .map(|bytes| Seed { ctx: 0, bytes }),
            );
        }
        Target::Scenario => {
            files(&root.join("examples"), &[".scn"], &mut paths);
            files(&root.join("tests"), &[".scn"], &mut paths);
            files(&own, &[".scn"], &mut paths);
            let mut models: Vec<(PathBuf, usize, usize)> = Vec::new();
            for scn in &paths {
                let Some(bytes) = read(scn) else { continue };
                let Some(m) = model_of(scn) else { continue };
                let range = match models.iter().find(|x| x.0 == m) {
                    Some(x) => (x.1, x.2),
                    None => {
                        let src = std::fs::read_to_string(&m).unwrap_or_default();
                        let start = ctx.programs.len();
                        ctx.programs.extend(lower_all(&m, &src));
                        models.push((m.clone(), start, ctx.programs.len()));
                        (start, ctx.programs.len())
                    }
                };
                // The system the scenario reads against (the first that accepts it).
                let text = String::from_utf8_lossy(&bytes);
                let which = (range.0..range.1)
                    .find(|&k| statecheck_sim::scenario::parse(&text, &ctx.programs[k]).is_ok())
                    .unwrap_or(range.0);
                if which < ctx.programs.len() {
                    seeds.push(Seed { ctx: which, bytes });
                }
            }
        }
        Target::Aiger => {
            files(&own, &[".aag", ".aig"], &mut paths);
            seeds.extend(
                paths
                    .iter()
                    .filter_map(|p| read(p))
                    .map(|bytes| Seed { ctx: 0, bytes }),
            );
            // Exports of the small semantic models: every problem, ASCII and binary.
            let mut sc = Vec::new();
            files(&root.join("tests/semantics"), &[".sc"], &mut sc);
            for p in sc {
                let src = std::fs::read_to_string(&p).unwrap_or_default();
                for prog in lower_all(&p, &src).iter().take(1) {
                    let Ok((bl, idx)) = statecheck_symbolic::check::problems(prog, &[]) else {
                        continue;
                    };
                    for &(pi, _) in idx.iter().take(2) {
                        let g = bl.problem(pi);
                        seeds.push(Seed {
                            ctx: 0,
                            bytes: statecheck_symbolic::aiger::ascii(&g, "seed"),
                        });
                        seeds.push(Seed {
                            ctx: 0,
                            bytes: statecheck_symbolic::aiger::binary(&g, "seed"),
                        });
                    }
                }
            }
        }
        Target::SelfTest => {
            for s in ["ok", "panic", "abort", "hang", "deep", "broken"] {
                seeds.push(Seed {
                    ctx: 0,
                    bytes: s.as_bytes().to_vec(),
                });
            }
        }
    }
    (ctx, seeds)
}
