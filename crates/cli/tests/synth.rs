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

/// `statecheck verify SUP --plant MODEL EXTRA…`: asserts exit 0 and returns standard output.
fn verify_plant(sup: &std::path::Path, model: &str, extra: &[&str]) -> String {
    let o = bin()
        .arg("verify")
        .arg(sup)
        .args(["--plant", model])
        .args(extra)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    stdout
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
    let stdout = verify_plant(&out, &model, &["--plant-system", "SmallFactoryRepair"]);
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

/// A scratch directory for one test.
fn scratch(tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-synth-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

#[test]
fn supervisor_of_a_large_instance_reloads_and_verifies() {
    // The line of 7 machines: 3^7 * 2^6 = 139 968 product states, all reachable (no `never`
    // requirement, so no state is left unexpanded); supervisor 3 * 4^6 = 12 288 states
    // (derivation in `families::line`).
    let dir = scratch("line7");
    let model = dir.join("line_7.sc");
    std::fs::write(&model, statecheck_synth::families::line(7)).expect("write");
    let out = dir.join("sup.sc");
    let o = bin()
        .args(["synth", "-q"])
        .arg(&model)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("product 1.400e5"), "{stdout}");
    assert!(stdout.contains("supervisor 12288 states"), "{stdout}");
    let stdout = verify_plant(&out, &model.to_string_lossy(), &[]);
    assert!(stdout.contains("(12288 plant states)"), "{stdout}");
    assert!(stdout.contains("controllable, nonblocking"), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn closed_stdout_neither_panics_nor_loses_the_output_file() {
    let dir = scratch("pipe");
    let out = dir.join("sup.sc");
    let mut child = bin()
        .args([
            "synth",
            &example("small_factory.sc"),
            "--system",
            "SmallFactory",
            "-o",
        ])
        .arg(&out)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("runs");
    // Close the read end at once, as `| head -0` would.
    drop(child.stdout.take());
    let o = child.wait_with_output().expect("waits");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let text = std::fs::read_to_string(&out).expect("the -o file is written");
    assert!(text.contains("system Supervised"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `u` is uncontrollable and leads from the initial state A to D, where nothing can happen
/// and which is not marked; B is the only marked state. So A must go, and no supervisor
/// exists; no requirement is violated on the way, so the explanation is a blocking witness:
/// the trace `u` to D.
const BLOCKING: &str = "plant chart P { controllable event c; uncontrollable event u; initial A;\n\
    state A { on c -> B; on u -> D; } marked state B; state D; }\n\
    system S { instance p: P; }\n";

#[test]
fn no_supervisor_has_a_witness_and_is_one_line_with_q() {
    let dir = scratch("blocking");
    let model = dir.join("blocking.sc");
    std::fs::write(&model, BLOCKING).expect("write");
    for engine in ["explicit", "symbolic"] {
        let o = bin()
            .args(["synth", "--engine", engine])
            .arg(&model)
            .output()
            .expect("runs");
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(3), "{stdout}");
        assert!(stdout.contains("no supervisor exists"), "{stdout}");
        assert!(
            stdout.contains("witness: the event trace u reaches (p.D)"),
            "{stdout}"
        );
        let o = bin()
            .args(["synth", "-q", "--engine", engine])
            .arg(&model)
            .output()
            .expect("runs");
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(3), "{stdout}");
        assert_eq!(stdout.lines().count(), 1, "{stdout}");
        // Product: A, B and D are reachable.
        assert!(
            stdout.starts_with(&format!("{engine} "))
                && stdout.contains("product 3.000e0 no supervisor"),
            "{stdout}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn limits_end_with_unknown_and_exit_3() {
    let dir = scratch("limits");
    let model = dir.join("line_8.sc");
    // 3^8 * 2^7 = 839 808 reachable product states: far more than 1000.
    std::fs::write(&model, statecheck_synth::families::line(8)).expect("write");
    let o = bin()
        .args(["synth", "--engine", "explicit", "--max-states", "1000"])
        .arg(&model)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(3), "{stdout}");
    assert!(
        stdout
            .starts_with("unknown: the state limit (1000 states) was reached during reachability"),
        "{stdout}"
    );
    // A bad limit is a usage error.
    let o = bin()
        .args(["synth", "--timeout", "-1"])
        .arg(&model)
        .output()
        .expect("runs");
    assert_eq!(o.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Event renaming end to end: `philosophers_5_renamed.sc` (one `Phil` and one `Fork` chart,
/// ten renaming instances) gives the 81-state, 260-transition supervisor of the copied-chart
/// `philosophers_5.sc` (docs/synthesis.md), and the written supervisor re-reads and passes
/// `verify --plant` against the renamed model, whose 81 plant states it visits.
#[test]
fn renamed_instances_synthesize_and_verify() {
    let dir = scratch("renamed");
    let model = example("philosophers_5_renamed.sc");
    let out = dir.join("sup.sc");
    let o = bin()
        .args(["synth", "-q", &model, "-o"])
        .arg(&out)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(
        stdout.contains("supervisor 81 states 260 transitions"),
        "{stdout}"
    );
    let text = std::fs::read_to_string(&out).expect("supervisor written");
    assert!(
        text.contains("Event.take0l"),
        "renamed events in the supervisor"
    );
    let stdout = verify_plant(&out, &model, &[]);
    assert!(stdout.contains("(81 plant states)"), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}
