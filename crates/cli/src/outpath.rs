//! Writing output files safely: an empty path is a usage error; a file is written to a
//! temporary file created fresh in the target's directory and renamed over the target, so a
//! reader never sees half a file and a symbolic link at the target (or planted in an output
//! directory) is replaced, never followed; no output may overwrite a file the command read.

use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Files this run has read (model, scenario, coverage), which no output may overwrite.
static INPUTS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Remember that `path` is an input of this run.
pub fn note_input(path: &str) {
    if let Ok(mut v) = INPUTS.lock() {
        v.push(PathBuf::from(path));
    }
}

/// A usable output path: not empty, no NUL byte. Errors are usage errors (exit 2).
pub fn check(path: &str, what: &str) -> Result<()> {
    if path.trim().is_empty() {
        bail!("the {what} path is empty; give a file or directory name");
    }
    if path.contains('\0') {
        bail!("the {what} path contains a NUL byte");
    }
    Ok(())
}

/// True when `a` and `b` name the same existing file.
fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(x), Ok(y)) => {
            #[cfg(unix)]
            {
                use std::os::unix::fs::MetadataExt;
                x.dev() == y.dev() && x.ino() == y.ino()
            }
            #[cfg(not(unix))]
            {
                let _ = (x, y);
                matches!((a.canonicalize(), b.canonicalize()), (Ok(p), Ok(q)) if p == q)
            }
        }
        _ => false,
    }
}

/// Create an output directory (and its parents) after checking its path.
pub fn create_dir(dir: &str, what: &str) -> Result<PathBuf> {
    check(dir, what)?;
    let p = PathBuf::from(dir);
    std::fs::create_dir_all(&p).with_context(|| format!("cannot create `{dir}`"))?;
    Ok(p)
}

/// Write `bytes` to `path` atomically: a fresh temporary file beside it (created with
/// `create_new`, which fails on any existing name, links included), then a rename over
/// `path` (which replaces a link there instead of writing through it). Refuses to replace a
/// file this run read.
pub fn write(path: &Path, bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let shown = path.display().to_string();
    check(&shown, "output")?;
    let inputs = INPUTS.lock().map(|v| v.clone()).unwrap_or_default();
    if let Some(inp) = inputs.iter().find(|i| same_file(i, path)) {
        bail!(
            "refusing to overwrite `{}`, an input of this command, with the output `{shown}`",
            inp.display()
        );
    }
    let name = path
        .file_name()
        .with_context(|| format!("`{shown}` names no file"))?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let mut tmp = None;
    for k in 0..100u32 {
        let mut t = std::ffi::OsString::from(".");
        t.push(name);
        t.push(format!(".{}.{k}.tmp", std::process::id()));
        let candidate = dir.join(t);
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&candidate)
        {
            Ok(f) => {
                tmp = Some((candidate, f));
                break;
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e).with_context(|| format!("cannot write `{shown}`")),
        }
    }
    let Some((tmp_path, mut f)) = tmp else {
        bail!("cannot write `{shown}`: no free temporary name in its directory");
    };
    let done = f
        .write_all(bytes)
        .and_then(|()| f.sync_all())
        .and_then(|()| std::fs::rename(&tmp_path, path));
    if let Err(e) = done {
        let _ = std::fs::remove_file(&tmp_path);
        return Err(e).with_context(|| format!("cannot write `{shown}`"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("statecheck-outpath-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).expect("temp dir");
        d
    }

    #[test]
    fn empty_output_path_is_refused() {
        assert!(check("", "output").is_err());
        assert!(check("  ", "output").is_err());
        assert!(create_dir("", "--cex-dir").is_err());
        assert!(write(Path::new(""), b"x").is_err());
    }

    #[cfg(unix)]
    #[test]
    fn a_symlink_in_the_output_directory_is_replaced_not_followed() {
        let d = temp_dir("symlink");
        let victim = d.join("victim.txt");
        std::fs::write(&victim, "keep me").expect("victim");
        let out = d.join("out");
        std::fs::create_dir(&out).expect("out dir");
        std::os::unix::fs::symlink(&victim, out.join("sys.c")).expect("symlink");
        write(&out.join("sys.c"), b"generated").expect("write");
        assert_eq!(std::fs::read_to_string(&victim).expect("victim"), "keep me");
        assert_eq!(
            std::fs::read_to_string(out.join("sys.c")).expect("out"),
            "generated"
        );
        assert!(!std::fs::symlink_metadata(out.join("sys.c"))
            .expect("meta")
            .file_type()
            .is_symlink());
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn an_input_file_is_never_overwritten() {
        let d = temp_dir("input");
        let model = d.join("m.sc");
        std::fs::write(&model, "chart M { initial S; state S; }").expect("model");
        note_input(&model.display().to_string());
        // The same file by another spelling of its path.
        let other = d.join(".").join("m.sc");
        assert!(write(&other, b"digraph {}").is_err());
        assert_eq!(
            std::fs::read_to_string(&model).expect("model"),
            "chart M { initial S; state S; }"
        );
        let _ = std::fs::remove_dir_all(&d);
    }
}
