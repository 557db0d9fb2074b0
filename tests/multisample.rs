//! 4× multisampling against Mesa's llvmpipe (`tests/llvmpipe/msaa.c`
//! recorded `msaa.txt`: each scene drawn into a 4-sample framebuffer
//! object and resolved with `glBlitFramebuffer`). Each scene makes the C
//! program's calls through softgl's Rust API on a 4-sample framebuffer and
//! reads it back resolved, on both back ends (`docs/llvmpipe-facts.md` §29).

mod common;

use softgl::{
    Backend, BlendFactor, Capability, ClearMask, CompareFunc, Context, FramebufferDesc, MatrixMode, PrimitiveMode,
    ReadFormat, StencilOp,
};

const N: i32 = 40;
const T: [[[f32; 3]; 3]; 3] = [
    [[2.3, 3.1, 0.3], [37.6, 8.4, 0.5], [12.2, 35.7, 0.4]],
    [[30.4, 2.2, -0.5], [35.9, 37.3, -0.2], [4.7, 20.6, -0.3]],
    [[1.4, 38.8, 0.8], [20.9, 0.6, 0.7], [38.2, 30.1, 0.9]],
];
const C: [[f32; 4]; 3] = [[0.9, 0.2, 0.1, 1.0], [0.1, 0.8, 0.3, 0.5], [0.2, 0.3, 0.9, 0.7]];

/// The scenes of `msaa.c`, with the pixels softgl may differ by and why
/// (all others are identical).
const SCENES: &[(&str, usize)] = &[
    ("depth", 0),
    ("blend", 0),
    ("smooth", 0),
    ("intersect", 0),
    ("coverage", 0),
    ("nomultisample", 0),
    ("stencil", 0),
    ("lines", 0),
    ("points", 0),
];

fn vertex(gl: &mut Context, [x, y, z]: [f32; 3]) {
    gl.vertex3(x, y, z);
}

fn tri(gl: &mut Context, t: usize) {
    let [r, g, b, a] = C[t];
    gl.color4(r, g, b, a);
    gl.begin(PrimitiveMode::Triangles).unwrap();
    for v in T[t] {
        vertex(gl, v);
    }
    gl.end().unwrap();
}

fn render(name: &str, backend: Backend) -> Context {
    let fb = softgl::Framebuffer::new_multisample(FramebufferDesc::rgba8_d24s8(N as u32, N as u32), 4).unwrap();
    render_into(name, fb, backend)
}

/// The scene `name` drawn into `fb` on `backend`.
fn render_into(name: &str, fb: softgl::Framebuffer, backend: Backend) -> Context {
    let mut gl = Context::with_framebuffer(fb);
    gl.set_backend(backend);
    gl.viewport(0, 0, N, N).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.ortho(0.0, f64::from(N), 0.0, f64::from(N), -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.clear_color(0.1, 0.1, 0.2, 1.0).unwrap();
    gl.clear_depth(1.0).unwrap();
    gl.clear_stencil(0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    match name {
        "depth" => {
            gl.enable(Capability::DepthTest).unwrap();
            (0..3).for_each(|t| tri(&mut gl, t));
        }
        "blend" => {
            gl.enable(Capability::Blend).unwrap();
            gl.blend_func(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha)
                .unwrap();
            (0..3).for_each(|t| tri(&mut gl, t));
        }
        "smooth" => {
            gl.begin(PrimitiveMode::Triangles).unwrap();
            for i in 0..3 {
                let [r, g, b, a] = C[i];
                gl.color4(r, g, b, a);
                vertex(&mut gl, T[0][i]);
            }
            gl.end().unwrap();
        }
        "intersect" => {
            gl.enable(Capability::DepthTest).unwrap();
            gl.begin(PrimitiveMode::Triangles).unwrap();
            let [r, g, b, a] = C[0];
            gl.color4(r, g, b, a);
            gl.vertex3(2.3, 3.1, -0.9);
            gl.vertex3(37.6, 8.4, 0.9);
            gl.vertex3(12.2, 35.7, 0.1);
            let [r, g, b, a] = C[1];
            gl.color4(r, g, b, a);
            gl.vertex3(30.4, 2.2, 0.6);
            gl.vertex3(35.9, 37.3, -0.7);
            gl.vertex3(4.7, 20.6, 0.2);
            gl.end().unwrap();
        }
        "coverage" => {
            gl.enable(Capability::SampleCoverage).unwrap();
            gl.sample_coverage(0.5, false).unwrap();
            tri(&mut gl, 0);
            gl.sample_coverage(0.5, true).unwrap();
            tri(&mut gl, 2);
        }
        "nomultisample" => {
            gl.disable(Capability::Multisample).unwrap();
            tri(&mut gl, 0);
            tri(&mut gl, 1);
            gl.enable(Capability::Multisample).unwrap();
            tri(&mut gl, 2);
        }
        "lines" => {
            let l = [
                [3.2, 4.7, 36.1, 9.3],
                [5.6, 33.4, 30.2, 2.9],
                [20.3, 1.8, 22.9, 38.1],
                [2.5, 20.5, 37.5, 20.5],
                [8.0, 8.0, 31.0, 31.0],
            ];
            let w = [1.0, 1.0, 2.0, 3.5, 6.0];
            for i in 0..5 {
                gl.line_width(w[i]).unwrap();
                let [r, g, b, a] = C[i % 3];
                gl.color4(r, g, b, a);
                gl.begin(PrimitiveMode::Lines).unwrap();
                gl.vertex2(l[i][0], l[i][1]);
                gl.vertex2(l[i][2], l[i][3]);
                gl.end().unwrap();
            }
            gl.line_width(1.0).unwrap();
        }
        "points" => {
            let p = [
                [5.3, 6.1, 1.0],
                [12.7, 30.2, 2.5],
                [20.5, 20.5, 4.0],
                [31.1, 9.9, 7.3],
                [33.0, 33.0, 3.0],
                [8.2, 19.6, 0.5],
            ];
            for (i, [x, y, size]) in p.into_iter().enumerate() {
                gl.point_size(size).unwrap();
                let [r, g, b, a] = C[i % 3];
                gl.color4(r, g, b, a);
                gl.begin(PrimitiveMode::Points).unwrap();
                gl.vertex2(x, y);
                gl.end().unwrap();
            }
            gl.point_size(1.0).unwrap();
        }
        "stencil" => {
            gl.enable(Capability::StencilTest).unwrap();
            gl.stencil_func(CompareFunc::Always, 1, 0xff).unwrap();
            gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace)
                .unwrap();
            gl.color_mask(false, false, false, false).unwrap();
            tri(&mut gl, 0);
            gl.color_mask(true, true, true, true).unwrap();
            gl.stencil_func(CompareFunc::Equal, 1, 0xff).unwrap();
            gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Keep)
                .unwrap();
            gl.color4(1.0, 1.0, 0.6, 1.0);
            // glRectf(0, 0, N, N).
            gl.begin(PrimitiveMode::Quads).unwrap();
            let n = N as f32;
            for (x, y) in [(0.0, 0.0), (n, 0.0), (n, n), (0.0, n)] {
                gl.vertex2(x, y);
            }
            gl.end().unwrap();
        }
        _ => panic!("unknown scene {name}"),
    }
    gl
}

fn llvmpipe() -> std::collections::HashMap<String, Vec<u8>> {
    common::hex_scenes(include_str!("llvmpipe/msaa.txt"))
}

/// Pixels that differ, and the largest channel difference.
fn differ(got: &[u8], want: &[u8]) -> (usize, u8) {
    assert_eq!(got.len(), want.len());
    let mut d = (0, 0);
    for (a, b) in got.chunks(4).zip(want.chunks(4)) {
        if a != b {
            d.0 += 1;
            d.1 = a.iter().zip(b).map(|(x, y)| x.abs_diff(*y)).max().unwrap_or(0).max(d.1);
        }
    }
    d
}

#[test]
fn multisampled_scenes_resolve_to_llvmpipes_bytes() {
    let want = llvmpipe();
    for &(name, tolerance) in SCENES {
        for backend in [Backend::Interpreter, Backend::Jit] {
            let mut gl = render(name, backend);
            let got = gl.read_pixels(0, 0, N, N, ReadFormat::Rgba8).unwrap();
            let (pixels, most) = differ(&got, &want[name]);
            assert!(
                pixels <= tolerance,
                "{name} ({backend:?}): {pixels} pixels differ (up to {most}), {tolerance} allowed"
            );
            assert_eq!(gl.get_error(), None);
        }
    }
}

#[test]
fn the_recording_shows_partly_covered_pixels() {
    // Resolved edges: colours that no single sample holds (the scene would
    // pass single-sampled otherwise).
    let l = llvmpipe();
    let depth = &l["depth"];
    let clear = [0x1a, 0x1a, 0x33, 0xff];
    let red = [230, 51, 26, 255];
    let mixed = depth
        .chunks(4)
        .filter(|p| *p != clear && *p != red && p[0] > 26 && p[1] < 60)
        .count();
    assert!(mixed > 20, "{mixed} red edge pixels mixed with the clear colour");
}

#[test]
fn a_multisampled_context_answers_for_its_samples() {
    let mut gl = Context::new_multisample(FramebufferDesc::rgba8_d24s8(8, 8), 4).unwrap();
    assert_eq!(gl.samples(), 4);
    assert!(gl.is_enabled(Capability::Multisample));
    assert!(!gl.is_enabled(Capability::SampleCoverage));
    assert_eq!(gl.framebuffer().samples(), 4);
    assert!(Context::new_multisample(FramebufferDesc::rgba8_d24s8(8, 8), 3).is_err());
    // A clear reaches every sample.
    gl.clear_color(1.0, 0.5, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    let fb = gl.framebuffer();
    for s in 0..4 {
        assert_eq!(fb.sample_pixel(7, 7, s), Some([255, 128, 0, 255]));
    }
}

#[test]
fn the_scenes_single_sampled_are_not_llvmpipes_resolved_bytes() {
    // The same calls on one sample a pixel: the edges differ, so the test
    // above checks the samples (and 1 sample with GL_MULTISAMPLE off too).
    let want = llvmpipe();
    let mut found = Vec::new();
    for &(name, _) in SCENES {
        let single = {
            let fb = softgl::Framebuffer::new(FramebufferDesc::rgba8_d24s8(N as u32, N as u32)).unwrap();
            let mut s = render_into(name, fb, Backend::Interpreter);
            s.read_pixels(0, 0, N, N, ReadFormat::Rgba8).unwrap()
        };
        found.push((name, differ(&single, &want[name]).0));
    }
    let want = [
        ("depth", 149),
        ("blend", 214),
        ("smooth", 77),
        ("intersect", 146),
        ("coverage", 869),
        ("nomultisample", 82),
        ("stencil", 77),
        ("lines", 261),
        ("points", 66),
    ];
    assert_eq!(found, want);
}

#[test]
fn a_multisampled_framebuffer_swapped_in_draws_per_sample_and_resolves() {
    // What a framebuffer object does: a context made on one framebuffer
    // draws into another (4 samples) and back, with the state kept.
    let desc = FramebufferDesc::rgba8_d24s8(N as u32, N as u32);
    let mut gl = Context::new(desc).unwrap();
    gl.set_threads(2);
    gl.set_scene_bound(1); // flush in the background after every primitive
    let window = gl.replace_framebuffer(softgl::Framebuffer::new_multisample(desc, 4).unwrap());
    assert_eq!(gl.samples(), 4);
    gl.viewport(0, 0, N, N).unwrap();
    gl.matrix_mode(MatrixMode::Projection).unwrap();
    gl.ortho(0.0, f64::from(N), 0.0, f64::from(N), -1.0, 1.0).unwrap();
    gl.matrix_mode(MatrixMode::Modelview).unwrap();
    gl.clear_color(0.1, 0.1, 0.2, 1.0).unwrap();
    gl.clear(ClearMask {
        color: true,
        depth: true,
        stencil: true,
        accum: false,
    })
    .unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    (0..3).for_each(|t| tri(&mut gl, t));
    let ms = gl.replace_framebuffer(window);
    assert_eq!((ms.samples(), gl.samples()), (4, 1));
    let resolved = ms.resolve().unwrap();
    let got = resolved.read_pixels(0, 0, N, N, ReadFormat::Rgba8).unwrap();
    assert_eq!(differ(&got, &llvmpipe()["depth"]), (0, 0));
    // The window is untouched.
    assert_eq!(gl.framebuffer().pixel(20, 20), Some([0, 0, 0, 0]));
}

/// With `GL_MULTISAMPLE` off, draws test depth and stencil in sample 0
/// (llvmpipe). Right after a clear every sample holds the same values, and
/// softgl then skips copying sample 0's into the others
/// (`Context::samples_same`): the same bytes in every sample as with the
/// copies, which a draw with multisampling on (here one with no fragments)
/// brings back.
#[test]
fn multisampling_off_after_a_clear_needs_no_copy_of_sample_0s_tests() {
    let draw = |copies: bool| {
        let fb = softgl::Framebuffer::new_multisample(FramebufferDesc::rgba8_d24s8(N as u32, N as u32), 4).unwrap();
        let mut gl = render_into("depth", fb, Backend::Interpreter);
        gl.clear(ClearMask::ALL).unwrap();
        if copies {
            // Outside the view volume: no fragment, but the samples may differ after it.
            gl.begin(PrimitiveMode::Triangles).unwrap();
            for v in [[-9.0, -9.0, 0.0], [-8.0, -9.0, 0.0], [-9.0, -8.0, 0.0]] {
                vertex(&mut gl, v);
            }
            gl.end().unwrap();
        }
        gl.disable(Capability::Multisample).unwrap();
        gl.enable(Capability::StencilTest).unwrap();
        gl.stencil_func(CompareFunc::Always, 1, 0xff).unwrap();
        gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr)
            .unwrap();
        (0..3).for_each(|t| tri(&mut gl, t));
        let fb = gl.framebuffer();
        let mut out = Vec::new();
        for s in 0..4 {
            for y in 0..N as u32 {
                for x in 0..N as u32 {
                    out.extend(fb.sample_pixel(x, y, s).unwrap());
                }
            }
        }
        for y in 0..N as u32 {
            for x in 0..N as u32 {
                out.extend(fb.depth_at(x, y).unwrap().to_le_bytes());
                out.push(fb.stencil_at(x, y).unwrap());
            }
        }
        out
    };
    let (without, with) = (draw(false), draw(true));
    assert_eq!(without.len(), with.len());
    assert!(without == with, "the copy-free path differs");
    // The triangles drew (not a comparison of two empty frames).
    assert!(without.chunks(4).take((N * N) as usize).any(|p| p[0] > 200));
}
