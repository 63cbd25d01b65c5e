//! Regression tests for defects found by fuzzing and attack-minded use (issue 20), each named
//! after what it guards and running the `statecheck` binary on a model written by the test.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "statecheck-regression-{}-{tag}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn statecheck(dir: &Path, args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .args(args)
        .output()
        .expect("statecheck runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !stderr.contains("panicked") && !stderr.contains("overflowed its stack"),
        "crash: {stderr}"
    );
    out
}

const SMALL: &str = "chart M {\n  input event go;\n  output n: int[0..3] = 0;\n  initial A;\n  state A { on go / { n = 1; } -> B; }\n  state B;\n}\nsystem Sys { instance m: M; invariant bad: m.n == 0; }\n";

/// A chart whose state `S` has `n` internal transitions, each raising the next local event.
fn raise_chain(n: usize) -> String {
    let mut s = String::from("chart R {\n  input event go;\n");
    for k in 0..n {
        s.push_str(&format!("  local event e{k};\n"));
    }
    s.push_str(
        "  output last: int[0..1] = 0;\n  initial S;\n  state S {\n    on go / { raise e0; };\n",
    );
    for k in 1..n {
        s.push_str(&format!("    on e{} / {{ raise e{k}; }};\n", k - 1));
    }
    s.push_str(&format!(
        "    on e{} / {{ last = 1; }};\n  }}\n}}\nsystem Sys {{ instance a: R; }}\n",
        n - 1
    ));
    s
}

#[test]
fn raise_chain_code_is_linear_in_size_and_does_not_overflow_the_stack() {
    let d = temp_dir("raise");
    let mut sizes = Vec::new();
    for n in [1000usize, 2000, 7000] {
        std::fs::write(d.join(format!("r{n}.sc")), raise_chain(n)).expect("model");
        let c = statecheck(
            &d,
            &["gen", "c", &format!("r{n}.sc"), "-o", &format!("c{n}")],
        );
        assert_eq!(
            c.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&c.stderr)
        );
        let r = statecheck(
            &d,
            &["gen", "rust", &format!("r{n}.sc"), "-o", &format!("rs{n}")],
        );
        assert_eq!(
            r.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&r.stderr)
        );
        let p = statecheck(
            &d,
            &[
                "export",
                "promela",
                &format!("r{n}.sc"),
                "-o",
                &format!("p{n}.pml"),
            ],
        );
        assert_eq!(
            p.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&p.stderr)
        );
        let len = |p: PathBuf| std::fs::metadata(p).expect("output").len() as f64;
        sizes.push([
            len(d.join(format!("c{n}/sys.c"))),
            len(d.join(format!("rs{n}/sys.rs"))),
            len(d.join(format!("p{n}.pml"))),
        ]);
    }
    // Doubling the chain (1,000 -> 2,000 events) at most a little over doubles each output
    // (4,000 events once gave 162 MB of C: the nesting of `else { if ..` grew the indent).
    for (t, (a, b)) in sizes[0].iter().zip(&sizes[1]).enumerate() {
        assert!(b / a < 2.2, "target {t}: {a} -> {b} bytes");
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn generated_c_compiles_without_tautological_compare_errors() {
    // `(x | 4) != 1` is always true for x in 0..3; gcc 12 rejected the generated C with
    // -Werror=tautological-compare.
    let d = temp_dir("tautology");
    let model = "chart M {\n  input x: int[0..3] = 0;\n  output y: bool = false;\n  output z: bool = false;\n  initial S;\n  state S { during { y = (x | 4) != 1; z = (x & 4) == 4; } }\n}\nsystem Sys { instance m: M; }\n";
    std::fs::write(d.join("t.sc"), model).expect("model");
    let g = statecheck(&d, &["gen", "c", "t.sc", "-o", "out"]);
    assert_eq!(
        g.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&g.stderr)
    );
    let cc = Command::new("gcc")
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-O1",
            "-c",
            "out/sys.c",
            "-o",
            "out/sys.o",
        ])
        .current_dir(&d)
        .output()
        .expect("gcc runs");
    assert!(
        cc.status.success(),
        "{}",
        String::from_utf8_lossy(&cc.stderr)
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn spin_accepts_long_actions_and_long_else_if_chains() {
    // 200 `else if`s in an entry action and in a transition action once gave SPIN's
    // "d_step sequence too long" / "inline text too long".
    let d = temp_dir("spin");
    let chain: String = std::iter::once("if x == 0 { y = 0; }".to_string())
        .chain((1..200).map(|k| format!(" else if x == {} {{ y = {}; }}", k % 4, k % 100)))
        .chain(std::iter::once(" else { y = 1; }".to_string()))
        .collect();
    let model = format!("chart M {{\n  input x: int[0..3] = 0;\n  output y: int[0..100] = 0;\n  initial S;\n  state S {{ on [x > 0] / {{ {chain} }}; entry {{ {chain} }} }}\n}}\nsystem Sys {{ instance m: M; }}\n");
    std::fs::write(d.join("m.sc"), model).expect("model");
    let e = statecheck(&d, &["export", "promela", "m.sc", "-o", "m.pml"]);
    assert_eq!(
        e.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&e.stderr)
    );
    let a = Command::new("spin")
        .args(["-a", "m.pml"])
        .current_dir(&d)
        .output()
        .expect("spin runs");
    let text =
        String::from_utf8_lossy(&a.stdout).into_owned() + &String::from_utf8_lossy(&a.stderr);
    assert!(
        a.status.success() && !text.contains("too long"),
        "spin -a: {text}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn spin_accepts_many_checked_divisions_in_one_action() {
    // Found by the differential fuzzer (crates/fuzz): 120 divisions by an input that may be 0,
    // each a check that restores 16 variables and jumps to the end of the tick, fit SPIN's
    // d_step by the old count (options and ends only) but not by SPIN's (every element:
    // 2048 at most), so `spin -a` failed with "d_step sequence too long".
    let d = temp_dir("spin-div");
    let vars: String = (0..16)
        .map(|k| format!("  output v{k}: int[0..9] = 1;\n"))
        .collect();
    let acts: String = (0..120).map(|k| format!("v{} = 9 / x; ", k % 16)).collect();
    let model = format!("chart M {{\n  input x: int[0..3] = 1;\n{vars}  initial S;\n  state S {{ on [x > 0] / {{ {acts}}}; }}\n}}\nsystem Sys {{ instance m: M; }}\n");
    std::fs::write(d.join("m.sc"), model).expect("model");
    let e = statecheck(&d, &["export", "promela", "m.sc", "-o", "m.pml"]);
    assert_eq!(
        e.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&e.stderr)
    );
    let a = Command::new("spin")
        .args(["-a", "m.pml"])
        .current_dir(&d)
        .output()
        .expect("spin runs");
    let text =
        String::from_utf8_lossy(&a.stdout).into_owned() + &String::from_utf8_lossy(&a.stderr);
    assert!(
        a.status.success() && !text.contains("too long"),
        "spin -a: {text}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn empty_output_paths_are_usage_errors() {
    let d = temp_dir("empty");
    std::fs::write(d.join("m.sc"), SMALL).expect("model");
    // `--cex-dir ""` once wrote `/bad.scn` at the filesystem root.
    let v = statecheck(&d, &["verify", "m.sc", "--cex-dir", ""]);
    assert_eq!(
        v.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&v.stderr)
    );
    let g = statecheck(&d, &["gen", "c", "m.sc", "-o", ""]);
    assert_eq!(
        g.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&g.stderr)
    );
    let o = statecheck(&d, &["dot", "m.sc", "-o", ""]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn dot_output_never_overwrites_the_input_model() {
    let d = temp_dir("dot");
    std::fs::write(d.join("m.sc"), SMALL).expect("model");
    let o = statecheck(&d, &["dot", "m.sc", "-o", "m.sc"]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(
        std::fs::read_to_string(d.join("m.sc")).expect("model"),
        SMALL
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[cfg(unix)]
#[test]
fn gen_c_replaces_a_symlink_in_the_output_directory_instead_of_following_it() {
    let d = temp_dir("symlink");
    std::fs::write(d.join("m.sc"), SMALL).expect("model");
    std::fs::write(d.join("victim.txt"), "keep me").expect("victim");
    std::fs::create_dir(d.join("out")).expect("out");
    std::os::unix::fs::symlink(d.join("victim.txt"), d.join("out/sys.c")).expect("symlink");
    let g = statecheck(&d, &["gen", "c", "m.sc", "-o", "out"]);
    assert_eq!(
        g.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&g.stderr)
    );
    assert_eq!(
        std::fs::read_to_string(d.join("victim.txt")).expect("victim"),
        "keep me"
    );
    let c = std::fs::read_to_string(d.join("out/sys.c")).expect("sys.c");
    assert!(c.starts_with("/* Generated by statecheck"));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn non_utf8_source_is_a_diagnostic_at_the_offending_byte() {
    let d = temp_dir("utf8");
    // Byte 0xE9 (Latin-1 `é`) at offset 12, on line 2 column 3.
    let mut bytes = b"// comment\n//".to_vec();
    bytes.push(0xE9);
    bytes.extend_from_slice(b"\nchart M { initial S; state S; }\n");
    std::fs::write(d.join("m.sc"), bytes).expect("model");
    let c = statecheck(&d, &["check", "m.sc"]);
    let err = String::from_utf8_lossy(&c.stderr);
    assert_eq!(c.status.code(), Some(1), "{err}");
    assert!(
        err.contains("E0005") && err.contains("m.sc:2:3") && err.contains("0xE9"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn many_unknown_names_on_one_scenario_line_print_the_line_once() {
    let d = temp_dir("scn");
    std::fs::write(d.join("m.sc"), SMALL).expect("model");
    let line: Vec<String> = (0..500).map(|k| format!("nope{k}")).collect();
    std::fs::write(d.join("s.scn"), format!("-\n{}\n", line.join(", "))).expect("scenario");
    let s = statecheck(&d, &["sim", "m.sc", "--scenario", "s.scn"]);
    let err = String::from_utf8_lossy(&s.stderr);
    assert_eq!(s.status.code(), Some(1), "{err}");
    // The first error of the line is shown with the line; the other 499 are counted.
    assert_eq!(err.matches("nope0, nope1").count(), 1, "{err}");
    assert!(err.contains("… and 499 more error(s) on line 2"), "{err}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn i64_min_in_a_scenario_replays() {
    // IC3 wrote `A.i = -9223372036854775808`, which `sim` then rejected. With it, `i / -1`
    // overflows: a run-time error at tick 1 (exit 1), not a rejected scenario.
    let d = temp_dir("min");
    let model = "chart M {\n  input i: int[-9223372036854775807 - 1..0] = 0;\n  output o: int[-10..10] = 0;\n  initial S;\n  state S { during { o = min(i / -1, 1); } }\n}\nsystem Sys { instance a: M; }\n";
    std::fs::write(d.join("m.sc"), model).expect("model");
    std::fs::write(d.join("s.scn"), "-\na.i = -9223372036854775808\n").expect("scenario");
    let s = statecheck(&d, &["sim", "m.sc", "--scenario", "s.scn"]);
    let all = String::from_utf8_lossy(&s.stdout).into_owned() + &String::from_utf8_lossy(&s.stderr);
    assert!(!all.contains("not a value of"), "{all}");
    assert!(all.contains("overflow"), "{all}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn no_c_compiler_outlives_verify() {
    // The explicit engine's `auto` backend compiles native successors in the background after
    // 0.3 s; a run that ended (here by its 1 s time limit, with the FAM far from explored)
    // once left gcc's `cc1` running and its temporary files in the cache. The compiler runs
    // in its own process group, which ends with the run.
    let d = temp_dir("cc-left");
    let cache = d.join("cache");
    std::fs::create_dir(&cache).expect("cache");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&cache, std::fs::Permissions::from_mode(0o700)).expect("mode");
    }
    let model = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fam/fam_system.sc");
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .args([
            "verify",
            model.to_str().expect("utf-8 path"),
            "--engine",
            "explicit",
            "--timeout",
            "1",
        ])
        .env("STATECHECK_CACHE_DIR", &cache)
        .output()
        .expect("runs");
    assert!(matches!(out.status.code(), Some(1 | 3)), "{out:?}");
    let left = Command::new("pgrep")
        .args(["-f", cache.to_str().expect("utf-8 path")])
        .output()
        .expect("pgrep runs");
    assert!(
        left.stdout.is_empty(),
        "compilers left running: {}",
        String::from_utf8_lossy(&left.stdout)
    );
    // Only finished libraries (and their sources) stay in the cache, no temporary files.
    let names: Vec<String> = std::fs::read_dir(&cache)
        .expect("cache")
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        names.iter().all(|n| n.matches('.').count() == 1),
        "temporary files left: {names:?}"
    );
    let _ = std::fs::remove_dir_all(&d);
}
