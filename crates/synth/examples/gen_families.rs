//! Write the generated benchmark models into `examples/synthesis/`.
use statecheck_synth::families;
fn main() -> std::io::Result<()> {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "examples/synthesis".into());
    std::fs::write(
        format!("{dir}/philosophers_5.sc"),
        families::philosophers(5),
    )?;
    std::fs::write(format!("{dir}/line_4.sc"), families::line(4))?;
    std::fs::write(format!("{dir}/line_12.sc"), families::line(12))?;
    Ok(())
}
