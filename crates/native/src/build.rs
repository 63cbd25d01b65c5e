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

/// Run the compiler on one file.
fn compile(cc: &str, c: &Path, lib: &Path) -> Result<(), String> {
    let out = Command::new(cc)
        .args(FLAGS)
        .arg("-o")
        .arg(lib)
        .arg(c)
        .output()
        .map_err(|e| format!("cannot run the C compiler `{cc}`: {e}"))?;
    if out.status.success() {
        return Ok(());
    }
    let err = String::from_utf8_lossy(&out.stderr);
    let first: Vec<&str> = err.lines().take(5).collect();
    Err(format!(
        "the C compiler `{cc}` failed ({}): {}",
        out.status,
        first.join(" | ")
    ))
}
