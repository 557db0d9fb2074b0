//! Real OSMesa clients against softgl's `libOSMesa.so.8`: C programs built
//! once against Mesa's headers (`-lOSMesa`, Debian's `libosmesa6-dev` and
//! `libglu1-mesa-dev`), run on Mesa 22's llvmpipe and on softgl (the same
//! binary, `LD_LIBRARY_PATH` pointing at softgl's directory), their outputs
//! compared within the tolerances written next to each check; and a
//! PyOpenGL script (`PYOPENGL_PLATFORM=osmesa`).
//!
//! Mesa's OSMesa and GLU (with headers), a C compiler, binutils and PyOpenGL
//! are the references here: a test that cannot find one prints one
//! `SKIPPED ...` line with the command that installs it and passes, or fails
//! under `SOFTGL_REQUIRE_REFERENCES=1` (as in CI, `.ci/run`). The decision is
//! `conformance/src/missing.rs`, the one module every such test uses.

use std::path::{Path, PathBuf};
use std::process::Command;

mod needs;
use needs::{have, profile_dir, work_dir, Need};

/// The directory with softgl's `libOSMesa.so.8` and `libOSMesa.so` (build.rs makes it).
fn lib_dir() -> PathBuf {
    let dir = profile_dir().join("osmesa");
    for name in ["libOSMesa.so.8", "libOSMesa.so"] {
        let p = dir.join(name);
        assert!(p.exists(), "{} is missing: build the workspace first", p.display());
    }
    dir
}

fn c_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/c")
}

/// Builds `tests/c/<name>.c` against Mesa's OSMesa and GLU (into a directory
/// of its own: tests building the same program run in parallel); `None`
/// (skipped, see [`have`]) when the compiler, OSMesa or GLU is missing.
fn build(name: &str) -> Option<PathBuf> {
    if !have(&format!("C client {name}.c"), &[Need::Cc, Need::OsMesa, Need::Glu]) {
        return None;
    }
    static BUILDS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = BUILDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = work_dir(&format!("bin-{name}-{n}"));
    let exe = dir.join(name);
    let out = Command::new("cc")
        .arg("-O1")
        .arg("-o")
        .arg(&exe)
        .arg(c_dir().join(format!("{name}.c")))
        .args(["-lOSMesa", "-lGLU", "-lpthread", "-ldl", "-lm"])
        .output()
        .expect("run cc");
    assert!(
        out.status.success(),
        "building {name}.c failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(exe)
}

/// A run's output directory and its stdout lines.
struct Run {
    dir: PathBuf,
    lines: Vec<String>,
}

impl Run {
    fn file(&self, name: &str) -> Vec<u8> {
        std::fs::read(self.dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
    }

    fn f32s(&self, name: &str) -> Vec<f32> {
        self.file(name)
            .chunks_exact(4)
            .map(|c| f32::from_ne_bytes(c.try_into().unwrap()))
            .collect()
    }

    fn u16s(&self, name: &str) -> Vec<u16> {
        self.file(name)
            .chunks_exact(2)
            .map(|c| u16::from_ne_bytes(c.try_into().unwrap()))
            .collect()
    }

    fn u32s(&self, name: &str) -> Vec<u32> {
        self.file(name)
            .chunks_exact(4)
            .map(|c| u32::from_ne_bytes(c.try_into().unwrap()))
            .collect()
    }
}

/// Runs `exe` on Mesa (`softgl == false`) or on softgl, checking which
/// library it loaded.
fn run(exe: &Path, softgl: bool) -> Run {
    let name = exe.file_name().unwrap().to_string_lossy().to_string();
    let dir = work_dir(&format!("{name}-{}", if softgl { "softgl" } else { "mesa" }));
    let mut cmd = Command::new(exe);
    cmd.arg(&dir)
        .env_remove("LD_LIBRARY_PATH")
        .env("GALLIUM_DRIVER", "llvmpipe");
    if softgl {
        cmd.env("LD_LIBRARY_PATH", lib_dir());
    }
    let out = cmd.output().expect("run the client");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "{name} on {} failed: {}\n{stdout}\n{}",
        if softgl { "softgl" } else { "Mesa" },
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<String> = stdout.lines().map(str::to_owned).collect();
    let library = lines.first().and_then(|l| l.strip_prefix("library ")).unwrap_or("");
    let ours = Path::new(library).starts_with(lib_dir());
    assert_eq!(ours, softgl, "{name} loaded {library}");
    assert_eq!(
        lines.last().map(String::as_str),
        Some("done"),
        "{name} did not finish:\n{stdout}"
    );
    Run { dir, lines }
}

/// Largest absolute difference and the number of differing elements.
fn diff<T: Copy + Into<f64>>(a: &[T], b: &[T]) -> (f64, usize) {
    assert_eq!(a.len(), b.len(), "sizes differ");
    a.iter().zip(b).fold((0.0, 0), |(m, n), (&x, &y)| {
        let d = (x.into() - y.into()).abs();
        (m.max(d), n + usize::from(d != 0.0))
    })
}

const W: usize = 61;
const H: usize = 47;
const PAD: usize = 5;

/// Channel positions of an order in RGBA, as `tests/c/formats.c` names them.
fn order(name: &str) -> &'static [usize] {
    match name.split('_').next().unwrap() {
        "rgba" => &[0, 1, 2, 3],
        "bgra" => &[2, 1, 0, 3],
        "argb" => &[3, 0, 1, 2],
        _ => &[0, 1, 2],
    }
}

/// Reorders Mesa's RGBA image `rgba` (tight, `n` channels of 4) into `name`'s order.
fn reorder<T: Copy>(rgba: &[T], name: &str) -> Vec<T> {
    rgba.chunks_exact(4)
        .flat_map(|px| order(name).iter().map(move |&c| px[c]))
        .collect()
}

/// Drops the row padding of a layout-2 buffer, checking it kept its 0xA5 sentinel.
fn unpad(bytes: &[u8], bpp: usize) -> Vec<u8> {
    let (row, stride) = (W * bpp, (W + PAD) * bpp);
    assert_eq!(bytes.len(), stride * H);
    let mut out = Vec::with_capacity(row * H);
    for line in bytes.chunks_exact(stride) {
        assert!(line[row..].iter().all(|&b| b == 0xA5), "row padding was written");
        out.extend_from_slice(&line[..row]);
    }
    out
}

/// Flips the rows of a tight image.
fn flip(bytes: &[u8], bpp: usize) -> Vec<u8> {
    bytes.chunks_exact(W * bpp).rev().flatten().copied().collect()
}

#[test]
fn formats_y_up_row_length_depth_and_read_pixels_match_mesa() {
    let Some(exe) = build("formats") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    let formats = [
        ("rgba_ubyte", 4),
        ("bgra_ubyte", 4),
        ("argb_ubyte", 4),
        ("rgb_ubyte", 3),
        ("rgb565", 2),
        ("rgba_ushort", 8),
        ("bgra_ushort", 8),
        ("argb_ushort", 8),
        ("rgb_ushort", 6),
        ("rgba_float", 16),
        ("bgra_float", 16),
        ("argb_float", 16),
        ("rgb_float", 12),
    ];
    for (name, bpp) in formats {
        // Layouts: 0 y-up, 1 y-down (OSMESA_Y_UP 0), 2 y-up with a padded OSMESA_ROW_LENGTH.
        let s: Vec<Vec<u8>> = (0..3).map(|l| soft.file(&format!("{name}.{l}.color"))).collect();
        let m: Vec<Vec<u8>> = (0..3).map(|l| mesa.file(&format!("{name}.{l}.color"))).collect();
        // In softgl the three layouts hold the same image.
        assert_eq!(flip(&s[1], bpp), s[0], "{name}: OSMESA_Y_UP 0 is not the flipped image");
        assert_eq!(unpad(&s[2], bpp), s[0], "{name}: OSMESA_ROW_LENGTH changed the image");
        assert_eq!(unpad(&m[2], bpp), m[0], "{name}: Mesa's row length");
        // Mesa 22 gets the other orders wrong for 16-bit and float channels
        // (BGRA and ARGB come out in RGBA order; RGB is garbled, as are RGB
        // bytes): softgl's are compared with Mesa's RGBA image, reordered.
        let wide = |kind: &str| format!("rgba_{kind}.0.color");
        match name {
            // The byte formats are exact: softgl matches llvmpipe's coverage,
            // interpolation, blending and rounding on this scene.
            "rgba_ubyte" | "bgra_ubyte" | "argb_ubyte" => {
                assert_eq!(s[0], m[0], "{name}");
                assert_eq!(s[1], m[1], "{name} y-down");
            }
            "rgb_ubyte" => assert_eq!(s[0], reorder(&mesa.file(&wide("ubyte")), name), "{name}"),
            // RGB 5-6-5 is exact too: llvmpipe ignores GL_DITHER and truncates
            // unorm8 to the high bits; its whole-buffer clear rounds half up
            // (docs/llvmpipe-facts.md §13), and softgl does the same.
            "rgb565" => {
                assert_eq!(s[0], m[0], "{name}");
                assert_eq!(s[1], m[1], "{name} y-down");
            }
            // 16-bit and float channels: rendered at that precision, as
            // Mesa renders them (RGBA16 unorm, RGBA32F): identical.
            _ if name.ends_with("ushort") => {
                assert_eq!(
                    soft.u16s(&format!("{name}.0.color")),
                    reorder(&mesa.u16s(&wide("ushort")), name),
                    "{name}"
                );
            }
            _ => {
                let a = soft.f32s(&format!("{name}.0.color"));
                assert_eq!(a, reorder(&mesa.f32s(&wide("float")), name), "{name}");
            }
        }
    }
    // OSMesaGetDepthBuffer: Z24S8 in 32 bits, stencil 0x5a in the high byte,
    // rows bottom-up for either OSMESA_Y_UP. Depth values within 2 units of
    // 2^24 (softgl's f32 plane setup differs from llvmpipe's step for step on
    // the sloped triangle; the flat quad and the clears are exact).
    for l in 0..2 {
        let (a, b) = (soft.u32s(&format!("depth.{l}")), mesa.u32s(&format!("depth.{l}")));
        assert!(a.iter().zip(&b).all(|(x, y)| x >> 24 == 0x5a && y >> 24 == 0x5a));
        let (max, n) = diff(&a, &b);
        assert!(max <= 2.0, "depth.{l}: max difference {max} over {n} pixels");
        let (c, d) = (
            soft.u32s(&format!("read_depth_uint.{l}")),
            mesa.u32s(&format!("read_depth_uint.{l}")),
        );
        let (max, _) = diff(&c, &d);
        assert!(
            max <= 2.0 * 257.0,
            "glReadPixels depth as uint: {max} (2 units of 2^24, replicated)"
        );
        assert_eq!(
            soft.file(&format!("read_stencil.{l}")),
            mesa.file(&format!("read_stencil.{l}"))
        );
        for r in ["read_rgba", "read_rgb", "read_bgra_sub"] {
            assert_eq!(
                soft.file(&format!("{r}.{l}")),
                mesa.file(&format!("{r}.{l}")),
                "{r}.{l}"
            );
        }
        // Floats from unorm8 bytes: v * (1/255) in f32, as Mesa converts them.
        assert_eq!(
            soft.f32s(&format!("read_float.{l}")),
            mesa.f32s(&format!("read_float.{l}"))
        );
    }
    // 16 depth bits without stencil: Z16, 2 bytes a value, as Mesa's
    // (GL_DEPTH_BITS 16). Within 1 unit: softgl rounds z * 65535 to even,
    // llvmpipe's Z16 conversion rounds 0.5 down.
    let (a, b) = (soft.u16s("depth16"), mesa.u16s("depth16"));
    let (max, _) = diff(&a, &b);
    assert!(max <= 1.0, "depth16: {max}");
    // What the program printed (GL_DEPTH_BITS 16, 2 bytes a value, no depth
    // buffer: GL_FALSE with zeros and NULL written) is Mesa's, line for line.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.contains(&"no depth, stencil 8: 0 0 0 0 1".to_owned()));
}

#[test]
fn glu_quadrics_look_at_and_perspective_match_mesa() {
    let Some(exe) = build("glu") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    let (a, b) = (soft.file("glu.color"), mesa.file("glu.color"));
    // Filled quadrics are exact. Lines (GLU_LINE, GLU_SILHOUETTE) cover the
    // same pixels, but softgl's line colour interpolation lands on 127 where
    // llvmpipe rounds a 0.5 channel to 128: 302 channels at one step.
    let (max, n) = diff(&a, &b);
    assert!(
        max <= 1.0 && n <= 320,
        "glu colours: max {max}, {n} channels differ (measured 302)"
    );
    let covered = |img: &[u8]| -> Vec<bool> { img.chunks_exact(4).map(|p| p[0] > 20 || p[1] > 20).collect() };
    assert_eq!(covered(&a), covered(&b), "coverage");
    let lit = covered(&a).iter().filter(|&&c| c).count();
    assert!(lit > 2500, "the quadrics drew only {lit} pixels");
    // Depth within 16 units of 2^24 under perspective (measured 9).
    let mask = |v: Vec<u32>| -> Vec<u32> { v.into_iter().map(|x| x & 0xff_ffff).collect() };
    let (max, _) = diff(&mask(soft.u32s("glu.depth")), &mask(mesa.u32s("glu.depth")));
    assert!(max <= 16.0, "glu depth: {max}");
    // No error from the quadrics; gluBuild2DMipmaps uploads its levels as on Mesa.
    assert!(soft.lines.contains(&"error after quadrics 0x0".to_owned()));
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.contains(&"gluBuild2DMipmaps 0 error 0x0".to_owned()));
}

/// Runs a client drawing four 128x128 scenes into a 256x256 image `file`
/// on Mesa and softgl: per scene (quarter), the largest channel difference
/// and the number of differing channels.
fn scene_diffs(name: &str, file: &str) -> Option<Vec<(f64, usize)>> {
    let exe = build(name)?;
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    for k in 1..=4 {
        assert!(soft.lines.contains(&format!("scene {k} error 0x0")), "{:?}", soft.lines);
    }
    let (a, b) = (soft.file(file), mesa.file(file));
    let quarter = |img: &[u8], q: usize| -> Vec<u8> {
        let (x0, y0) = ((q % 2) * 128, (q / 2) * 128);
        (y0..y0 + 128)
            .flat_map(|y| img[(y * 256 + x0) * 4..(y * 256 + x0 + 128) * 4].to_vec())
            .collect()
    };
    Some((0..4).map(|q| diff(&quarter(&a, q), &quarter(&b, q))).collect())
}

#[test]
fn lit_scenes_match_mesa() {
    let Some(counts) = scene_diffs("lit", "lit.color") else {
        return;
    };
    // Measured: scenes 1 and 3 identical; scene 2 (8 spot lights with
    // attenuation, local viewer, linear fog) two channels one step off;
    // scene 4 (colour material, NORMALIZE, flat, a user clip plane) identical.
    assert!(counts.iter().all(|&(max, _)| max <= 1.0), "{counts:?}");
    assert!(counts.iter().map(|c| c.1).sum::<usize>() <= 4, "{counts:?}");
}

#[test]
fn stiff_lit_scenes_match_mesa() {
    let Some(counts) = scene_diffs("lit_stiff", "lit_stiff.color") else {
        return;
    };
    // Shininess 0 with attenuation, spot exponent 128 with RESCALE_NORMAL,
    // normals of length 1e-20 and 1e20, object-space lighting: measured identical.
    assert_eq!(counts, [(0.0, 0); 4]);
}

#[test]
fn per_vertex_and_tracked_materials_match_mesa() {
    let Some(exe) = build("materials") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // glMaterial between glBegin and glEnd lights the vertices that follow
    // (immediate, display list, flat, two-sided); with GL_COLOR_MATERIAL a
    // glMaterial of the tracked value is ignored: the same image, byte for
    // byte, and the same materials read back.
    let image = soft.file("materials.color");
    let differing = image
        .iter()
        .zip(mesa.file("materials.color"))
        .filter(|(a, b)| **a != *b)
        .count();
    assert_eq!(differing, 0);
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.iter().any(|l| l == "scene 4 error 0x0"), "{:?}", soft.lines);
}

#[test]
fn clip_planes_match_mesa() {
    let Some(counts) = scene_diffs("clip_planes", "clip_planes.color") else {
        return;
    };
    // Measured (channels differing): points (2) identical; a lit
    // normal-array mesh (3) 18 channels (6 pixels) one step off;
    // polygon-mode lines (1) and lines (4) 9 and 21 channels (3 and 8
    // pixels) where an end lands on the other side of a pixel (lines
    // crossing the near plane alone differ in 3 of those 8 pixels, §6).
    assert_eq!(counts[1], (0.0, 0));
    assert!(counts[2].0 <= 1.0 && counts[2].1 <= 24, "{counts:?}");
    assert!(counts[0].1 <= 12 && counts[3].1 <= 28, "{counts:?}");
}

#[test]
fn errors_from_bad_arguments_match_mesa() {
    let Some(exe) = build("errors") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Every line after the library's name is the same: OSMesa's refusals,
    // each GL error, the sticky first error, the state read back.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.len() > 70);
}

#[test]
fn the_accumulation_buffer_matches_mesa() {
    let Some(exe) = build("accum") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Queries (GL_ACCUM_*_BITS, GL_ACCUM_CLEAR_VALUE), the attribute stack
    // and the errors: the same lines.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    for (name, steps) in [("rgba", 14), ("bgra", 14), ("rgb565", 14)] {
        for step in 0..steps {
            // Every step read back with glReadPixels: byte for byte Mesa's
            // (RGBA16 snorm values, C's truncations, shorts that wrap).
            let file = format!("{name}.{step}.read");
            assert_eq!(soft.file(&file), mesa.file(&file), "{file}");
            // softgl's own buffer holds the same pixels (Mesa's may be stale:
            // see tests/c/accum.c).
            let read = soft.file(&file);
            let color = soft.file(&format!("{name}.{step}.color"));
            match name {
                "rgba" => assert_eq!(color, read, "{name}.{step}"),
                "bgra" => assert_eq!(reorder(&read, name), color, "{name}.{step}"),
                _ => {}
            }
        }
    }
    // The motion blur blends four frames: many distinct colours.
    let blur = soft.file("rgba.0.read");
    let mut colours: Vec<&[u8]> = blur.chunks_exact(4).collect();
    colours.sort();
    colours.dedup();
    assert!(colours.len() > 50, "only {} colours", colours.len());
}

#[test]
fn deep_colour_buffers_match_mesa() {
    let Some(exe) = build("deep") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // GL_RED_BITS.. 8, 16 and 32 and OSMESA_TYPE for each buffer type, and no
    // GL error: the same lines.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft
        .lines
        .contains(&"float pass 0: bits 32 32 32 32 type 0x1406".to_owned()));
    for pass in 0..2 {
        // Bytes: identical (smooth, lit, blended, fogged, logic op, accum).
        let name = format!("ubyte.{pass}.color");
        assert_eq!(soft.file(&name), mesa.file(&name), "{name}");
        // 16 bits: within 1 of 65535 on at most 16 pixels, all in the lit
        // sphere: softgl's per-vertex lighting lands within ~3e-6 of
        // llvmpipe's in f32 (identical once rounded to 8 bits); everything
        // else (interpolation, the unorm16 conversion, 16-bit blending,
        // logic op, the whole-buffer and scissored clears, accum) is exact.
        let (a, b) = (
            soft.u16s(&format!("ushort.{pass}.color")),
            mesa.u16s(&format!("ushort.{pass}.color")),
        );
        let (max, n) = diff(&a, &b);
        assert!(max <= 1.0 && n <= 16, "ushort.{pass}: max {max} over {n} channels");
        // Floats: unclamped (additive blending to 1.9, the colour sum past
        // 1, accum's wrapped shorts below 0), within 4e-6 on the lit sphere's
        // pixels (the same lighting difference) and equal elsewhere.
        let (a, b) = (
            soft.f32s(&format!("float.{pass}.color")),
            mesa.f32s(&format!("float.{pass}.color")),
        );
        let (max, n) = diff(&a, &b);
        assert!(max <= 4e-6 && n <= 4 * 400, "float.{pass}: max {max} over {n} channels");
        assert!(
            a.iter().any(|&v| v > 1.5) && a.iter().any(|&v| v < 0.0),
            "float.{pass} was clamped"
        );
        // glReadPixels(GL_FLOAT): clamped to [0, 1], as Mesa reads its float buffer.
        let (a, b) = (
            soft.f32s(&format!("float.{pass}.read")),
            mesa.f32s(&format!("float.{pass}.read")),
        );
        let (max, _) = diff(&a, &b);
        assert!(max <= 4e-6, "float.{pass}.read: max {max}");
        assert!(a.iter().all(|&v| (0.0..=1.0).contains(&v)));
        let (a, b) = (
            soft.f32s(&format!("ushort.{pass}.read")),
            mesa.f32s(&format!("ushort.{pass}.read")),
        );
        let (max, _) = diff(&a, &b);
        assert!(max <= 1.0 / 65535.0 + 1e-9, "ushort.{pass}.read: max {max}");
        // glReadPixels as bytes and shorts, from each buffer: exact but for
        // the lit sphere's last bits (1 unit on at most 16 channels).
        for t in ["ubyte", "ushort", "float"] {
            let file = format!("{t}.{pass}.read_ubyte");
            let (max, n) = diff(&soft.file(&file), &mesa.file(&file));
            assert!(max <= 1.0 && n <= 16, "{file}: max {max} over {n}");
            let file = format!("{t}.{pass}.read_ushort");
            let (max, n) = diff(&soft.u16s(&file), &mesa.u16s(&file));
            assert!(max <= 1.0 && n <= 16, "{file}: max {max} over {n}");
        }
    }
    // OSMesaColorClamp(GL_TRUE) changes nothing, in Mesa 22 as in softgl.
    assert_eq!(soft.file("float.0.color"), soft.file("float.1.color"));
    assert_eq!(mesa.file("float.0.color"), mesa.file("float.1.color"));
}

#[test]
fn deep_colour_framebuffer_objects_match_mesa() {
    let Some(exe) = build("deep_fbo") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Every format's sizes, completeness, GL_*_BITS while bound (16, 32;
    // alpha 0 for the RGB ones), no error; the window's 8 after.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.contains(&"rgba32f bits 32 32 32 32".to_owned()));
    assert!(soft.lines.contains(&"rgb16f bits 16 16 16 0".to_owned()));
    // The scene in each: read as bytes, identical; as shorts within 1 on at
    // most 16 channels and as floats within 2.4e-7 (1–2 ulp): the f32
    // shading's last bits (the JIT equals the interpreter here; the RGBA8
    // object's bytes are identical to llvmpipe's).
    for f in ["rgba16", "rgba32f", "rgb16", "rgb32f", "rgba16f", "rgb16f"] {
        assert_eq!(soft.file(&format!("{f}.ub")), mesa.file(&format!("{f}.ub")), "{f}.ub");
    }
    for f in ["rgba16", "rgb16"] {
        let (max, n) = diff(&soft.u16s(&format!("{f}.us")), &mesa.u16s(&format!("{f}.us")));
        assert!(max <= 1.0 && n <= 16, "{f}.us: max {max} over {n}");
    }
    // Half floats: those last bits cross a truncation (llvmpipe rounds
    // toward zero into a half) on 127 of 12288 channels: one half ulp
    // (2^-11 below 1, 2^-10 up to 2) apart there, equal elsewhere.
    for f in ["rgba16f", "rgb16f"] {
        let (a, b) = (soft.f32s(&format!("{f}.f")), mesa.f32s(&format!("{f}.f")));
        let apart: Vec<(f32, f32)> = a
            .iter()
            .zip(&b)
            .filter(|(x, y)| x != y)
            .map(|(x, y)| (*x, *y))
            .collect();
        assert!(apart.len() <= 160, "{f}.f: {} channels differ", apart.len());
        for (x, y) in apart {
            assert!(
                (x - y).abs() <= half_ulp(x.abs().max(y.abs())),
                "{f}.f: {x} against {y}"
            );
        }
    }
    // The RGB formats read alpha 1 wherever they were drawn or cleared.
    for f in ["rgb16", "rgb16f", "rgb32f"] {
        let (a, b) = (soft.f32s(&format!("{f}.f")), mesa.f32s(&format!("{f}.f")));
        assert!(a.iter().skip(3).step_by(4).all(|&v| v == 1.0), "{f}.f alpha");
        assert!(b.iter().skip(3).step_by(4).all(|&v| v == 1.0), "{f}.f alpha (llvmpipe)");
    }
    // A GL_RGBA16 texture drawn into holds what the renderbuffer does.
    assert_eq!(soft.file("tex16.us"), soft.file("rgba16.us"));
    assert_eq!(mesa.file("tex16.us"), mesa.file("rgba16.us"));
    let (max, _) = diff(&soft.f32s("rgba16.f"), &mesa.f32s("rgba16.f"));
    assert!(max <= 1.0 / 65535.0 + 1e-9, "rgba16.f: max {max}");
    for f in ["rgba32f", "rgb32f"] {
        let (max, _) = diff(&soft.f32s(&format!("{f}.f")), &mesa.f32s(&format!("{f}.f")));
        assert!(max <= 2.4e-7, "{f}.f: max {max}");
    }
    let (a, b) = (soft.f32s("rgba32f.f"), mesa.f32s("rgba32f.f"));
    // A float object is read unclamped (additive blending to 1.4 and more).
    assert!(a.iter().any(|&v| v > 1.3) && b.iter().any(|&v| v > 1.3));
    // Blits: float, shorts and bytes into one another, NEAREST 1:1 exact
    // (0–3), scaled and flipped float to shorts (4) and shorts to float (5)
    // carry the sources' differences above, LINEAR shorts to bytes (7)
    // exact; LINEAR float to float (6) within 4.1e-6 (llvmpipe's weights'
    // last bits; one byte and 24 shorts 1 off).
    for i in [0, 1, 2, 3, 7] {
        for t in ["ub", "us", "f"] {
            let file = format!("blit.{i}.{t}");
            assert_eq!(soft.file(&file), mesa.file(&file), "{file}");
        }
    }
    for i in [4, 5, 6] {
        let (max, n) = diff(&soft.u16s(&format!("blit.{i}.us")), &mesa.u16s(&format!("blit.{i}.us")));
        assert!(max <= 1.0 && n <= 32, "blit.{i}.us: max {max} over {n}");
        let (max, n) = diff(&soft.file(&format!("blit.{i}.ub")), &mesa.file(&format!("blit.{i}.ub")));
        assert!(max <= 1.0 && n <= 2, "blit.{i}.ub: max {max} over {n}");
        // 4 and 5 land in or come from shorts: one unit, 1/65535.
        let tolerance = if i == 6 { 4.1e-6 } else { 1.0 / 65535.0 + 1e-9 };
        let (max, _) = diff(&soft.f32s(&format!("blit.{i}.f")), &mesa.f32s(&format!("blit.{i}.f")));
        assert!(max <= tolerance, "blit.{i}.f: max {max}");
    }
}

/// The distance between a half float of magnitude `x` and the next (2^-24
/// among the denormals).
fn half_ulp(x: f32) -> f32 {
    let e = if x > 0.0 { x.log2().floor().max(-14.0) } else { -14.0 };
    (e - 10.0).exp2()
}

/// 4× deep colour objects resolved by `glBlitFramebuffer` into their own
/// format and into RGBA8 (`tests/c/msaa_deep.c`).
#[test]
fn multisampled_deep_colour_matches_mesa() {
    let Some(exe) = build("msaa_deep") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Complete, GL_SAMPLES 4, no error.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.contains(&"rgba32f status 0x8cd5 samples 4".to_owned()));
    for f in ["rgba16", "rgba32f", "rgba16f", "rgb16f"] {
        for k in 0..2 {
            let name = format!("{f}.{k}");
            // Bytes identical; shorts within 1 on at most 4 channels and
            // floats within 2.4e-7 (the f32 planes' last bits, as single-
            // sampled), halves identical (none crosses a truncation here).
            assert_eq!(
                soft.file(&format!("{name}.ub")),
                mesa.file(&format!("{name}.ub")),
                "{name}.ub"
            );
            let (max, n) = diff(&soft.u16s(&format!("{name}.us")), &mesa.u16s(&format!("{name}.us")));
            assert!(max <= 1.0 && n <= 4, "{name}.us: max {max} over {n}");
            let (max, _) = diff(&soft.f32s(&format!("{name}.f")), &mesa.f32s(&format!("{name}.f")));
            let tolerance = if f == "rgba16" { 1.0 / 65535.0 + 1e-9 } else { 2.4e-7 };
            assert!(max <= tolerance, "{name}.f: max {max}");
            if f.ends_with("16f") {
                assert_eq!(
                    soft.file(&format!("{name}.f")),
                    mesa.file(&format!("{name}.f")),
                    "{name}.f"
                );
            }
        }
    }
}

#[test]
fn fbo_colour_formats_match_mesa() {
    let Some(exe) = build("fbo_formats") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Formats llvmpipe stores in fewer bits than any storage softgl has
    // (B4G4R4A4, B5G5R5A1, B2G3R3, B4G4R4X4, B5G5R5X1, B10G10R10X2/A2): the
    // nearest storage with at least the bits asked for, and its sizes.
    let storage = [
        ("rgba2", "8 8 8 8", "rgba8"),
        ("rgba4", "8 8 8 8", "rgba8"),
        ("rgb5_a1", "8 8 8 8", "rgba8"),
        ("r3_g3_b2", "5 6 5 0", "rgb565"),
        ("rgb4", "5 6 5 0", "rgb565"),
        ("rgb5", "5 6 5 0", "rgb565"),
        ("rgb10", "16 16 16 0", "rgb16"),
        ("rgb10_a2", "16 16 16 16", "rgba16"),
    ];
    let sized = |l: &&String| {
        storage
            .iter()
            .any(|(f, _, _)| l.starts_with(&format!("{f} ")) && (l.contains(" sizes ") || l.contains(" bits ")))
    };
    let m: Vec<&String> = mesa.lines[1..].iter().filter(|l| !sized(l)).collect();
    let s: Vec<&String> = soft.lines[1..].iter().filter(|l| !sized(l)).collect();
    // Every other line: completeness, component types (GL_FLOAT for the
    // float formats; INVALID_OPERATION on GL_DEPTH_STENCIL_ATTACHMENT, as
    // Mesa), clears past [0, 1] (float objects store the colour as given,
    // halves truncated, GL_COLOR_CLEAR_VALUE unclamped only while a float
    // object is drawn), half-float edges bit for bit, blits' errors.
    assert_eq!(s, m);
    for (f, bits, _) in storage {
        let internal = mesa
            .lines
            .iter()
            .find(|l| l.starts_with(&format!("{f} sizes ")))
            .unwrap();
        let internal = internal.split(" internal ").nth(1).unwrap();
        assert!(
            soft.lines.contains(&format!("{f} sizes {bits} internal {internal}")),
            "{f}"
        );
        assert!(
            soft.lines.contains(&format!("{f} attachment sizes {bits} error 0x0")),
            "{f}"
        );
        assert!(soft.lines.contains(&format!("{f} bits {bits}")), "{f}");
    }
    // Their pixels are their storage's.
    for (f, _, like) in storage {
        for t in ["f", "us", "ub"] {
            assert_eq!(
                soft.file(&format!("fmt.{f}.{t}")),
                soft.file(&format!("fmt.{like}.{t}")),
                "{f}.{t}"
            );
        }
    }
    // Where the storage is llvmpipe's, the bytes are llvmpipe's; shorts and
    // floats as in `deep_colour_framebuffer_objects_match_mesa` (halves:
    // one half ulp on at most 4 channels, 3 seen).
    let same = [
        "rgb565", "rgb12", "rgba12", "rgb16", "rgba16", "rgb16f", "rgba16f", "rgb32f", "rgba32f", "rgb8", "rgba8",
    ];
    let names = same
        .iter()
        .map(|f| format!("fmt.{f}"))
        .chain((0..8).map(|i| format!("blit.{i}")));
    for name in names {
        assert_eq!(
            soft.file(&format!("{name}.ub")),
            mesa.file(&format!("{name}.ub")),
            "{name}.ub"
        );
        if name == "fmt.rgb565" {
            // Read as shorts and floats from their bytes (see the report's note).
            continue;
        }
        let (a, b) = (soft.f32s(&format!("{name}.f")), mesa.f32s(&format!("{name}.f")));
        let apart: Vec<(f32, f32)> = a
            .iter()
            .zip(&b)
            .filter(|(x, y)| x != y)
            .map(|(x, y)| (*x, *y))
            .collect();
        let half = ["fmt.rgb16f", "fmt.rgba16f", "blit.0", "blit.1", "blit.5"].contains(&name.as_str());
        if half {
            assert!(apart.len() <= 4, "{name}.f: {} channels differ", apart.len());
        }
        for (x, y) in apart {
            let tolerance = if half {
                half_ulp(x.abs().max(y.abs()))
            } else {
                1.0 / 65535.0 + 1e-9
            };
            assert!((x - y).abs() <= tolerance, "{name}.f: {x} against {y}");
        }
        let (max, n) = diff(&soft.u16s(&format!("{name}.us")), &mesa.u16s(&format!("{name}.us")));
        assert!(max <= 8.0 && n <= 4, "{name}.us: max {max} over {n}");
    }
}

#[test]
fn display_lists_match_mesa() {
    let Some(exe) = build("lists") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Compile, compile-and-execute, nesting, glCallLists with a base, a GLU
    // sphere in a list, client arrays read at compile time: the same image,
    // byte for byte, and the same list state and errors.
    let image = soft.file("lists.color");
    assert_eq!(image, mesa.file("lists.color"));
    let lit = image.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 1000, "only {lit} pixels drawn");
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}

#[test]
fn quads_from_display_lists_split_as_mesa() {
    let Some(exe) = build("list_quads") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Quads drawn at once split v0-v2, from a list v1-v3 (Mesa replays a
    // list's glBegin/glEnd as indexed vertices, docs/llvmpipe-facts.md §37):
    // smooth per-vertex colours and lit quads, byte for byte (before the
    // split followed this, 1696 pixels differed, the lit ones by up to 39).
    let image = soft.file("list_quads.color");
    assert_eq!(image, mesa.file("list_quads.color"));
    let lit = image.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 3000, "only {lit} pixels drawn");
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}

#[test]
fn buffer_objects_match_mesa() {
    let Some(exe) = build("buffers") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Arrays and indices in buffer objects, every way GL 1.5 draws them, and
    // reads past a buffer's end (zeros, index 0, as llvmpipe): the same
    // image, byte for byte, and the same state, queries and errors.
    let image = soft.file("buffers.color");
    let differ = image
        .chunks_exact(4)
        .zip(mesa.file("buffers.color").chunks_exact(4))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differ, 0, "pixels differing from llvmpipe's");
    let lit = image.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 3000, "only {lit} pixels drawn");
    // Mesa 22 does not check a draw that reads a mapped buffer; GL 1.5
    // (§2.9.3) makes it GL_INVALID_OPERATION, as softgl does.
    let mapped = |r: &Run| r.lines.iter().position(|l| l.starts_with("mapped draw")).unwrap();
    assert_eq!(soft.lines[mapped(&soft)], "mapped draw 0x0502");
    let rest = |r: &Run| {
        let m = mapped(r);
        r.lines[1..]
            .iter()
            .enumerate()
            .filter(|(i, _)| i + 1 != m)
            .map(|(_, l)| l.clone())
            .collect::<Vec<_>>()
    };
    assert_eq!(rest(&soft), rest(&mesa));
}

#[test]
fn occlusion_query_counts_match_mesa() {
    let Some(exe) = build("queries") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Exact GL_SAMPLES_PASSED counts (every primitive type; scissor, alpha,
    // stencil and depth rejecting; none drawn; several draws; a list), the
    // availability as llvmpipe answers it, the state and the errors.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    let counted = |r: &Run, what: &str| -> u32 {
        let l = r.lines.iter().find(|l| l.starts_with(what)).unwrap();
        l[what.len()..].split_whitespace().next().unwrap().parse().unwrap()
    };
    assert_eq!(counted(&soft, "nearer"), 1001);
    assert_eq!(counted(&soft, "all again, depth rejects"), 0);
    let image = soft.file("queries.color");
    let differ = image
        .chunks_exact(4)
        .zip(mesa.file("queries.color").chunks_exact(4))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differ, 0, "pixels differing from llvmpipe's");
}

#[test]
fn point_parameters_transposed_matrices_and_sample_coverage_match_mesa() {
    let Some(exe) = build("gl14") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Points bounded and attenuated with distance under a perspective
    // projection (the sizes as Mesa's fixed-function vertex program makes
    // them): the same image, byte for byte; the state, queries and errors.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    let image = soft.file("gl14.color");
    let differ = image
        .chunks_exact(4)
        .zip(mesa.file("gl14.color").chunks_exact(4))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differ, 0, "pixels differing from llvmpipe's");
    let lit = image.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 3000, "only {lit} pixels drawn");
}

#[test]
fn fog_and_the_colour_sum_match_mesa() {
    let Some(exe) = build("fog") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    for k in 0..11 {
        let name = format!("fog.{k}");
        let (m, s) = (mesa.file(&name), soft.file(&name));
        let differing = m.chunks_exact(4).zip(s.chunks_exact(4)).filter(|(a, b)| a != b).count();
        // Scene 9 (points and wide lines): one pixel at a line endpoint tie,
        // where llvmpipe's diamond tests are asymmetric (docs/llvmpipe-facts.md
        // §11; 3 pixels with fog off). Every triangle scene is byte for byte.
        let allowed = if k == 9 { 3 } else { 0 };
        assert!(differing <= allowed, "scene {k}: {differing} pixels differ");
    }
    // Something was drawn in every scene: not all pixels the clear colour.
    for k in 0..11 {
        let img = soft.file(&format!("fog.{k}"));
        let drawn = img.chunks_exact(4).filter(|p| p[..3] != [26, 51, 77]).count();
        assert!(drawn > 500, "scene {k}: only {drawn} pixels drawn");
    }
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}

#[test]
fn textured_spheres_match_mesa() {
    let Some(exe) = build("textured") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // The texture state read back (gluBuild2DMipmaps' levels, formats and
    // component sizes, parameters, the environment, the attribute stack) and
    // the error of every bad call: Mesa's, line for line.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    let (a, b) = (soft.file("textured.color"), mesa.file("textured.color"));
    // Six 128x128 scenes, three a row (bottom row first) in a 384x256 image.
    let scene = |img: &[u8], k: usize| -> Vec<u8> {
        let (x0, y0) = ((k % 3) * 128, (k / 3) * 128);
        (y0..y0 + 128)
            .flat_map(|y| img[(y * 384 + x0) * 4..(y * 384 + x0 + 128) * 4].to_vec())
            .collect()
    };
    let counts: Vec<(f64, usize)> = (0..6).map(|k| diff(&scene(&a, k), &scene(&b, k))).collect();
    println!("textured: per scene (max channel difference, channels differing): {counts:?}");
    let drawn = |img: &[u8]| img.chunks_exact(4).filter(|p| p[..3] != [13, 13, 26]).count();
    for k in 0..6 {
        assert!(drawn(&scene(&a, k)) > 5000, "scene {k} drew too little");
    }
    assert!(counts.iter().all(|&(max, _)| max <= TEXTURED_MAX), "{counts:?}");
    assert!(
        counts.iter().map(|c| c.1).sum::<usize>() <= TEXTURED_CHANNELS,
        "{counts:?}"
    );
}

/// The textured scenes' tolerance: one step, in at most 30 channels of the
/// 6 x 65536. Measured: 10 channels in 9 pixels one step apart (scenes 0-5:
/// 2, 1, 3, 2, 0, 2), on the trilinear sphere and the bilinear ones alike,
/// coverage identical; the rest of the 6 scenes byte for byte.
const TEXTURED_MAX: f64 = 1.0;
const TEXTURED_CHANNELS: usize = 30;

#[test]
fn contexts_on_threads_are_independent() {
    let Some(exe) = build("threads") else { return };
    for softgl in [false, true] {
        let r = run(&exe, softgl);
        for i in 0..4 {
            assert!(r.lines.contains(&format!("thread {i} failures 0")), "{:?}", r.lines);
        }
        assert!(r.lines.contains(&"main thread current 1".to_owned()));
    }
}

#[test]
fn ldd_shows_softgls_library() {
    let Some(exe) = build("threads") else { return };
    let out = Command::new("ldd")
        .arg(&exe)
        .env("LD_LIBRARY_PATH", lib_dir())
        .output()
        .expect("ldd");
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text
        .lines()
        .find(|l| l.contains("libOSMesa.so.8"))
        .expect("libOSMesa.so.8 in ldd");
    assert!(line.contains(&lib_dir().display().to_string()), "{line}");
    // The file's SONAME is Mesa's, so programs linked against either find it.
    let out = Command::new("readelf")
        .args(["-d"])
        .arg(lib_dir().join("libOSMesa.so.8"))
        .output();
    if let Ok(out) = out {
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("[libOSMesa.so.8]"), "{text}");
    }
}

#[test]
fn glu_calls_all_resolve_in_softgl() {
    // Debian's libGLU.so.1 resolves its gl* calls in whichever library
    // exports them first: every one must be ours.
    if !have("GLU's gl* calls", &[Need::Nm, Need::Glu]) {
        return;
    }
    let names = osmesa_exports();
    let out = Command::new("nm")
        .args(["-D", "/usr/lib/x86_64-linux-gnu/libGLU.so.1"])
        .output()
        .expect("nm (binutils)");
    let text = String::from_utf8_lossy(&out.stdout);
    let needed: Vec<&str> = text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("U "))
        .filter(|n| n.starts_with("gl"))
        .collect();
    assert!(needed.len() > 30, "libGLU.so.1 needs {} gl functions?", needed.len());
    for n in needed {
        assert!(names.iter().any(|e| e == n), "{n} is not exported");
    }
}

/// The dynamic symbols softgl's library defines.
fn osmesa_exports() -> Vec<String> {
    let out = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(lib_dir().join("libOSMesa.so"))
        .output()
        .expect("nm (binutils)");
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| l.split_whitespace().nth(2).map(str::to_owned))
        .collect()
}

#[test]
fn every_export_is_reachable_through_get_proc_address() {
    if !have("exports through nm", &[Need::Nm]) {
        return;
    }
    let exports = osmesa_exports();
    for name in OSMesa::exported_names() {
        assert!(exports.iter().any(|e| e == name), "{name} is listed but not exported");
    }
    let gl_exports = exports
        .iter()
        .filter(|e| e.starts_with("gl") && !e.starts_with("glX"))
        .count();
    assert_eq!(gl_exports, OSMesa::exported_names().len());
    assert!(gl_exports > 300, "{gl_exports} gl exports");
}

#[test]
fn pyopengl_draws_and_reads_back() {
    if !have("PyOpenGL client", &[Need::PyOpenGl]) {
        return;
    }
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/pyopengl_osmesa.py");
    let out = Command::new("python3")
        .arg(&script)
        .env("PYOPENGL_PLATFORM", "osmesa")
        .env("LD_LIBRARY_PATH", lib_dir())
        .env("SOFTGL_OSMESA_DIR", lib_dir())
        .output()
        .expect("run python3");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "PyOpenGL script failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("renderer softgl"), "{stdout}");
    assert!(stdout.lines().last() == Some("ok"), "{stdout}");
}

/// `glGetFramebufferAttachmentParameteriv` on the default framebuffer
/// (piglit's probes ask it for the read buffer's sizes once
/// ARB_framebuffer_object is listed): every attachment × pname, value and
/// error, for three visuals: Mesa's, line for line.
#[test]
fn default_framebuffer_attachment_queries_match_mesa() {
    let Some(exe) = build("fb0") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(
        soft.lines.contains(&"fb 0x0402 0x8212: 8 0x0000".to_string()),
        "BACK_LEFT RED_SIZE"
    );
    assert!(soft.lines.len() > 700, "{} lines", soft.lines.len());
}

#[test]
fn window_framebuffer_attachment_queries_match_mesa() {
    let Some(exe) = build("window_fb") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // glGetFramebufferAttachmentParameteriv on object 0 (piglit's probes ask
    // it once ARB_framebuffer_object is listed): every value and error,
    // Mesa's, line for line, on nine window configurations.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert_eq!(soft.lines.len(), 9 * (1 + 3 * 14 * 14 + 1) + 2);
    assert!(soft
        .lines
        .contains(&"0x8d40 BACK_LEFT RED_SIZE = 0x8 error 0x0".to_string()));
}

#[test]
fn framebuffer_objects_match_mesa() {
    let Some(exe) = build("fbo") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Every status, query and error: Mesa's, line for line.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    // MuJoCo's path: the resolved RGB bytes (pack alignment 1) and stencil,
    // render to texture then sampling (LINEAR and after glGenerateMipmap),
    // the shadow map sampled with compare, LINEAR blits scaled up and down
    // and scissored: byte for byte.
    for name in [
        "fbo.resolve.rgb",
        "fbo.resolve.stencil",
        "fbo.rtt",
        "fbo.shadow.sampled",
        "fbo.blit.linear_up",
        "fbo.blit.linear_down",
    ] {
        assert_eq!(soft.file(name), mesa.file(name), "{name}");
    }
    let drawn = soft
        .file("fbo.resolve.rgb")
        .chunks(3)
        .filter(|p| *p != [26, 51, 77])
        .count();
    assert!(drawn > 2000, "only {drawn} pixels drawn");
    // Depth read back as GL_FLOAT: within 2 units of 2^24, the rasterizer's
    // known depth difference on sloped triangles (clients.rs, formats test);
    // the clears and flat regions are exact. Measured: 1 f32 ulp at 0.5.
    for name in ["fbo.resolve.depth", "fbo.blit.depth", "fbo.shadow.depth"] {
        let (a, b) = (soft.f32s(name), mesa.f32s(name));
        let (max, n) = diff(&a, &b);
        println!("{name}: max {max:e} over {n} of {} values", a.len());
        assert!(max <= 2.0 / 16_777_215.0, "{name}: {max}");
    }
    // NEAREST blits, scaled and flipped: byte for byte except where a
    // destination pixel centre maps exactly onto a texel edge, which
    // llvmpipe's blit quad resolves by its per-block f32 interpolation
    // (either texel): here the 34 pixels of row 42, (42.5 · 64/85 = 32).
    let (a, b) = (soft.file("fbo.blit.nearest"), mesa.file("fbo.blit.nearest"));
    let differing: Vec<usize> = (0..a.len() / 4)
        .filter(|&i| a[4 * i..4 * i + 4] != b[4 * i..4 * i + 4])
        .collect();
    assert!(differing.len() <= 34, "{} pixels differ", differing.len());
    assert!(differing.iter().all(|&i| i / 192 == 42), "only the tie row differs");
}

#[test]
fn multisampled_framebuffer_objects_match_mesa() {
    let Some(exe) = build("msaa_fbo") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // GL_SAMPLES/GL_SAMPLE_BUFFERS (window, object, after rebinding), the
    // renderbuffer sample counts, the errors of reads and blits: Mesa's.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    // MuJoCo's frame in a 4x object (depth-tested smooth triangles, blended
    // ones, bitmap text in front of and behind them, stencil), resolved by
    // blits and read back as RGB bytes, and the window drawn between two
    // frames of the object: byte for byte.
    for name in ["msaa.1.rgb", "msaa.2.rgb", "msaa.window"] {
        assert_eq!(soft.file(name), mesa.file(name), "{name}");
        let clear = soft.file(name)[..3].to_vec();
        let drawn = soft.file(name).chunks(3).filter(|p| *p != clear.as_slice()).count();
        assert!(drawn > 2000, "{name}: only {drawn} pixels drawn");
    }
    // GL_MULTISAMPLE off: the single-sampled frame's bytes in every sample,
    // resolved into the window; it and the single-sampled frame differ from
    // llvmpipe's in the same bytes (3, by 1: the smooth-colour interpolation
    // difference of the single-sampled rasterizer, not multisampling).
    assert_eq!(soft.file("msaa.3.rgb"), soft.file("msaa.3.single.rgb"));
    assert_eq!(mesa.file("msaa.3.rgb"), mesa.file("msaa.3.single.rgb"));
    let (m, s) = (mesa.file("msaa.3.rgb"), soft.file("msaa.3.rgb"));
    let off: Vec<i32> = m
        .iter()
        .zip(&s)
        .filter(|(a, b)| a != b)
        .map(|(a, b)| i32::from(*a) - i32::from(*b))
        .collect();
    assert!(off.len() <= 3 && off.iter().all(|d| d.abs() <= 1), "{off:?}");
    // Depth resolved (sample 0's, as llvmpipe's blit) and read as GL_FLOAT:
    // within 2 units of 2^24, the rasterizer's known depth difference on
    // sloped triangles (as `framebuffer_objects_match_mesa`).
    for name in ["msaa.1.depth", "msaa.2.depth"] {
        let (a, b) = (soft.f32s(name), mesa.f32s(name));
        let (max, n) = diff(&a, &b);
        println!("{name}: max {max:e} over {n} of {} values", a.len());
        assert!(max <= 2.0 / 16_777_215.0, "{name}: {max}");
    }
}

#[test]
fn raster_positions_and_bitmaps_match_mesa() {
    let Some(exe) = build("bitmaps") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Text from glBitmap display lists placed with glRasterPos/glWindowPos,
    // bitmaps with depth test, blending, alpha test, logic op, masks, fog,
    // lighting, clip planes, unpack state, scissor and stencil, raster
    // positions off-screen and on the boundary: byte for byte.
    for k in 0..8 {
        let name = format!("bitmaps.{k}");
        let (m, s) = (mesa.file(&name), soft.file(&name));
        let clear = s[s.len() - 4..].to_vec();
        if k == 3 {
            // Fog: llvmpipe does not fog bitmaps (its quad has fog coordinate
            // 0, `docs/llvmpipe-facts.md` §26); softgl fogs them at the raster
            // distance as GL says. The same pixels are drawn; llvmpipe's in
            // the raster colour (0.2, 0.3, 1: 51, 76, 255), softgl's between it and the
            // fog colour (0.9, 0.8, 0.1), each channel.
            for (a, b) in m.chunks_exact(4).zip(s.chunks_exact(4)) {
                assert_eq!(a == clear.as_slice(), b == clear.as_slice(), "scene 3: coverage");
                if a != clear.as_slice() {
                    assert_eq!(a[..3], [51, 76, 255]);
                    let fog = [230u8, 204, 26];
                    for c in 0..3 {
                        let (lo, hi) = (a[c].min(fog[c]), a[c].max(fog[c]));
                        assert!((lo..=hi).contains(&b[c]), "scene 3: {b:?} is not fogged {a:?}");
                    }
                    assert_ne!(a[..3], b[..3], "scene 3: not fogged");
                }
            }
            continue;
        }
        let differing = m.chunks_exact(4).zip(s.chunks_exact(4)).filter(|(a, b)| a != b).count();
        assert_eq!(differing, 0, "scene {k}: {differing} pixels differ");
        // Something was drawn: pixels other than the clear colour.
        let drawn = s.chunks_exact(4).filter(|p| *p != clear.as_slice()).count();
        assert!(drawn > 100, "scene {k}: only {drawn} pixels drawn");
    }
    // The raster state read back (position, validity, distance, colours,
    // texture coordinates), through glPushAttrib, and the errors.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}

#[test]
fn draw_pixels_copy_pixels_and_pixel_transfer_match_mesa() {
    let Some(exe) = build("drawpix") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    let px = |r: &Run, name: &str| r.file(name);
    for k in 0..9 {
        let name = format!("drawpix.{k}");
        let (m, s) = (px(&mesa, &name), px(&soft, &name));
        // Scene 8 (GL_MAP_COLOR): red and green only; Mesa's blue and alpha
        // look-ups sample the image, not the maps (a bug in its
        // `nir_lower_drawpixels.c`: the second look-up has no texture).
        let channels = if k == 8 { 0..2 } else { 0..4 };
        let (mut differing, mut worst) = (0, 0);
        for (a, b) in m.chunks_exact(4).zip(s.chunks_exact(4)) {
            let d = channels.clone().map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0);
            differing += usize::from(d != 0);
            worst = worst.max(d);
        }
        // Scene 0: 2 pixels of the GL_INT image 1 step apart (the 32-bit
        // signed to float conversion). Scene 1 (zooms): 30 pixels where a
        // centre lies exactly on a boundary between source pixels (zoom
        // -1.5), which llvmpipe's two triangles round apart.
        let (allowed, step) = match k {
            0 => (2, 1),
            1 => (30, 255),
            _ => (0, 0),
        };
        assert!(
            differing <= allowed && worst <= step,
            "scene {k}: {differing} pixels differ, by up to {worst}"
        );
        let clear = [26, 51, 76, 128];
        let drawn = s.chunks_exact(4).filter(|p| *p != clear).count();
        assert!(drawn > 100, "scene {k}: only {drawn} pixels drawn");
        // Stencil identical; depth identical but for glCopyPixels(GL_DEPTH)
        // (scene 5), within 1 step of 24 bits: llvmpipe samples and writes
        // the depth as floats.
        assert_eq!(
            px(&soft, &format!("{name}.s")),
            px(&mesa, &format!("{name}.s")),
            "scene {k} stencil"
        );
        let (mz, sz) = (soft.f32s(&format!("{name}.z")), mesa.f32s(&format!("{name}.z")));
        let (dz, _) = diff(&mz, &sz);
        let tolerance = if k == 5 { 1.0 / 16777215.0 + 1e-9 } else { 0.0 };
        assert!(dz <= tolerance, "scene {k}: depth differs by {dz}");
    }
    // Pixel state, maps, the attribute stack and errors: the same lines.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}

#[test]
fn line_and_polygon_stipple_match_mesa() {
    let Some(exe) = build("stipple") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    let mut report = Vec::new();
    for k in 0..10 {
        let name = format!("stipple.{k}");
        let (m, s) = (mesa.file(&name), soft.file(&name));
        let differing = m.chunks_exact(4).zip(s.chunks_exact(4)).filter(|(a, b)| a != b).count();
        let drawn = s.chunks_exact(4).filter(|p| p[..3] != [26, 51, 76]).count();
        report.push((k, differing, drawn));
    }
    for &(k, differing, drawn) in &report {
        // Scenes 0 and 4 (separate lines; triangles as lines): a dash's last
        // pixel one row off where the line crosses a row boundary within f32
        // rounding: llvmpipe's line set-up (`lp_setup_line.c`) places a
        // dash's corners through dy/dx, softgl's (`raster/line.rs`) from its
        // end points. Every other scene is byte for byte.
        let allowed = match k {
            0 => 4,
            4 => 1,
            _ => 0,
        };
        assert!(
            differing <= allowed,
            "scene {k}: {differing} pixels differ ({report:?})"
        );
        assert!(drawn > 100, "scene {k}: only {drawn} pixels drawn");
    }
    assert_eq!(soft.file("stipple.get"), mesa.file("stipple.get"));
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}

#[test]
fn packed_depth_stencil_matches_mesa() {
    let Some(exe) = build("packed") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Every error, status and level query: Mesa's, line for line.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    // DEPTH_STENCIL round trips, depth read as UNSIGNED_INT, stencil and
    // depth drawn into a DS texture on DEPTH_STENCIL_ATTACHMENT, and the
    // 4096² shadow map sampled with compare and eye-linear texgen: byte for byte.
    for name in [
        "packed.get.ds",
        "packed.get.z",
        "packed.get.sub",
        "packed.get.ds2",
        "packed.get.z24",
        "packed.shadow",
    ] {
        assert_eq!(soft.file(name), mesa.file(name), "{name}");
    }
    // Depth and stencil drawn into a DS texture: stencil exact; depth within
    // 2 units of 2^24, the rasterizer's known depth difference on sloped
    // triangles (see the formats and fbo tests); the clear is exact.
    let (a, b) = (soft.u32s("packed.fbo.ds"), mesa.u32s("packed.fbo.ds"));
    assert_eq!(
        a.iter().map(|v| v & 0xff).collect::<Vec<_>>(),
        b.iter().map(|v| v & 0xff).collect::<Vec<_>>()
    );
    let (max, n) = diff(
        &a.iter().map(|v| v >> 8).collect::<Vec<_>>(),
        &b.iter().map(|v| v >> 8).collect::<Vec<_>>(),
    );
    println!("packed.fbo.ds depth: max {max} over {n} of {}", a.len());
    assert!(max <= 2.0, "packed.fbo.ds depth: {max}");
    // glReadPixels of DEPTH_STENCIL after a sloped triangle, then glDrawPixels
    // (zoomed, stencil write mask 0x7f; again with the depth mask off) and
    // glCopyPixels of DEPTH_STENCIL: stencil exact, depth within the same 2 units.
    for name in ["packed.read", "packed.draw", "packed.draw.nodepth", "packed.copy"] {
        let (a, b) = (soft.u32s(name), mesa.u32s(name));
        let stencil = |v: &[u32]| v.iter().map(|v| v & 0xff).collect::<Vec<_>>();
        assert_eq!(stencil(&a), stencil(&b), "{name} stencil");
        let depth = |v: &[u32]| v.iter().map(|v| v >> 8).collect::<Vec<_>>();
        let (max, n) = diff(&depth(&a), &depth(&b));
        println!("{name} depth: max {max} over {n} of {}", a.len());
        assert!(max <= 2.0, "{name} depth: {max}");
    }
    // Both stencil outcomes occur: REPLACE (0x5a) where depth passed, INCR (3 + 1) where it failed.
    assert!(b.iter().any(|v| v & 0xff == 0x5a) && b.iter().any(|v| v & 0xff == 4));
    let shadow = soft.file("packed.shadow");
    let lit = shadow.chunks(4).filter(|p| p[0] == 255).count();
    let dark = shadow.chunks(4).filter(|p| p[0] == 0).count();
    assert!(lit > 1000 && dark > 100, "lit {lit}, shadowed {dark}");
}

#[test]
fn evaluators_match_mesa() {
    let Some(exe) = build("eval") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Curves, lit and rational patches with GL_AUTO_NORMAL, texture and
    // colour maps, glEvalCoord/glEvalPoint, a compiled glMap: the same
    // image, byte for byte, and the same glGetMap values and errors.
    let image = soft.file("eval.color");
    let lit = image.chunks_exact(4).filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(lit > 2000, "only {lit} pixels drawn");
    // Mesa's current values after evaluation are not GL's (its
    // `vbo_exec_EvalCoord*` copies the vertex back after resizing its
    // attributes: alpha 0, the normal and texture coordinates read from the
    // colour); GL 1.5 §5.1 leaves them unchanged, as softgl does.
    let (cur, other): (Vec<_>, Vec<_>) = soft.lines[1..].iter().partition(|l| l.starts_with("current"));
    let mesa_other: Vec<_> = mesa.lines[1..].iter().filter(|l| !l.starts_with("current")).collect();
    assert_eq!(other, mesa_other);
    assert_eq!(
        cur,
        [
            "current colour after mesh1 0.25 0.5 0.75 1",
            "current colour after evalcoord 1 1 1 1",
            "current normal after autonormal 0 0 1",
            "current texcoord 0 0 0 1",
            "current colour after mesh2 1 1 1 1",
        ]
    );
    // Every pixel is llvmpipe's but 7, none of them an evaluator's doing
    // (the coverage is the same, so the evaluated positions are): the
    // shared pixel where two segments of a line strip meet at a
    // half-integer x (llvmpipe leaves it to neither segment or to the other
    // one: (45, 75), (16, 85) on the list's line, whose joints are at
    // x = 16.5, 45.5; (69, 8), (69, 17), (69, 26) on a flat strip), and 2
    // point colours one level apart (an exact .5 tie, 0.5 · 255, converted
    // to 8 bits).
    let mesa_image = mesa.file("eval.color");
    let differ: Vec<(usize, usize)> = (0..image.len() / 4)
        .filter(|&p| image[p * 4..p * 4 + 4] != mesa_image[p * 4..p * 4 + 4])
        .map(|p| (p % 128, p / 128))
        .collect();
    assert_eq!(
        differ,
        [(69, 8), (113, 15), (69, 17), (112, 22), (69, 26), (45, 75), (16, 85)]
    );
}

#[test]
fn selection_and_feedback_match_mesa() {
    let Some(exe) = build("select") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Hit records (names, min/max window z scaled to 2^32 - 1), feedback
    // buffers of every type (tokens, window coordinates after clipping,
    // colours, texture coordinates), culling, polygon modes, overflow, the
    // name stack's errors and the state read back: the same, value for value.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    assert!(soft.lines.len() > 2000, "{} lines", soft.lines.len());
    assert!(soft.lines.iter().any(|l| l == "select: hits 7"));
    assert!(soft.lines.iter().any(|l| l == "drawn 0"));
}

/// Depth within `tol` (absolute, window depth) of Mesa's, per value; prints how far.
fn near_depths(name: &str, a: &[f32], b: &[f32], tol: f32) {
    assert_eq!(a.len(), b.len(), "{name}: sizes differ");
    let (mut max, mut n) = (0.0f32, 0);
    for (x, y) in a.iter().zip(b) {
        let d = (x - y).abs();
        max = max.max(d);
        n += usize::from(x.to_bits() != y.to_bits());
    }
    println!("{name}: {n} of {} differ, by at most {max:e}", a.len());
    assert!(max <= tol, "{name}: {max:e} > {tol:e}");
}

#[test]
fn float_depth_and_clip_control_match_mesa() {
    let Some(exe) = build("depthfloat") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    // Both extensions listed; glClipControl's errors, its state through
    // display lists and glPushAttrib(GL_TRANSFORM_BIT); the raster position
    // under each mode; renderbuffer and texture sizes, completeness, the
    // blit between depth formats (INVALID_OPERATION) and the transfer
    // type's errors: Mesa's, line for line.
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
    // Colour of every scene (reverse Z into DEPTH32F_STENCIL8, GL_UPPER_LEFT
    // with culling, polygon offset with a depth range, plain GL depth), and
    // the float shadow map sampled with compare: byte for byte.
    for name in [
        "reverse.rgba",
        "upper.rgba",
        "offset.rgba",
        "plain.rgba",
        "shadow.sampled",
        "shadow.outside.gequal",
        "shadow.outside.less",
    ] {
        assert_eq!(soft.file(name), mesa.file(name), "{name}");
    }
    // A DEPTH_COMPONENT32F texture's upload (clamped) and readback as
    // GL_FLOAT and GL_UNSIGNED_INT, and glDrawPixels/glCopyPixels of float
    // depth: exact.
    // GL_FLOAT_32_UNSIGNED_INT_24_8_REV into DEPTH32F_STENCIL8 and
    // DEPTH24_STENCIL8 textures, read back both ways, and drawn with glDrawPixels.
    for name in [
        "tex.get.zf",
        "tex.get.zui",
        "pixels.zf",
        "tex32f.get.ds2",
        "tex32f.get.ds",
        "drawpix.ds2",
    ] {
        assert_eq!(soft.file(name), mesa.file(name), "{name}");
    }
    // Into DEPTH24_STENCIL8: stencil exact, depth within one unit of 2^24 (softgl
    // keeps Z24 texels as the floats the sampler reads, where neighbouring
    // values can share one: `unpack::depth_unsampled`).
    let (a, b) = (soft.u32s("tex24.get.ds"), mesa.u32s("tex24.get.ds"));
    assert!(a
        .iter()
        .zip(&b)
        .all(|(x, y)| x & 0xff == y & 0xff && (x >> 8).abs_diff(y >> 8) <= 1));
    let (a, b) = (soft.u32s("tex24.get.ds2"), mesa.u32s("tex24.get.ds2"));
    assert!(a
        .chunks(2)
        .zip(b.chunks(2))
        .all(|(x, y)| x[1] == y[1] && x[0].abs_diff(y[0]) <= 1));
    // Depth of sloped triangles: softgl's plane evaluation is within 4 units
    // of 2^-24 of llvmpipe's f32 (measured ≤ 2.4e-7; the same difference that
    // 24-bit depth shows as ≤ 2 units, see `packed_depth_stencil_matches_mesa`).
    const TOL: f32 = 4.0 / 16_777_216.0;
    for scene in ["reverse", "upper", "offset", "plain"] {
        let (a, b) = (soft.f32s(&format!("{scene}.zf")), mesa.f32s(&format!("{scene}.zf")));
        near_depths(&format!("{scene}.zf"), &a, &b, TOL);
        // GL_UNSIGNED_INT: `(uint32_t)(z · 0xffffffff)` of the same floats.
        let (a, b) = (soft.u32s(&format!("{scene}.zui")), mesa.u32s(&format!("{scene}.zui")));
        let (max, _) = diff(&a, &b);
        assert!(max <= f64::from(TOL) * 4_294_967_295.0 + 1.0, "{scene}.zui: {max}");
        // DEPTH_STENCIL as UNSIGNED_INT_24_8 and FLOAT_32_UNSIGNED_INT_24_8_REV:
        // stencil exact (cleared to 0x35), depth as above.
        let (a, b) = (soft.u32s(&format!("{scene}.ds")), mesa.u32s(&format!("{scene}.ds")));
        assert!(
            a.iter().zip(&b).all(|(x, y)| x & 0xff == y & 0xff),
            "{scene}.ds stencil"
        );
        let (max, _) = diff(
            &a.iter().map(|v| v >> 8).collect::<Vec<_>>(),
            &b.iter().map(|v| v >> 8).collect::<Vec<_>>(),
        );
        assert!(max <= 5.0, "{scene}.ds depth: {max}");
        let (a, b) = (soft.u32s(&format!("{scene}.ds2")), mesa.u32s(&format!("{scene}.ds2")));
        let words = |v: &[u32]| v.chunks(2).map(|p| p[1]).collect::<Vec<_>>();
        assert_eq!(words(&a), words(&b), "{scene}.ds2 stencil words");
        assert!(
            b.chunks(2).all(|p| p[1] == 0x35),
            "{scene}.ds2: stencil 0x35 in the low byte"
        );
        let floats = |v: &[u32]| v.chunks(2).map(|p| f32::from_bits(p[0])).collect::<Vec<_>>();
        near_depths(&format!("{scene}.ds2"), &floats(&a), &floats(&b), TOL);
    }
    // The shadow map rendered with MuJoCo's offset, and a float-to-float blit.
    for name in ["shadow.zf", "blit.zf"] {
        near_depths(name, &soft.f32s(name), &mesa.f32s(name), TOL);
    }
    // The scenes drew something, and reverse Z kept the near surfaces.
    let z = mesa.f32s("reverse.zf");
    assert!(z.iter().filter(|&&v| v > 0.5).count() > 200 && z.contains(&0.0));
}

/// The pixel-path gaps of issue 14 (`tests/c/pixgaps.c`): textured pixel
/// rectangles, pixel transfer on texture uploads, copies and glReadPixels.
#[test]
fn pixel_gaps_match_mesa() {
    let Some(exe) = build("pixgaps") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    let (w, h) = (64, 48);
    for k in 0..2 {
        let name = format!("pixgaps.{k}");
        let (m, s) = (mesa.file(&name), soft.file(&name));
        let px = |b: &[u8], x: usize, y: usize| -> [u8; 4] { b[4 * (y * w + x)..][..4].try_into().unwrap() };
        // Scene 1, rows 16..: the glCopyTexImage2D/glCopyTexSubImage2D
        // textures. Mesa's copy through the transfer operations
        // (`fallback_copy_texsubimage`) reads rows in the wrong order and
        // past the region (zeros), so these are checked against GL's rule:
        // each source pixel as f32, red ×0.75, green ×1.5, blue −0.2,
        // clamped, rounded (±1: f32 against Mesa's exact conversions).
        let rows = if k == 1 { 16 } else { h };
        for y in 0..rows {
            for x in 0..w {
                assert_eq!(px(&m, x, y), px(&s, x, y), "scene {k}: pixel ({x}, {y})");
            }
        }
        if k == 1 {
            let transfer = |c: [u8; 4]| {
                let f = c.map(|v| f32::from(v) / 255.0);
                let t = [f[0] * 0.75, f[1] * 1.5, f[2] - 0.2, f[3]];
                t.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
            };
            // The 16×8 texture on quads 32×32: texel (i, j) at pixel (2i, 16 + 4j).
            for j in 0..8 {
                for i in 0..16 {
                    let first = transfer(px(&s, 8 + i, 4 + j));
                    let sub = if (4..12).contains(&i) && (2..6).contains(&j) {
                        transfer(px(&s, 40 + i - 4, 4 + j - 2))
                    } else {
                        first
                    };
                    for (x0, want) in [(0, first), (32, sub)] {
                        let got = px(&s, x0 + 2 * i, 16 + 4 * j);
                        let d = (0..4).map(|c| got[c].abs_diff(want[c])).max().unwrap();
                        assert!(
                            d <= 1,
                            "scene 1: copied texel ({i}, {j}) at x {x0}: {got:?}, not {want:?}"
                        );
                    }
                }
            }
        }
        let clear = s[s.len() - 4..].to_vec();
        let drawn = s.chunks_exact(4).filter(|p| *p != clear.as_slice()).count();
        assert!(drawn > 100, "scene {k}: only {drawn} pixels drawn");
    }
    // glReadPixels through the transfer operations: as Mesa, but for
    // GL_FLOAT (line 5), which Mesa leaves unclamped after scale and bias;
    // GL clamps every RGBA component in its final conversion (§4.3.2).
    for (i, (a, b)) in mesa.lines.iter().zip(&soft.lines).enumerate().skip(1) {
        if i == 4 {
            let vals = |l: &str| l.split(' ').map(|v| v.parse::<f32>().unwrap()).collect::<Vec<_>>();
            let clamped: Vec<f32> = vals(a).iter().map(|v| v.min(1.0)).collect();
            assert_eq!(vals(b), clamped, "GL_FLOAT read");
        } else {
            assert_eq!(a, b, "line {i}");
        }
    }
}

/// Alpha to coverage and alpha to one in a 4× framebuffer object, and
/// drawing with GL_MULTISAMPLE off after multisampled drawing (depth and
/// stencil of sample 0), bitmaps and pixel rectangles (alpha above 0.5
/// keeps them), `tests/c/a2c.c`: resolved, against llvmpipe byte for byte.
#[test]
fn alpha_to_coverage_matches_mesa() {
    let Some(exe) = build("a2c") else { return };
    let (mesa, soft) = (run(&exe, false), run(&exe, true));
    for k in 0..7 {
        let name = format!("a2c.{k}");
        let (m, s) = (mesa.file(&name), soft.file(&name));
        let differing: Vec<usize> = (0..m.len() / 4)
            .filter(|&i| m[4 * i..][..4] != s[4 * i..][..4])
            .collect();
        assert!(
            differing.is_empty(),
            "scene {k}: {} pixels differ, first at {:?}",
            differing.len(),
            differing.first().map(|i| (i % 64, i / 64))
        );
    }
    assert_eq!(soft.lines[1..], mesa.lines[1..]);
}
