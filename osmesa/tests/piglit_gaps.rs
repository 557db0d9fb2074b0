//! What piglit's GL 1.x groups found missing in softgl (issue 15), each
//! checked against Mesa's llvmpipe by a C client built once and run on both
//! (as `clients.rs` does): `tests/c/gaps15.c` through OSMesa (multi-draw
//! errors, null sub-images, colour-index textures, zero-area feedback through
//! `GL_EXT_vertex_array`, packed reads, `GL_EXT_shadow_funcs`), and
//! `tests/c/egl_msaa.c` through EGL (4-sample configs). A missing
//! reference prints one `SKIPPED ...` line and passes, unless
//! `SOFTGL_REQUIRE_REFERENCES=1` (`tests/needs`).

use std::path::{Path, PathBuf};
use std::process::Command;

mod needs;
use needs::{client_lines, have, profile_dir, work_dir, Need};

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
    client_lines(&mut cmd, what)
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
    assert!(
        soft.iter()
            .any(|l| l.starts_with("feedback, cull 0x0: 23 values: 1795.000 3.000")),
        "{soft:?}"
    );
    assert!(
        soft.iter().any(|l| l == "compare 0x205 (read 0x205): 255 255 err 0x0"),
        "{soft:?}"
    );
    assert_eq!(soft.len(), 69);
}

/// Runs `tests/c/egl_msaa.c` asking for `samples` on Mesa's EGL or on
/// softgl's; its stdout lines, colour bytes and depths.
fn egl_msaa(exe: &Path, samples: u32, softgl: bool) -> (Vec<String>, Vec<u8>, Vec<f32>) {
    let what = format!("egl-msaa-{samples}-{}", if softgl { "softgl" } else { "mesa" });
    let dir = work_dir(&what);
    let mut cmd = Command::new(exe);
    cmd.arg(&dir).arg(samples.to_string()).env_remove("LD_LIBRARY_PATH");
    if softgl {
        cmd.env("LD_LIBRARY_PATH", profile_dir().join("egl"));
    }
    let out = cmd.output().expect("run egl_msaa");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "{what}: {}\n{stdout}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<String> = stdout.lines().map(str::to_owned).collect();
    assert_eq!(lines.last().map(String::as_str), Some("done"), "{what}:\n{stdout}");
    let color = std::fs::read(dir.join("color")).expect("color");
    let depth = std::fs::read(dir.join("depth"))
        .expect("depth")
        .chunks_exact(4)
        .map(|c| f32::from_ne_bytes(c.try_into().unwrap()))
        .collect();
    (lines, color, depth)
}

#[test]
fn a_multisampled_egl_window_matches_llvmpipe() {
    let Some(exe) = build("egl_msaa", &[Need::Cc, Need::Egl], &["-lEGL", "-lOpenGL"]) else {
        return;
    };
    let single = egl_msaa(&exe, 0, true).1;
    for samples in [0, 2, 4] {
        let (mesa_lines, mesa_color, mesa_depth) = egl_msaa(&exe, samples, false);
        let (lines, color, depth) = egl_msaa(&exe, samples, true);
        // The config (2 samples asked: 4 given, as llvmpipe), GL_SAMPLES, no error.
        assert_eq!(lines, mesa_lines, "{samples} samples");
        let want = if samples > 0 {
            "GL_SAMPLES 4, GL_SAMPLE_BUFFERS 1"
        } else {
            "GL_SAMPLES 0, GL_SAMPLE_BUFFERS 0"
        };
        assert!(lines[1].starts_with(want), "{lines:?}");
        // glReadPixels reads sample 0, as llvmpipe maps a multisampled
        // window buffer (`llvmpipe_transfer_map`: sample 0): every byte equal.
        assert_eq!(color, mesa_color, "colour, {samples} samples");
        // Depth: within 2 units of 2^24 (per-sample depth is evaluated from
        // llvmpipe's f32 planes at the sample, softgl's differ in the last
        // bits; docs/llvmpipe-facts.md §31).
        let worst = depth
            .iter()
            .zip(&mesa_depth)
            .map(|(a, b)| ((a - b).abs() * 16_777_215.0).round() as u32)
            .max();
        assert!(
            worst.is_some_and(|w| w <= 2),
            "depth off by {worst:?}/2^24, {samples} samples"
        );
        if samples > 0 {
            // The samples matter: sample 0 is not the single-sampled image.
            let differ = color.iter().zip(&single).filter(|(a, b)| a != b).count();
            assert!(differ >= 100, "{differ} bytes differ from one sample a pixel");
        }
    }
}
