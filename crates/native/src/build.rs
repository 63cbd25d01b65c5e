//! Compiling a generated successor generator into a shared library, with a cache.
//!
//! The compiler is `$CC`, else `cc`. Libraries are cached in `$STATECHECK_CACHE_DIR`, else
//! `$XDG_CACHE_HOME/statecheck/native`, else `~/.cache/statecheck/native`, under the hash of
//! the source and the compiler command. A library is loaded and run from there, so the
//! directory must be private: it is created with mode 0700, one that others can write to is
//! refused, and without any of the three variables there is no cache and no native code (the
//! engine runs the interpreter and says why; never the shared temp directory). The
//! source is stored beside its library and compared in full before a cached library is used,
//! so a hash collision costs a compilation, never a wrong library. A library is written under
//! a temporary name and renamed into place, so concurrent runs never load half a file.

use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Flags of every compilation (the generated code is C99; warnings are not for the user).
/// Hidden visibility (only `sc_expand` is exported) lets the compiler inline the step function.
const FLAGS: [&str; 6] = [
    "-std=gnu99",
    "-O2",
    "-fPIC",
    "-shared",
    "-fvisibility=hidden",
    "-w",
];

/// The compiler command.
fn compiler() -> String {
    std::env::var("CC")
        .ok()
        .filter(|c| !c.trim().is_empty())
        .unwrap_or_else(|| "cc".to_string())
}

/// The cache directory: the user's own (a library is loaded and run from here, so never a
/// directory that others can write to).
fn cache_dir() -> Result<PathBuf, String> {
    let var = |v: &str| {
        std::env::var_os(v)
            .filter(|x| !x.is_empty())
            .map(PathBuf::from)
    };
    var("STATECHECK_CACHE_DIR")
        .or_else(|| var("XDG_CACHE_HOME").map(|d| d.join("statecheck/native")))
        .or_else(|| var("HOME").map(|d| d.join(".cache/statecheck/native")))
        .ok_or_else(|| {
            "no private cache directory for native code (set STATECHECK_CACHE_DIR, XDG_CACHE_HOME or HOME)".to_string()
        })
}

/// Create `dir` (mode 0700 where it is new) and check that only its owner can write to it.
fn private_dir(dir: &Path) -> Result<(), String> {
    let mut builder = std::fs::DirBuilder::new();
    builder.recursive(true);
    #[cfg(unix)]
    std::os::unix::fs::DirBuilderExt::mode(&mut builder, 0o700);
    builder
        .create(dir)
        .map_err(|e| format!("cannot create the cache directory {}: {e}", dir.display()))?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let meta = std::fs::symlink_metadata(dir)
            .map_err(|e| format!("cannot read the cache directory {}: {e}", dir.display()))?;
        if !meta.is_dir() || meta.permissions().mode() & 0o022 != 0 {
            return Err(format!(
                "the cache directory {} is not a private directory (others can write to it); no native code is loaded from it",
                dir.display()
            ));
        }
    }
    Ok(())
}

/// The path of a shared library built from `source`, compiling it unless the cache has it.
pub(crate) fn library(source: &str) -> Result<PathBuf, String> {
    let cc = compiler();
    let mut h = std::collections::hash_map::DefaultHasher::new();
    source.hash(&mut h);
    cc.hash(&mut h);
    FLAGS.hash(&mut h);
    let stem = format!("sc_{:016x}", h.finish());
    let dir = cache_dir()?;
    private_dir(&dir)?;
    let c_path = dir.join(format!("{stem}.c"));
    let lib_path = dir.join(format!("{stem}.{}", std::env::consts::DLL_EXTENSION));
    let cached =
        lib_path.exists() && std::fs::read_to_string(&c_path).is_ok_and(|text| text == source);
    if cached {
        return Ok(lib_path);
    }
    let unique = format!(
        "{stem}.{}.{}",
        std::process::id(),
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos())
    );
    let tmp_c = dir.join(format!("{unique}.c"));
    let tmp_lib = dir.join(format!("{unique}.tmp"));
    std::fs::write(&tmp_c, source).map_err(|e| format!("cannot write {}: {e}", tmp_c.display()))?;
    let result = compile(&cc, &tmp_c, &tmp_lib);
    let placed = result.and_then(|()| {
        std::fs::rename(&tmp_lib, &lib_path)
            .and_then(|()| std::fs::rename(&tmp_c, &c_path))
            .map_err(|e| format!("cannot place {}: {e}", lib_path.display()))
    });
    let _ = std::fs::remove_file(&tmp_c);
    let _ = std::fs::remove_file(&tmp_lib);
    placed.map(|()| lib_path)
}

#[cfg(unix)]
use std::os::unix::process::CommandExt as _;

/// Compilers still running, by a number of our own: [`kill_compilers`] ends them when the
/// run ends (a `verify` that returns must not leave gcc behind; found by issue 20's limits
/// check).
static RUNNING: std::sync::Mutex<Vec<Running>> = std::sync::Mutex::new(Vec::new());

/// A compiler in [`RUNNING`]: our number for it, the child (the leader of its own process
/// group, so that its own children, `cc1` and `as`, end with it) and the files it writes.
type Running = (u64, std::process::Child, Vec<std::path::PathBuf>);

/// Kill `c` and every process of its group (the driver's `cc1`, `as`, `ld`), and reap it.
fn kill_group(c: &mut std::process::Child) {
    // `kill -KILL -- -PGID`: the group of a child we started in its own group (no `unsafe`).
    let _ = Command::new("kill")
        .args(["-KILL", "--", &format!("-{}", c.id())])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status();
    let _ = c.kill();
    let _ = c.wait();
}

/// The next number for [`RUNNING`].
static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// Kill every compiler this process started that is still running (and reap it). Later
/// compiles still start; call this when the run ends.
pub fn kill_compilers() {
    let mut running = RUNNING.lock().unwrap_or_else(|e| e.into_inner());
    for (_, c, files) in running.iter_mut() {
        kill_group(c);
        for f in files.iter() {
            let _ = std::fs::remove_file(f);
        }
    }
    running.clear();
}

/// Run the compiler on one file (its diagnostics go to a file beside the output, so that a
/// full pipe never blocks it); the child is registered in [`RUNNING`] while it runs.
fn compile(cc: &str, c: &Path, lib: &Path) -> Result<(), String> {
    let err_path = lib.with_extension("stderr");
    let err_file = std::fs::File::create(&err_path)
        .map_err(|e| format!("cannot create {}: {e}", err_path.display()))?;
    let mut cmd = Command::new(cc);
    #[cfg(unix)]
    cmd.process_group(0);
    let child = cmd
        .args(FLAGS)
        .arg("-o")
        .arg(lib)
        .arg(c)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(err_file)
        .spawn()
        .map_err(|e| format!("cannot run the C compiler `{cc}`: {e}"))?;
    let id = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    RUNNING.lock().unwrap_or_else(|e| e.into_inner()).push((
        id,
        child,
        vec![c.to_path_buf(), lib.to_path_buf(), err_path.clone()],
    ));
    let status = loop {
        let mut running = RUNNING.lock().unwrap_or_else(|e| e.into_inner());
        let Some(k) = running.iter().position(|(i, _, _)| *i == id) else {
            break None; // killed by `kill_compilers`
        };
        match running[k].1.try_wait() {
            Ok(Some(st)) => {
                running.swap_remove(k);
                break Some(st);
            }
            Ok(None) => {}
            Err(_) => {
                let (_, mut c, _) = running.swap_remove(k);
                kill_group(&mut c);
                break None;
            }
        }
        drop(running);
        std::thread::sleep(std::time::Duration::from_millis(10));
    };
    let err = std::fs::read_to_string(&err_path).unwrap_or_default();
    let _ = std::fs::remove_file(&err_path);
    let Some(status) = status else {
        return Err(format!("the C compiler `{cc}` was stopped"));
    };
    if status.success() {
        return Ok(());
    }
    let first: Vec<&str> = err.lines().take(5).collect();
    Err(format!(
        "the C compiler `{cc}` failed ({status}): {}",
        first.join(" | ")
    ))
}
