//! What the explicit engine's tests share: the counters model whose counts are derived by
//! hand (`n` independent modulo-(m+1) counters, at most one incremented per tick: (m+1)^n
//! states after tick 0 plus the pre-start state; `pad` wide padding variables per counter
//! never change, so they only widen the packed vector, by 40 bits each).

/// The lowered counters model (system `S`, invariant `not_all_max`).
pub fn program(n: usize, m: usize, pad: usize) -> statecheck_ir::Program {
    let pads: String = (0..pad)
        .map(|i| format!("  local pad{i}: int[0..1000000000000] = 7;\n"))
        .collect();
    let pairs: Vec<String> = (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| format!("!(k[{i}].inc && k[{j}].inc)")))
        .collect();
    let text = format!(
        "chart Counter {{\n  input event inc;\n  output c: int[0..{m}] = 0;\n{pads}  initial Run;\n  state Run {{\n    on inc [c < {m}] / {{ c += 1; }};\n    on inc / {{ c = 0; }};\n  }}\n}}\nsystem S {{\n  instance k[{n}]: Counter;\n  assume {};\n  invariant not_all_max: !({});\n}}\n",
        pairs.join(" && "),
        (0..n).map(|i| format!("k[{i}].c == {m}")).collect::<Vec<_>>().join(" && ")
    );
    let (file, d1) = statecheck_syntax::parse(&text);
    let (model, d2) = statecheck_model::check(&file);
    assert!(
        !d1.iter().chain(&d2).any(|d| d.is_error()),
        "{text}\n{d1:?}{d2:?}"
    );
    let sys = model.system("S").expect("system S");
    statecheck_ir::lower(&model, sys).expect("lowers")
}
