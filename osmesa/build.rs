//! Gives the library the SONAME of Mesa's (`libOSMesa.so.8`) and places
//! `libOSMesa.so.8` and `libOSMesa.so` in `<target>/<profile>/osmesa/`, as links
//! to the `libOSMesa.so` cargo writes into `<target>/<profile>/deps/` (every
//! build writes that one; `cargo test` does not copy it up to `<profile>/`).
//! That directory is what `LD_LIBRARY_PATH` names for programs built against
//! Mesa's OSMesa. `<target>/<profile>/egl/` holds the same library as
//! `libEGL.so.1`, `libGL.so.1` and `libOpenGL.so.0` (and their `.so` names),
//! for EGL programs (piglit, PyOpenGL with `PYOPENGL_PLATFORM=egl`).

use std::path::{Path, PathBuf};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libOSMesa.so.8");
    let Some(profile_dir) = profile_dir() else {
        println!("cargo:warning=could not locate the target directory; libOSMesa.so.8 links not made");
        return;
    };
    let dirs: [(&str, &[&str]); 2] = [
        ("osmesa", &["libOSMesa.so.8", "libOSMesa.so"]),
        (
            "egl",
            &[
                "libEGL.so.1",
                "libEGL.so",
                "libGL.so.1",
                "libGL.so",
                "libOpenGL.so.0",
                "libOpenGL.so",
            ],
        ),
    ];
    for (name, links) in dirs {
        let dir = profile_dir.join(name);
        if let Err(e) = link_dir(&dir, links) {
            println!("cargo:warning=could not make {}: {e}", dir.display());
        }
    }
}

/// `<target>/<profile>`: OUT_DIR is `<target>/<profile>/build/<pkg>-<hash>/out`.
fn profile_dir() -> Option<PathBuf> {
    let out = PathBuf::from(std::env::var_os("OUT_DIR")?);
    out.ancestors().nth(3).map(Path::to_path_buf)
}

fn link_dir(dir: &Path, links: &[&str]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for name in links {
        let link = dir.join(name);
        if std::fs::symlink_metadata(&link).is_ok() {
            std::fs::remove_file(&link)?;
        }
        std::os::unix::fs::symlink("../deps/libOSMesa.so", &link)?;
    }
    Ok(())
}
