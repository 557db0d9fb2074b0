//! Rectangle textures (`GL_ARB_texture_rectangle`) against Mesa's llvmpipe:
//! `tests/c/texrect.c`, built once and run on both (as `clients.rs` does),
//! prints the state, defaults and errors of every call that takes the target
//! and draws fifteen scenes sampling odd-sized rectangles at unnormalized
//! coordinates; softgl runs it on the JIT (tiered and optimized: its native
//! sampler) and on the interpreter, each byte for byte. A missing reference prints one `SKIPPED ...` line and
//! passes, unless `SOFTGL_REQUIRE_REFERENCES=1` (`tests/needs`).

use std::path::{Path, PathBuf};
use std::process::Command;

mod needs;
use needs::{client_lines, have, profile_dir, work_dir, Need};

/// Builds `tests/c/texrect.c`; `None` (skipped) without the references.
fn build() -> Option<PathBuf> {
    if !have("C client texrect.c", &[Need::Cc, Need::OsMesa, Need::Glu]) {
        return None;
    }
    let exe = work_dir("texrect-bin").join("texrect");
    let out = Command::new("cc")
        .arg("-O1")
        .arg("-o")
        .arg(&exe)
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c/texrect.c"))
        .args(["-lOSMesa", "-lGLU", "-lpthread", "-ldl", "-lm"])
        .output()
        .expect("run cc");
    assert!(
        out.status.success(),
        "building texrect.c failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(exe)
}

/// How softgl runs the client: its default (the JIT, textured keys tiered:
/// the quick code, every unit through the reference sampler, until the
/// optimized code with native sampling is installed), the optimized code
/// alone, or the interpreter.
const SOFTGL_MODES: [(&str, &str, &str); 3] = [
    ("default", "SOFTGL_JIT_TIER", ""),
    ("optimized", "SOFTGL_JIT_TIER", "optimized"),
    ("interpreter", "SOFTGL_BACKEND", "interp"),
];

/// Runs `exe` on softgl (`LD_LIBRARY_PATH` at its build, in `mode` of
/// [`SOFTGL_MODES`]) or on Mesa (`None`): its stdout lines and its output directory.
fn run(exe: &Path, mode: Option<(&str, &str, &str)>) -> (Vec<String>, PathBuf) {
    let what = match mode {
        Some((name, ..)) => format!("texrect-softgl-{name}"),
        None => "texrect-mesa".to_string(),
    };
    let dir = work_dir(&what);
    let mut cmd = Command::new(exe);
    cmd.arg(&dir)
        .env_remove("LD_LIBRARY_PATH")
        .env_remove("SOFTGL_JIT_TIER")
        .env_remove("SOFTGL_BACKEND")
        .env("GALLIUM_DRIVER", "llvmpipe");
    if let Some((_, var, value)) = mode {
        cmd.env("LD_LIBRARY_PATH", profile_dir().join("osmesa"));
        if !value.is_empty() {
            cmd.env(var, value);
        }
    }
    (client_lines(&mut cmd, &what), dir)
}

const W: usize = 320;
const CELL: usize = 64;

/// Cell `k` (five a row, bottom row first) of a `W`-wide RGBA image.
fn cell(img: &[u8], k: usize) -> Vec<u8> {
    let (x0, y0) = ((k % 5) * CELL, (k / 5) * CELL);
    (y0..y0 + CELL)
        .flat_map(|y| img[(y * W + x0) * 4..(y * W + x0 + CELL) * 4].to_vec())
        .collect()
}

#[test]
fn rectangle_textures_match_llvmpipe() {
    let Some(exe) = build() else { return };
    let (mesa, mesa_dir) = run(&exe, None);
    for mode in SOFTGL_MODES {
        let (soft, soft_dir) = run(&exe, Some(mode));
        compare(mode.0, (&soft, &soft_dir), (&mesa, &mesa_dir));
    }
}

/// softgl's run (in `mode`) against Mesa's: every line, the rectangle
/// rendered through the framebuffer object, the fifteen scenes.
fn compare(mode: &str, (soft, soft_dir): (&[String], &Path), (mesa, mesa_dir): (&[String], &Path)) {
    assert!(soft[0].contains(&*profile_dir().to_string_lossy()), "{}", soft[0]);
    // Each implementation's own limit: llvmpipe's 16384, softgl's 2D limit.
    let max = "max rectangle size ";
    assert_eq!(
        mesa.iter().find(|l| l.starts_with(max)).unwrap(),
        "max rectangle size 16384 0x0000"
    );
    assert_eq!(
        soft.iter().find(|l| l.starts_with(max)).unwrap(),
        "max rectangle size 4096 0x0000"
    );
    // Every other line (state, defaults, each error, push/pop, lists,
    // framebuffer completeness) is Mesa's.
    let rest = |v: &[String]| {
        v[1..]
            .iter()
            .filter(|l| !l.starts_with(max))
            .cloned()
            .collect::<Vec<_>>()
    };
    assert_eq!(rest(soft), rest(mesa), "{mode}");
    assert!(soft.iter().any(|l| l == "extension ARB 1 EXT 1 NV 1"));
    assert!(soft.iter().any(|l| l == "rectangle framebuffer complete 1"));
    assert!(soft.iter().any(|l| l == "readback equal 1"));
    assert_eq!(soft.len(), 131);
    // Rendered into the rectangle through the framebuffer object: Mesa's bytes.
    let rt = |d: &Path| std::fs::read(d.join("texrect.rt")).expect("texrect.rt");
    assert_eq!(rt(soft_dir), rt(mesa_dir), "{mode}: render to rectangle");
    // Fifteen scenes, byte for byte.
    let color = |d: &Path| std::fs::read(d.join("texrect.color")).expect("texrect.color");
    let (s, m) = (color(soft_dir), color(mesa_dir));
    let background = [13u8, 26, 51, 255];
    for k in 0..15 {
        let (a, b) = (cell(&s, k), cell(&m, k));
        let differing = a.iter().zip(&b).filter(|(x, y)| x != y).count();
        let drawn = a.chunks_exact(4).filter(|p| *p != background).count();
        assert!(drawn > 500, "{mode}: scene {k} drew {drawn} pixels");
        assert_eq!(
            differing, 0,
            "{mode}: scene {k}: {differing} channels differ from llvmpipe's"
        );
    }
}
