//! What piglit's GL 1.x groups found missing in softgl (issue 15), each
//! checked against Mesa's llvmpipe by a C client built once and run on both
//! (as `clients.rs` does): `tests/c/gaps15.c` through OSMesa. A missing
//! reference prints one `SKIPPED ...` line and passes, unless
//! `SOFTGL_REQUIRE_REFERENCES=1` (`tests/needs`).

use std::path::{Path, PathBuf};
use std::process::Command;

mod needs;
use needs::{have, profile_dir, work_dir, Need};

/// Builds `tests/c/<name>.c` with `libs`; `None` (skipped) without the references.
fn build(name: &str, needs: &[Need], libs: &[&str]) -> Option<PathBuf> {
    if !have(&format!("C client {name}.c"), needs) {
        return None;
    }
    let exe = work_dir(&format!("gaps-bin-{name}")).join(name);
    let out = Command::new("cc")
        .arg("-O1")
        .arg("-o")
        .arg(&exe)
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/c/{name}.c")))
        .args(libs)
        .output()
        .expect("run cc");
    assert!(
        out.status.success(),
        "building {name}.c failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(exe)
}

/// Runs `exe` with `LD_LIBRARY_PATH` at `lib` (softgl) or unset (Mesa); its stdout lines.
fn run(exe: &Path, lib: Option<&Path>, what: &str) -> Vec<String> {
    let dir = work_dir(&format!("gaps-{what}"));
    let mut cmd = Command::new(exe);
    cmd.arg(&dir)
        .env_remove("LD_LIBRARY_PATH")
        .env("GALLIUM_DRIVER", "llvmpipe");
    if let Some(lib) = lib {
        cmd.env("LD_LIBRARY_PATH", lib);
    }
    let out = cmd.output().expect("run the client");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "{what} failed: {}\n{stdout}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<String> = stdout.lines().map(str::to_owned).collect();
    assert_eq!(lines.last().map(String::as_str), Some("done"), "{what}:\n{stdout}");
    lines
}

#[test]
fn multi_draw_errors_null_subimages_and_index_textures_match_mesa() {
    let Some(exe) = build("gaps15", &[Need::Cc, Need::OsMesa], &["-lOSMesa", "-ldl"]) else {
        return;
    };
    let mesa = run(&exe, None, "gaps15-mesa");
    let soft = run(&exe, Some(&profile_dir().join("osmesa")), "gaps15-softgl");
    // Line 0 names the library; every error, pixel and texel after it is Mesa's.
    assert!(soft[0].contains(&*profile_dir().to_string_lossy()), "{}", soft[0]);
    assert_eq!(soft[1..], mesa[1..]);
    assert!(soft.iter().any(|l| l == "  called: 255 0 0 255"), "{soft:?}");
    assert_eq!(soft.len(), 35);
}
