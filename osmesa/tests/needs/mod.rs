//! What the client tests need from the machine (a C compiler, Mesa's OSMesa,
//! GLU, binutils, PyOpenGL, EGL headers, piglit, MuJoCo), looked for once per test
//! process; a missing one is skipped loudly or, under
//! `SOFTGL_REQUIRE_REFERENCES=1`, fails (`conformance/src/missing.rs` decides).
//! Each test binary uses part of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// Where Debian's piglit keeps its test programs.
pub const PIGLIT_BIN: &str = "/usr/lib/x86_64-linux-gnu/piglit/bin";

#[path = "../../../conformance/src/missing.rs"]
mod missing;
pub use missing::Missing;

/// Something a test needs from the machine.
#[derive(Clone, Copy, Debug)]
pub enum Need {
    /// A C compiler (`cc`).
    Cc,
    /// Mesa's OSMesa to build against and run: `<GL/osmesa.h>`, `-lOSMesa`.
    OsMesa,
    /// GLU to build against and run: `<GL/glu.h>`, `-lGLU`.
    Glu,
    /// `nm` (binutils).
    Nm,
    /// `python3` with PyOpenGL.
    PyOpenGl,
    /// Khronos' EGL headers and `-lEGL` (glvnd's libEGL).
    Egl,
    /// piglit with waffle and Mesa's EGL.
    Piglit,
    /// `python3` with MuJoCo's Python package and PyOpenGL (`MUJOCO_GL=osmesa`).
    Mujoco,
}

impl Need {
    const ALL: [Need; 8] = [
        Need::Cc,
        Need::OsMesa,
        Need::Glu,
        Need::Nm,
        Need::PyOpenGl,
        Need::Egl,
        Need::Piglit,
        Need::Mujoco,
    ];

    /// Looks once per test process.
    fn find(self) -> Result<(), Missing> {
        static FOUND: [OnceLock<Result<(), Missing>>; Need::ALL.len()] = [const { OnceLock::new() }; Need::ALL.len()];
        FOUND[self as usize].get_or_init(|| self.look()).clone()
    }

    fn look(self) -> Result<(), Missing> {
        let ok = |cmd: &str, args: &[&str]| Command::new(cmd).args(args).output().is_ok_and(|o| o.status.success());
        match self {
            Need::Cc if ok("cc", &["--version"]) => Ok(()),
            Need::Cc => Err(Missing::new("a C compiler (cc)", "apt-get install -y gcc libc6-dev")),
            Need::OsMesa => c_probe(
                "osmesa",
                "#include <GL/osmesa.h>\nint main(void) { return OSMesaGetCurrentContext() != 0; }\n",
                "-lOSMesa",
            )
            .then_some(())
            .ok_or_else(|| {
                Missing::new(
                    "Mesa's OSMesa (GL/osmesa.h, libOSMesa.so.8)",
                    "apt-get install -y libosmesa6 libosmesa6-dev",
                )
            }),
            Need::Glu => c_probe(
                "glu",
                "#include <GL/glu.h>\nint main(void) { return gluErrorString(0) == 0; }\n",
                "-lGLU",
            )
            .then_some(())
            .ok_or_else(|| Missing::new("GLU (GL/glu.h, libGLU.so.1)", "apt-get install -y libglu1-mesa-dev")),
            Need::Nm if ok("nm", &["--version"]) => Ok(()),
            Need::Nm => Err(Missing::new("nm", "apt-get install -y binutils")),
            Need::PyOpenGl if ok("python3", &["-c", "import OpenGL.version"]) => Ok(()),
            Need::PyOpenGl if ok("python3", &["--version"]) => Err(Missing::new(
                "PyOpenGL for python3",
                "python3 -m pip install PyOpenGL (Debian's python3: apt-get install -y python3-opengl)",
            )),
            Need::PyOpenGl => Err(Missing::new("python3", "apt-get install -y python3 python3-opengl")),
            Need::Egl => c_probe(
                "egl",
                "#include <EGL/egl.h>\nint main(void) { return eglGetError() != EGL_SUCCESS; }\n",
                "-lEGL",
            )
            .then_some(())
            .ok_or_else(|| Missing::new("EGL headers and libEGL (EGL/egl.h)", "apt-get install -y libegl-dev")),
            Need::Mujoco if ok("python3", &["-c", "import mujoco, OpenGL.version"]) => Ok(()),
            Need::Mujoco => Err(Missing::new(
                "MuJoCo's Python package with PyOpenGL",
                "python3 -m pip install mujoco PyOpenGL",
            )),
            Need::Piglit if Path::new(PIGLIT_BIN).is_dir() && ok("piglit", &["--help"]) => Ok(()),
            Need::Piglit => Err(Missing::new(
                "piglit",
                "apt-get install -y piglit libegl-mesa0 libgl1-mesa-dri libwaffle-1-0",
            )),
        }
    }
}

/// Builds and runs a one-line C program against `lib`: whether both work.
pub fn c_probe(name: &str, source: &str, lib: &str) -> bool {
    let dir = work_dir(&format!("probe-{name}"));
    let (src, exe) = (dir.join("probe.c"), dir.join("probe"));
    std::fs::write(&src, source).expect("write the probe");
    let built = Command::new("cc")
        .arg("-o")
        .arg(&exe)
        .arg(&src)
        .arg(lib)
        .output()
        .is_ok_and(|o| o.status.success());
    built
        && Command::new(&exe)
            .env_remove("LD_LIBRARY_PATH")
            .status()
            .is_ok_and(|s| s.success())
}

/// Whether everything `check` needs is here; if not, skips it (one loud
/// line) and returns false — or fails it under `SOFTGL_REQUIRE_REFERENCES=1`.
pub fn have(check: &str, needs: &[Need]) -> bool {
    match needs.iter().try_for_each(|n| n.find()) {
        Ok(()) => true,
        Err(m) => {
            m.skip(check);
            false
        }
    }
}

/// `<target>/<profile>`: this test runs from `<target>/<profile>/deps`.
pub fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("test executable path");
    exe.parent()
        .and_then(Path::parent)
        .expect("target profile dir")
        .to_path_buf()
}

pub fn work_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join("osmesa-clients").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("work dir");
    d
}

/// Runs the client `cmd` (named `what` in failures): its stdout lines, of
/// which the last must be `done` (the client ran to its end).
pub fn client_lines(cmd: &mut Command, what: &str) -> Vec<String> {
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
