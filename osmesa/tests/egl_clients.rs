//! Real EGL clients on softgl's `<profile>/egl/` directory: a C program built
//! against Khronos' EGL and Mesa's OSMesa headers renders `tests/c/formats.c`'s
//! scene through both faces of the library in one process (the bytes must be
//! equal), and a PyOpenGL script (`PYOPENGL_PLATFORM=egl`) draws and reads back.
//!
//! A C compiler with `libegl-dev` and `libosmesa6-dev`, and PyOpenGL: a test
//! that misses one prints one `SKIPPED ...` line and passes, or fails under
//! `SOFTGL_REQUIRE_REFERENCES=1` (`tests/needs`).

mod needs;
use needs::{have, Need};
use std::path::{Path, PathBuf};
use std::process::Command;

/// `<target>/<profile>/<name>` (build.rs makes `egl` and `osmesa`).
fn profile_subdir(name: &str) -> PathBuf {
    let exe = std::env::current_exe().expect("test executable path");
    let dir = exe
        .parent()
        .and_then(Path::parent)
        .expect("target profile dir")
        .join(name);
    assert!(dir.is_dir(), "{} is missing: build softgl-osmesa first", dir.display());
    dir
}

/// Runs `cmd`, asserting success; its stdout.
fn stdout_of(cmd: &mut Command, what: &str) -> String {
    let out = cmd.output().unwrap_or_else(|e| panic!("{what}: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{what} failed: {}\n{stdout}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

#[test]
fn the_formats_scene_is_the_same_bytes_through_egl_and_osmesa() {
    if !have("EGL client egl_scene.c", &[Need::Cc, Need::Egl, Need::OsMesa]) {
        return;
    }
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("egl-clients");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("work dir");
    let exe = dir.join("egl_scene");
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c/egl_scene.c");
    stdout_of(
        Command::new("cc")
            .args(["-O1", "-o"])
            .arg(&exe)
            .arg(&source)
            .args(["-lEGL", "-lOSMesa", "-ldl"]),
        "cc egl_scene.c (needs libegl-dev and libosmesa6-dev)",
    );
    let (egl, osmesa) = (profile_subdir("egl"), profile_subdir("osmesa"));
    let path = std::env::join_paths([&egl, &osmesa]).unwrap();
    let stdout = stdout_of(Command::new(&exe).arg(&dir).env("LD_LIBRARY_PATH", path), "egl_scene");
    // Both OSMesaCreateContext and eglGetDisplay come from softgl's one library.
    let lines: Vec<&str> = stdout.lines().collect();
    for (line, prefix) in lines.iter().zip(["library ", "egl "]) {
        let lib = line.strip_prefix(prefix).unwrap_or_else(|| panic!("{stdout}"));
        assert!(Path::new(lib).starts_with(&egl), "{line}");
    }
    assert_eq!(lines.last(), Some(&"done"), "{stdout}");
    let read = |name: &str| std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    let color = read("egl_color");
    assert_eq!(color.len(), 61 * 47 * 4);
    assert!(color.chunks(4).any(|p| p != &color[..4]), "the scene drew something");
    assert_eq!(color, read("osmesa_color"), "glReadPixels colour, EGL vs OSMesa");
    assert_eq!(color, read("osmesa_buffer"), "EGL's pixels vs OSMesa's buffer");
    assert_eq!(
        read("egl_depth"),
        read("osmesa_depth"),
        "glReadPixels depth, EGL vs OSMesa"
    );
}

#[test]
fn pyopengl_draws_through_egl() {
    if !have("PyOpenGL EGL client", &[Need::PyOpenGl]) {
        return;
    }
    let egl = profile_subdir("egl");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/pyopengl_egl.py");
    let stdout = stdout_of(
        Command::new("python3")
            .arg(&script)
            .env("PYOPENGL_PLATFORM", "egl")
            .env("LD_LIBRARY_PATH", &egl)
            .env("SOFTGL_EGL_DIR", &egl),
        "PyOpenGL script (needs `pip install PyOpenGL`)",
    );
    assert!(stdout.contains("egl 1 5 softgl"), "{stdout}");
    assert!(stdout.contains("renderer softgl"), "{stdout}");
    assert_eq!(stdout.lines().last(), Some("ok"), "{stdout}");
}
