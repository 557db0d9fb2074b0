//! Golden images: scenes rendered through the Rust API, compared exactly with
//! the PNGs in `tests/golden/`.
//!
//! Tolerance is 0: softgl is deterministic (fixed-point rasterization, integer
//! fragment stages), so any difference is a change in behavior to look at. On a
//! mismatch the test writes `<name>.actual.png` and `<name>.diff.png` (differing
//! pixels in red, brighter for larger differences, over a dimmed copy of the
//! expected image) to `golden-diff/` in the cargo target directory, and fails
//! with the number of differing pixels and the largest channel difference.
//! `SOFTGL_BLESS=1` (re)writes the stored PNGs instead; without it a missing
//! golden is a failure. Every scene is rendered on both back ends (interpreter
//! and JIT) and both must match the same golden exactly.

use image::{Rgba, RgbaImage};
use softgl::Backend;
use softgl::{
    BlendFactor, Capability, ClearMask, CompareFunc, Context, Face, FramebufferDesc, LogicOp, MatrixMode, PolygonMode,
    PrimitiveMode, ShadeModel, StencilOp,
};
use std::cell::Cell;
use std::path::{Path, PathBuf};

thread_local! {
    /// The back end the scene being rendered on this thread uses.
    static BACKEND: Cell<Backend> = const { Cell::new(Backend::Jit) };
}

fn golden_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests").join("golden")
}

/// `<target>/golden-diff`, next to the `tmp` directory cargo gives integration tests.
fn diff_dir() -> PathBuf {
    let tmp = Path::new(env!("CARGO_TARGET_TMPDIR"));
    tmp.parent().unwrap_or(tmp).join("golden-diff")
}

fn blessing() -> bool {
    std::env::var("SOFTGL_BLESS").is_ok_and(|v| v == "1")
}

/// How an image differs from its golden.
#[derive(Debug, PartialEq)]
struct Mismatch {
    pixels: usize,
    max_channel_diff: u8,
    diff: RgbaImage,
}

/// Compares two images of the same size pixel by pixel; `None` when identical.
fn compare(expected: &RgbaImage, actual: &RgbaImage) -> Option<Mismatch> {
    assert_eq!(expected.dimensions(), actual.dimensions());
    let mut pixels = 0;
    let mut max_channel_diff = 0u8;
    let diff = RgbaImage::from_fn(expected.width(), expected.height(), |x, y| {
        let (e, a) = (expected.get_pixel(x, y).0, actual.get_pixel(x, y).0);
        let d = (0..4).map(|c| e[c].abs_diff(a[c])).max().unwrap_or(0);
        if d == 0 {
            // Dimmed luminance of the expected pixel, for orientation.
            let l = (u32::from(e[0]) * 3 + u32::from(e[1]) * 6 + u32::from(e[2])) / 10;
            let l = (l / 4) as u8;
            Rgba([l, l, l, 255])
        } else {
            pixels += 1;
            max_channel_diff = max_channel_diff.max(d);
            Rgba([128 + d / 2, 0, 0, 255])
        }
    });
    (pixels > 0).then_some(Mismatch {
        pixels,
        max_channel_diff,
        diff,
    })
}

/// Checks `actual` against `tests/golden/<name>.png`, or writes it when blessing.
#[track_caller]
fn check_golden(name: &str, actual: &RgbaImage) {
    let path = golden_dir().join(format!("{name}.png"));
    if blessing() {
        std::fs::create_dir_all(golden_dir()).unwrap();
        actual
            .save(&path)
            .unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
        eprintln!("blessed {}", path.display());
        return;
    }
    let expected = match image::open(&path) {
        Ok(img) => img.to_rgba8(),
        Err(e) => panic!(
            "golden {} cannot be read ({e}); render it with SOFTGL_BLESS=1 and look at it",
            path.display()
        ),
    };
    let out = diff_dir();
    let write_actual = || {
        std::fs::create_dir_all(&out).unwrap();
        let p = out.join(format!("{name}.actual.png"));
        actual.save(&p).unwrap();
        p
    };
    if expected.dimensions() != actual.dimensions() {
        let p = write_actual();
        panic!(
            "{name}: size {:?}, golden has {:?}; actual written to {}",
            actual.dimensions(),
            expected.dimensions(),
            p.display()
        );
    }
    if let Some(m) = compare(&expected, actual) {
        let p = write_actual();
        let d = out.join(format!("{name}.diff.png"));
        m.diff.save(&d).unwrap();
        panic!(
            "{name}: {} of {} pixels differ from {} (max channel difference {}); wrote {} and {}",
            m.pixels,
            actual.width() * actual.height(),
            path.display(),
            m.max_channel_diff,
            p.display(),
            d.display()
        );
    }
}

// ----- scene helpers -----

fn context(w: u32, h: u32, clear: [f32; 3]) -> Context {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(w, h)).unwrap();
    gl.set_backend(BACKEND.get());
    gl.clear_color(clear[0], clear[1], clear[2], 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl
}

/// Viewport on cell `(col, row)` of `size` pixels (row 0 at the top) with
/// object coordinates `[0, 1]²` filling it.
fn cell(gl: &mut Context, col: i32, row: i32, rows: i32, size: i32) {
    gl.viewport(col * size, (rows - 1 - row) * size, size, size).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.load_identity().unwrap();
    gl.ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.load_identity().unwrap();
}

/// A saturated color of hue `i / n`.
fn hue(i: usize, n: usize) -> [f32; 3] {
    let h = 6.0 * i as f32 / n as f32;
    let f = h - h.floor();
    match h as u32 % 6 {
        0 => [1.0, f, 0.0],
        1 => [1.0 - f, 1.0, 0.0],
        2 => [0.0, 1.0, f],
        3 => [0.0, 1.0 - f, 1.0],
        4 => [f, 0.0, 1.0],
        _ => [1.0, 0.0, 1.0 - f],
    }
}

/// Draws `verts` as `mode`, vertex `i` colored `hue(i, n)`.
fn draw_hued(gl: &mut Context, mode: PrimitiveMode, verts: &[[f32; 2]]) {
    gl.begin(mode).unwrap();
    for (i, v) in verts.iter().enumerate() {
        let [r, g, b] = hue(i, verts.len());
        gl.color3(r, g, b);
        gl.vertex2(v[0], v[1]);
    }
    gl.end().unwrap();
}

/// `n` points on a circle around `(0.5, 0.5)`, counter-clockwise from angle `start`.
fn ring(n: usize, r: f32, start: f32) -> Vec<[f32; 2]> {
    (0..n)
        .map(|i| {
            let a = start + std::f32::consts::TAU * i as f32 / n as f32;
            [0.5 + r * a.cos(), 0.5 + r * a.sin()]
        })
        .collect()
}

/// A zigzag from left to right: bottom, top, bottom, top, …
fn zigzag(n: usize) -> Vec<[f32; 2]> {
    (0..n)
        .map(|i| {
            let x = 0.1 + 0.8 * i as f32 / (n - 1) as f32;
            let y = if i % 2 == 0 {
                0.15 + 0.05 * (i % 4) as f32
            } else {
                0.85 - 0.05 * (i % 4) as f32
            };
            [x, y]
        })
        .collect()
}

/// An axis-aligned quad at depth `z`.
fn quad(gl: &mut Context, [x0, y0, x1, y1]: [f32; 4], z: f32, rgba: [f32; 4]) {
    gl.begin(PrimitiveMode::Quads).unwrap();
    gl.color4(rgba[0], rgba[1], rgba[2], rgba[3]);
    gl.vertex3(x0, y0, z);
    gl.vertex3(x1, y0, z);
    gl.vertex3(x1, y1, z);
    gl.vertex3(x0, y1, z);
    gl.end().unwrap();
}

// ----- scenes -----

/// The six triangle-making modes, smooth-shaded with one hue per vertex, in a
/// 3 × 2 grid: Triangles, TriangleStrip, TriangleFan / Quads, QuadStrip, Polygon.
fn triangle_modes() -> Context {
    let mut gl = context(96, 64, [0.1, 0.1, 0.1]);
    let scenes: [(PrimitiveMode, Vec<[f32; 2]>); 6] = [
        (
            PrimitiveMode::Triangles,
            vec![
                [0.05, 0.1],
                [0.6, 0.05],
                [0.3, 0.6],
                [0.45, 0.9],
                [0.55, 0.35],
                [0.95, 0.7],
            ],
        ),
        (PrimitiveMode::TriangleStrip, zigzag(7)),
        (PrimitiveMode::TriangleFan, {
            let mut v = vec![[0.5, 0.5]];
            v.extend(ring(8, 0.45, 0.3).into_iter().take(7));
            v
        }),
        (
            PrimitiveMode::Quads,
            vec![
                [0.05, 0.05],
                [0.5, 0.1],
                [0.45, 0.55],
                [0.1, 0.45],
                [0.55, 0.5],
                [0.95, 0.6],
                [0.85, 0.95],
                [0.5, 0.9],
            ],
        ),
        (PrimitiveMode::QuadStrip, zigzag(8)),
        (PrimitiveMode::Polygon, ring(7, 0.45, 0.1)),
    ];
    for (k, (mode, verts)) in scenes.iter().enumerate() {
        cell(&mut gl, k as i32 % 3, k as i32 / 3, 2, 32);
        draw_hued(&mut gl, *mode, verts);
    }
    gl
}

/// The ten primitive modes in a 5 × 2 grid of 32-pixel cells, in
/// `PrimitiveMode::ALL` order, each with its own point size, line width or
/// shading.
fn primitive_modes() -> Context {
    let mut gl = context(160, 64, [0.95, 0.95, 0.95]);
    for (k, mode) in PrimitiveMode::ALL.into_iter().enumerate() {
        cell(&mut gl, k as i32 % 5, k as i32 / 5, 2, 32);
        gl.shade_model(ShadeModel::Smooth).unwrap();
        gl.point_size(1.0).unwrap();
        gl.line_width(1.0).unwrap();
        let verts = match mode {
            PrimitiveMode::Points => {
                gl.point_size(3.0).unwrap();
                ring(8, 0.35, 0.0)
            }
            PrimitiveMode::Lines => ring(8, 0.4, 0.2),
            PrimitiveMode::LineStrip => {
                gl.line_width(2.0).unwrap();
                zigzag(6)
            }
            PrimitiveMode::LineLoop => {
                gl.shade_model(ShadeModel::Flat).unwrap();
                ring(5, 0.4, 0.3)
            }
            PrimitiveMode::Triangles => ring(6, 0.42, 0.0),
            PrimitiveMode::TriangleStrip => zigzag(6),
            PrimitiveMode::TriangleFan => {
                gl.shade_model(ShadeModel::Flat).unwrap();
                let mut v = vec![[0.5, 0.5]];
                v.extend(ring(10, 0.42, 0.0).into_iter().take(8));
                v
            }
            PrimitiveMode::Quads => ring(8, 0.42, 0.4),
            PrimitiveMode::QuadStrip => zigzag(6),
            PrimitiveMode::Polygon => ring(9, 0.42, 0.0),
        };
        draw_hued(&mut gl, mode, &verts);
    }
    gl
}

/// Two quads crossing at an angle under perspective, depth-tested; a decal
/// coplanar with one of them pulled forward by polygon offset (fill); and
/// both quads outlined in black with polygon offset (line); a horizontal
/// triangle through both.
fn depth_offset() -> Context {
    let mut gl = context(96, 96, [0.1, 0.12, 0.18]);
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.translate(0.0, 0.0, -3.2).unwrap();
    gl.rotate(15.0, 1.0, 0.0, 0.0).unwrap();
    gl.enable(Capability::DepthTest).unwrap();

    let face = |gl: &mut Context, angle: f32, c0: [f32; 3], c1: [f32; 3]| {
        gl.push_matrix().unwrap();
        gl.rotate(angle, 0.0, 1.0, 0.0).unwrap();
        gl.begin(PrimitiveMode::Quads).unwrap();
        gl.color3(c0[0], c0[1], c0[2]);
        gl.vertex3(-1.0, -0.7, 0.0);
        gl.vertex3(1.0, -0.7, 0.0);
        gl.color3(c1[0], c1[1], c1[2]);
        gl.vertex3(1.0, 0.7, 0.0);
        gl.vertex3(-1.0, 0.7, 0.0);
        gl.end().unwrap();
        gl.pop_matrix().unwrap();
    };
    let warm = ([0.9, 0.3, 0.1], [1.0, 0.85, 0.2]);
    let cool = ([0.1, 0.3, 0.9], [0.2, 0.9, 0.9]);
    face(&mut gl, 35.0, warm.0, warm.1);
    face(&mut gl, -35.0, cool.0, cool.1);

    // The decal: coplanar with the warm quad; without the offset it would fight.
    gl.enable(Capability::PolygonOffsetFill).unwrap();
    gl.polygon_offset(-1.0, -2.0).unwrap();
    gl.push_matrix().unwrap();
    gl.rotate(35.0, 0.0, 1.0, 0.0).unwrap();
    gl.begin(PrimitiveMode::Polygon).unwrap();
    gl.color3(1.0, 1.0, 1.0);
    for [x, y] in ring(6, 0.25, 0.0) {
        gl.vertex3(x - 1.1, y - 0.5, 0.0);
    }
    gl.end().unwrap();
    gl.pop_matrix().unwrap();
    gl.disable(Capability::PolygonOffsetFill).unwrap();

    // Outlines, pulled forward so the hidden parts stay hidden and the visible ones win.
    gl.enable(Capability::PolygonOffsetLine).unwrap();
    gl.polygon_offset(-1.0, -1.0).unwrap();
    gl.polygon_mode(Face::FrontAndBack, PolygonMode::Line).unwrap();
    face(&mut gl, 35.0, [0.0; 3], [0.0; 3]);
    face(&mut gl, -35.0, [0.0; 3], [0.0; 3]);
    gl.polygon_mode(Face::FrontAndBack, PolygonMode::Fill).unwrap();
    gl.disable(Capability::PolygonOffsetLine).unwrap();

    // A horizontal green triangle piercing both quads: its front edge is in
    // front of them, its apex behind their crossing line.
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.color3(0.2, 0.8, 0.3);
    gl.vertex3(-1.2, -0.3, 1.1);
    gl.vertex3(1.2, -0.3, 1.1);
    gl.color3(0.6, 1.0, 0.6);
    gl.vertex3(0.0, -0.3, -1.2);
    gl.end().unwrap();
    gl
}

/// Stencil decals: a disc writes stencil 1, a triangle (color writes off) adds
/// 1 over it; stripes then appear only where the stencil is 1 (disc or
/// triangle, not both), dots only where it is 2 (both), a grid only where it
/// is 0 (neither).
fn stencil_decal() -> Context {
    let mut gl = context(96, 96, [0.95, 0.95, 0.9]);
    cell(&mut gl, 0, 0, 1, 96);
    gl.enable(Capability::StencilTest).unwrap();

    gl.stencil_func(CompareFunc::Always, 1, 0xff).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace)
        .unwrap();
    gl.begin(PrimitiveMode::Polygon).unwrap();
    gl.color3(0.25, 0.3, 0.5);
    for [x, y] in ring(32, 0.36, 0.0) {
        gl.vertex2(x - 0.08, y);
    }
    gl.end().unwrap();

    gl.color_mask(false, false, false, false).unwrap();
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr)
        .unwrap();
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.vertex2(0.4, 0.08);
    gl.vertex2(0.97, 0.5);
    gl.vertex2(0.4, 0.92);
    gl.end().unwrap();
    gl.color_mask(true, true, true, true).unwrap();

    // Diagonal stripes where the stencil is 1.
    gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep)
        .unwrap();
    gl.stencil_func(CompareFunc::Equal, 1, 0xff).unwrap();
    gl.begin(PrimitiveMode::Quads).unwrap();
    for i in -10..10 {
        let x = i as f32 * 0.1;
        gl.color3(1.0, 0.8, 0.1);
        gl.vertex2(x, 0.0);
        gl.vertex2(x + 0.04, 0.0);
        gl.color3(1.0, 0.5, 0.1);
        gl.vertex2(x + 1.04, 1.0);
        gl.vertex2(x + 1.0, 1.0);
    }
    gl.end().unwrap();

    // Dots where it is 2.
    gl.stencil_func(CompareFunc::Equal, 2, 0xff).unwrap();
    gl.point_size(3.0).unwrap();
    gl.begin(PrimitiveMode::Points).unwrap();
    gl.color3(0.9, 0.1, 0.2);
    for j in 0..16 {
        for i in 0..16 {
            gl.vertex2((i as f32 + 0.5) / 16.0, (j as f32 + 0.5) / 16.0);
        }
    }
    gl.end().unwrap();

    // A grid where it is 0.
    gl.stencil_func(CompareFunc::Equal, 0, 0xff).unwrap();
    gl.begin(PrimitiveMode::Lines).unwrap();
    gl.color3(0.6, 0.65, 0.75);
    for i in 0..12 {
        let t = (i as f32 + 0.5) / 12.0;
        gl.vertex2(t, 0.0);
        gl.vertex2(t, 1.0);
        gl.vertex2(0.0, t);
        gl.vertex2(1.0, t);
    }
    gl.end().unwrap();
    gl
}

/// Transparency over a depth-tested scene: a checkerboard and an opaque quad
/// write depth; translucent quads (depth writes off, destination alpha kept)
/// are hidden where they lie behind the opaque one; an additive band; a
/// triangle XORed onto the colors (alpha masked); a green-only scissored
/// clear; a scissored depth clear revealing a quad drawn behind everything.
fn blend_logic() -> Context {
    let mut gl = context(96, 96, [0.0, 0.0, 0.0]);
    cell(&mut gl, 0, 0, 1, 96);
    gl.enable(Capability::DepthTest).unwrap();
    // ortho(…, -1, 1): window depth grows as object z falls; larger z is nearer.
    gl.begin(PrimitiveMode::Quads).unwrap();
    for j in 0..8 {
        for i in 0..8 {
            let g = if (i + j) % 2 == 0 { 0.35 } else { 0.55 };
            gl.color3(g, g, g);
            let (x, y) = (i as f32 / 8.0, j as f32 / 8.0);
            gl.vertex3(x, y, -0.9);
            gl.vertex3(x + 0.125, y, -0.9);
            gl.vertex3(x + 0.125, y + 0.125, -0.9);
            gl.vertex3(x, y + 0.125, -0.9);
        }
    }
    gl.end().unwrap();
    quad(&mut gl, [0.3, 0.3, 0.7, 0.7], 0.0, [1.0, 0.55, 0.1, 1.0]);

    gl.depth_mask(false).unwrap();
    gl.enable(Capability::Blend).unwrap();
    gl.blend_func_separate(
        BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha,
        BlendFactor::Zero,
        BlendFactor::One,
    )
    .unwrap();
    quad(&mut gl, [0.08, 0.42, 0.55, 0.92], 0.5, [1.0, 0.1, 0.1, 0.5]); // in front of the opaque quad
    quad(&mut gl, [0.45, 0.45, 0.92, 0.92], -0.5, [0.1, 1.0, 0.2, 0.6]); // behind it
    gl.begin(PrimitiveMode::Quads).unwrap(); // alpha ramp from 0 to 1
    gl.color4(0.2, 0.4, 1.0, 0.0);
    gl.vertex3(0.08, 0.08, 0.2);
    gl.color4(0.2, 0.4, 1.0, 1.0);
    gl.vertex3(0.92, 0.08, 0.2);
    gl.vertex3(0.92, 0.36, 0.2);
    gl.color4(0.2, 0.4, 1.0, 0.0);
    gl.vertex3(0.08, 0.36, 0.2);
    gl.end().unwrap();
    gl.blend_func(BlendFactor::One, BlendFactor::One).unwrap();
    quad(&mut gl, [0.0, 0.62, 1.0, 0.68], 0.9, [0.3, 0.3, 0.3, 0.0]);
    gl.disable(Capability::Blend).unwrap();
    gl.depth_mask(true).unwrap();

    // XOR with white inverts RGB; alpha is masked so it stays 255.
    gl.disable(Capability::DepthTest).unwrap();
    gl.enable(Capability::ColorLogicOp).unwrap();
    gl.logic_op(LogicOp::Xor).unwrap();
    gl.color_mask(true, true, true, false).unwrap();
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.color3(1.0, 1.0, 1.0);
    gl.vertex2(0.6, 0.02);
    gl.vertex2(0.98, 0.02);
    gl.vertex2(0.98, 0.5);
    gl.end().unwrap();
    gl.disable(Capability::ColorLogicOp).unwrap();

    // Scissored clears: green channel only, then depth only.
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(4, 70, 30, 20).unwrap();
    gl.color_mask(false, true, false, false).unwrap();
    gl.clear_color(0.0, 1.0, 0.0, 0.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.color_mask(true, true, true, true).unwrap();
    gl.scissor(60, 56, 30, 34).unwrap();
    gl.clear_depth(1.0).unwrap();
    gl.clear(ClearMask::DEPTH).unwrap();
    gl.disable(Capability::ScissorTest).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.begin(PrimitiveMode::Quads).unwrap();
    gl.color3(0.6, 0.2, 0.9);
    gl.vertex3(0.0, 0.0, -0.95);
    gl.vertex3(1.0, 0.0, -0.95);
    gl.color3(0.9, 0.9, 1.0);
    gl.vertex3(1.0, 1.0, -0.95);
    gl.vertex3(0.0, 1.0, -0.95);
    gl.end().unwrap();
    gl
}

/// Renders through `scene` on each back end and checks the images.
fn golden(name: &str, scene: fn() -> Context) {
    for backend in [Backend::Interpreter, Backend::Jit] {
        BACKEND.set(backend);
        let mut gl = scene();
        assert_eq!(gl.backend(), backend);
        assert_eq!(
            gl.get_error(),
            None,
            "{name} on {backend:?}: a GL error while rendering"
        );
        check_golden(name, &gl.framebuffer().to_rgba_image());
        if backend == Backend::Jit {
            let stats = gl.specialist_stats();
            assert!(stats.misses > 0 && stats.failures == 0, "{name}: specialists {stats:?}");
        }
    }
}

#[test]
fn golden_triangle_modes() {
    golden("triangle_modes", triangle_modes);
}

#[test]
fn golden_primitive_modes() {
    golden("primitive_modes", primitive_modes);
}

#[test]
fn golden_depth_offset() {
    golden("depth_offset", depth_offset);
}

#[test]
fn golden_stencil_decal() {
    golden("stencil_decal", stencil_decal);
}

#[test]
fn golden_blend_logic() {
    golden("blend_logic", blend_logic);
}

#[test]
fn golden_demo() {
    golden("demo", || softgl::demo::render_on(BACKEND.get(), 160, 120).unwrap());
}

#[test]
fn scenes_render_the_same_twice() {
    for scene in [
        triangle_modes,
        primitive_modes,
        depth_offset,
        stencil_decal,
        blend_logic,
    ] {
        let (mut a, mut b) = (scene(), scene());
        assert_eq!(a.framebuffer().color_bytes(), b.framebuffer().color_bytes());
    }
}

#[test]
fn compare_counts_differences_and_marks_them() {
    let expected = RgbaImage::from_pixel(4, 3, Rgba([10, 20, 30, 255]));
    assert_eq!(compare(&expected, &expected.clone()), None);
    let mut actual = expected.clone();
    actual.put_pixel(1, 2, Rgba([10, 20, 30, 254]));
    actual.put_pixel(3, 0, Rgba([200, 20, 30, 255]));
    let m = compare(&expected, &actual).unwrap();
    assert_eq!((m.pixels, m.max_channel_diff), (2, 190));
    assert_eq!(m.diff.get_pixel(1, 2).0, [128, 0, 0, 255]);
    assert_eq!(m.diff.get_pixel(3, 0).0, [223, 0, 0, 255]);
    // Equal pixels: a quarter of the luminance (10·3 + 20·6 + 30) / 10 = 18, so 4.
    assert_eq!(m.diff.get_pixel(0, 0).0, [4, 4, 4, 255]);
}
