//! `statecheck synth` and `statecheck verify --plant` end to end on the Small Factory.

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_statecheck"))
}

fn example(name: &str) -> String {
    format!(
        "{}/../../examples/synthesis/{name}",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn synth_small_factory_then_verify() {
    let dir = std::env::temp_dir().join(format!("statecheck-synth-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out = dir.join("sup.sc");
    let model = example("small_factory.sc");
    let o = bin()
        .args([
            "synth",
            &model,
            "--system",
            "SmallFactoryRepair",
            "--check",
            "-o",
        ])
        .arg(&out)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(
        stdout.contains("supervisor: 12 states, 24 transitions"),
        "{stdout}"
    );
    assert!(stdout.contains("start1: in(buf.Empty)"), "{stdout}");
    assert!(stdout.contains("repair1: !in(m2.Down)"), "{stdout}");
    let o = bin()
        .arg("verify")
        .arg(&out)
        .args(["--plant", &model, "--plant-system", "SmallFactoryRepair"])
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("controllable, nonblocking"), "{stdout}");
    // The emitted system's own properties hold under the ordinary checker.
    let o = bin()
        .arg("verify")
        .arg(&out)
        .args(["--engine", "explicit", "-q"])
        .output()
        .expect("runs");
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    // And it goes through the code generators: C99 that compiles warning-free.
    let c_dir = dir.join("c");
    let o = bin()
        .args(["gen", "c"])
        .arg(&out)
        .args(["--harness", "-o"])
        .arg(&c_dir)
        .output()
        .expect("runs");
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    if Command::new("gcc").arg("--version").output().is_ok() {
        let o = Command::new("gcc")
            .args([
                "-std=c99",
                "-Wall",
                "-Wextra",
                "-Wpedantic",
                "-Werror",
                "-o",
            ])
            .arg(c_dir.join("h"))
            .arg(c_dir.join("supervised.c"))
            .arg(c_dir.join("supervised_harness.c"))
            .output()
            .expect("gcc runs");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn synth_reports_empty_supervisor() {
    let dir = std::env::temp_dir().join(format!("statecheck-synth-empty-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let model = dir.join("tank.sc");
    std::fs::write(
        &model,
        "plant chart Tank { controllable event fill; uncontrollable event leak; initial Low;\n\
         marked state Low { on fill -> High; on leak -> Empty; } state High { on leak -> Low; } state Empty; }\n\
         system S { instance t: Tank; requirement never (in(t.Empty)); }\n",
    )
    .expect("write");
    let o = bin()
        .args(["synth", "--engine", "symbolic"])
        .arg(&model)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(3), "{stdout}");
    assert!(stdout.contains("no supervisor exists"), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}
