//! Write the generated benchmark models into `examples/synthesis/`, or one instance:
//! `gen_families [DIR]`, `gen_families philosophers|line N OUT.sc` or
//! `gen_families tl|dp|cm|at|bw|ta N K OUT.sc` (`families::scaled`).
use statecheck_synth::families;
fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let [family, n, k, out] = args.as_slice() {
        let n: usize = n.parse().map_err(std::io::Error::other)?;
        let k: usize = k.parse().map_err(std::io::Error::other)?;
        let text = families::scaled::generate(family, n, k)
            .ok_or_else(|| std::io::Error::other("tl|dp|cm|at|bw|ta N K (N, K >= 1) OUT"))?;
        return std::fs::write(out, text);
    }
    if let [family, n, out] = args.as_slice() {
        let n: usize = n.parse().map_err(std::io::Error::other)?;
        let text = match family.as_str() {
            "philosophers" if n >= 2 => families::philosophers(n),
            "line" if n >= 2 => families::line(n),
            _ => return Err(std::io::Error::other("philosophers|line N (N >= 2) OUT")),
        };
        return std::fs::write(out, text);
    }
    let dir = args
        .first()
        .cloned()
        .unwrap_or_else(|| "examples/synthesis".into());
    std::fs::write(
        format!("{dir}/philosophers_5.sc"),
        families::philosophers(5),
    )?;
    std::fs::write(format!("{dir}/line_4.sc"), families::line(4))?;
    std::fs::write(format!("{dir}/line_12.sc"), families::line(12))?;
    Ok(())
}
