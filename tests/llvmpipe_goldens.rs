//! softgl against Mesa 22.3.6 llvmpipe, without Mesa: fifteen scenes were
//! rendered once by llvmpipe through OSMesa (`tests/llvmpipe/gen.c`), which
//! also wrote every GL call it made to a trace. Each test replays its trace
//! through softgl and compares colour, depth and stencil with llvmpipe's.
//!
//! Where softgl is known to differ, the budget next to the scene says how
//! much and why; every other budget is zero. A budget is a ceiling measured
//! at the commit that set it: lowering it is progress, raising it needs a reason.

use softgl::{
    Backend, BlendFactor, Capability, ClearMask, CompareFunc, Context, Face, FramebufferDesc, GlResult, LogicOp,
    MatrixMode, PolygonMode, PrimitiveMode, ShadeModel, StencilOp,
};
use std::path::{Path, PathBuf};

/// How far softgl may land from llvmpipe on a scene.
#[derive(Clone, Copy, Debug)]
struct Budget {
    /// Pixels whose colour bytes differ.
    color_pixels: usize,
    /// Pixels drawn by one renderer and not the other.
    coverage: usize,
    /// Depth values that differ.
    depth_values: usize,
    /// Largest depth difference, in units of 2^-24.
    depth_max: u32,
}

const EXACT: Budget = Budget {
    color_pixels: 0,
    coverage: 0,
    depth_values: 0,
    depth_max: 0,
};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/llvmpipe")
}

fn cap(s: &str) -> Capability {
    match s {
        "GL_DEPTH_TEST" => Capability::DepthTest,
        "GL_BLEND" => Capability::Blend,
        "GL_COLOR_LOGIC_OP" => Capability::ColorLogicOp,
        "GL_STENCIL_TEST" => Capability::StencilTest,
        "GL_POLYGON_OFFSET_FILL" => Capability::PolygonOffsetFill,
        "GL_POLYGON_OFFSET_LINE" => Capability::PolygonOffsetLine,
        "GL_POLYGON_OFFSET_POINT" => Capability::PolygonOffsetPoint,
        "GL_CULL_FACE" => Capability::CullFace,
        "GL_SCISSOR_TEST" => Capability::ScissorTest,
        _ => panic!("unknown capability {s}"),
    }
}

fn mode(s: &str) -> PrimitiveMode {
    let names = [
        "GL_POINTS",
        "GL_LINES",
        "GL_LINE_STRIP",
        "GL_LINE_LOOP",
        "GL_TRIANGLES",
        "GL_TRIANGLE_STRIP",
        "GL_TRIANGLE_FAN",
        "GL_QUADS",
        "GL_QUAD_STRIP",
        "GL_POLYGON",
    ];
    let i = names
        .iter()
        .position(|&n| n == s)
        .unwrap_or_else(|| panic!("unknown mode {s}"));
    PrimitiveMode::ALL[i]
}

fn func(s: &str) -> CompareFunc {
    let names = [
        "GL_NEVER",
        "GL_LESS",
        "GL_EQUAL",
        "GL_LEQUAL",
        "GL_GREATER",
        "GL_NOTEQUAL",
        "GL_GEQUAL",
        "GL_ALWAYS",
    ];
    let i = names
        .iter()
        .position(|&n| n == s)
        .unwrap_or_else(|| panic!("unknown function {s}"));
    CompareFunc::ALL[i]
}

fn factor(s: &str) -> BlendFactor {
    match s {
        "GL_ZERO" => BlendFactor::Zero,
        "GL_ONE" => BlendFactor::One,
        "GL_SRC_ALPHA" => BlendFactor::SrcAlpha,
        "GL_ONE_MINUS_SRC_ALPHA" => BlendFactor::OneMinusSrcAlpha,
        _ => panic!("unknown blend factor {s}"),
    }
}

fn stencil_op(s: &str) -> StencilOp {
    match s {
        "GL_KEEP" => StencilOp::Keep,
        "GL_INCR" => StencilOp::Incr,
        "GL_REPLACE" => StencilOp::Replace,
        "GL_ZERO" => StencilOp::Zero,
        _ => panic!("unknown stencil op {s}"),
    }
}

/// Replays the trace `name` into a new context.
fn replay(name: &str, backend: Backend) -> Context {
    let path = dir().join(format!("s{name}.trace"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut gl: Option<Context> = None;
    for line in text.lines() {
        let t: Vec<&str> = line.split_whitespace().collect();
        let f = |i: usize| t[i].parse::<f32>().unwrap();
        let d = |i: usize| t[i].parse::<f64>().unwrap();
        let n = |i: usize| t[i].parse::<i32>().unwrap();
        if t[0] == "INIT" {
            let mut ctx = Context::new(FramebufferDesc::rgba8_d24s8(n(1) as u32, n(2) as u32)).unwrap();
            ctx.set_backend(backend);
            gl = Some(ctx);
            continue;
        }
        let g = gl.as_mut().expect("INIT comes first");
        let r: GlResult = match t[0] {
            "EN" => g.enable(cap(t[1])),
            "DIS" => g.disable(cap(t[1])),
            "B" => g.begin(mode(t[1])),
            "E" => g.end(),
            "C" => {
                g.color4(f(1), f(2), f(3), f(4));
                Ok(())
            }
            "V" => {
                g.vertex3(f(1), f(2), f(3));
                Ok(())
            }
            "VP" => g.viewport(n(1), n(2), n(3), n(4)),
            "MM" => g.matrix_mode(if t[1] == "GL_PROJECTION" {
                MatrixMode::Projection
            } else {
                MatrixMode::Modelview
            }),
            "LI" => g.load_identity(),
            "ORTHO" => g.ortho(d(1), d(2), d(3), d(4), d(5), d(6)),
            "FRUST" => g.frustum(d(1), d(2), d(3), d(4), d(5), d(6)),
            "CC" => g.clear_color(f(1), f(2), f(3), f(4)),
            "CLR" => g.clear(ClearMask::ALL),
            "DF" => g.depth_func(func(t[1])),
            "DM" => g.depth_mask(n(1) != 0),
            "SM" => g.shade_model(if t[1] == "GL_FLAT" {
                ShadeModel::Flat
            } else {
                ShadeModel::Smooth
            }),
            "PS" => g.point_size(f(1)),
            "LW" => g.line_width(f(1)),
            "BF" => g.blend_func(factor(t[1]), factor(t[2])),
            "LO" => g.logic_op(if t[1] == "GL_XOR" { LogicOp::Xor } else { LogicOp::Copy }),
            "SF" => g.stencil_func(func(t[1]), n(2), t[3].parse().unwrap()),
            "SO" => g.stencil_op(stencil_op(t[1]), stencil_op(t[2]), stencil_op(t[3])),
            "PO" => g.polygon_offset(f(1), f(2)),
            "PM" => {
                let face = match t[1] {
                    "GL_FRONT" => Face::Front,
                    "GL_BACK" => Face::Back,
                    _ => Face::FrontAndBack,
                };
                let m = match t[2] {
                    "GL_POINT" => PolygonMode::Point,
                    "GL_LINE" => PolygonMode::Line,
                    _ => PolygonMode::Fill,
                };
                g.polygon_mode(face, m)
            }
            "END" => Ok(()),
            op => panic!("unknown trace op {op}"),
        };
        r.unwrap_or_else(|e| panic!("{name}: {line}: {e}"));
    }
    gl.expect("trace has INIT")
}

/// llvmpipe's buffers for a scene, rows bottom-up as GL reads them.
struct Reference {
    color: Vec<[u8; 4]>,
    depth: Vec<u32>,
    stencil: Vec<u8>,
}

/// Converts `raw/` dumps from gen.c into the PNGs the tests read.
fn bless(name: &str) {
    let raw = |ext: &str| std::fs::read(dir().join(format!("raw/s{name}.{ext}"))).unwrap();
    let (w, h) = (128, 128);
    let flip = |i: usize| {
        let (x, y) = (i % w, i / w);
        (x as u32, (h - 1 - y) as u32)
    };
    let color = raw("rgba");
    let depth = raw("depth");
    let stencil = raw("stencil");
    let mut c = image::RgbaImage::new(w as u32, h as u32);
    let mut d = image::RgbaImage::new(w as u32, h as u32);
    let mut s = image::GrayImage::new(w as u32, h as u32);
    for i in 0..w * h {
        let (x, y) = flip(i);
        c.put_pixel(x, y, image::Rgba(color[i * 4..i * 4 + 4].try_into().unwrap()));
        let [b0, b1, b2, _] = depth[i * 4..i * 4 + 4].try_into().unwrap();
        d.put_pixel(x, y, image::Rgba([b0, b1, b2, 255]));
        s.put_pixel(x, y, image::Luma([stencil[i]]));
    }
    c.save(dir().join(format!("s{name}.color.png"))).unwrap();
    d.save(dir().join(format!("s{name}.depth.png"))).unwrap();
    s.save(dir().join(format!("s{name}.stencil.png"))).unwrap();
}

fn reference(name: &str) -> Reference {
    if std::env::var_os("SOFTGL_BLESS_LLVMPIPE").is_some() {
        bless(name);
    }
    let open = |kind: &str| {
        let p = dir().join(format!("s{name}.{kind}.png"));
        image::open(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
    };
    let (c, d, s) = (
        open("color").to_rgba8(),
        open("depth").to_rgba8(),
        open("stencil").to_luma8(),
    );
    let h = c.height();
    let at = |i: u32| (i % c.width(), h - 1 - i / c.width());
    let n = c.width() * h;
    Reference {
        color: (0..n).map(|i| c.get_pixel(at(i).0, at(i).1).0).collect(),
        depth: (0..n)
            .map(|i| {
                let [b0, b1, b2, _] = d.get_pixel(at(i).0, at(i).1).0;
                u32::from_le_bytes([b0, b1, b2, 0])
            })
            .collect(),
        stencil: (0..n).map(|i| s.get_pixel(at(i).0, at(i).1).0[0]).collect(),
    }
}

/// Replays scene `name` on both back ends: each must stay within `budget`
/// of llvmpipe, and the two must be identical.
fn check(name: &str, budget: Budget) {
    let mut interp = replay(name, Backend::Interpreter);
    let mut jit = replay(name, Backend::Jit);
    let (a, b) = (interp.framebuffer(), jit.framebuffer());
    assert!(
        a.color_bytes() == b.color_bytes(),
        "scene {name}: JIT colors differ from the interpreter's"
    );
    for y in 0..a.height() {
        for x in 0..a.width() {
            assert_eq!(
                a.depth_at(x, y),
                b.depth_at(x, y),
                "scene {name}: JIT depth at ({x}, {y})"
            );
            assert_eq!(
                a.stencil_at(x, y),
                b.stencil_at(x, y),
                "scene {name}: JIT stencil at ({x}, {y})"
            );
        }
    }
    check_against_llvmpipe(name, &mut interp, budget);
}

fn check_against_llvmpipe(name: &str, gl: &mut Context, budget: Budget) {
    let want = reference(name);
    let fb = gl.framebuffer();
    let (w, h) = (fb.width(), fb.height());
    let clear = [0u8; 4];
    let (mut color, mut coverage, mut depth, mut depth_max, mut stencil) = (0, 0, 0, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            let got = fb.pixel(x, y).unwrap();
            color += usize::from(got != want.color[i]);
            coverage += usize::from((got == clear) != (want.color[i] == clear));
            let dz = fb.depth_at(x, y).unwrap().abs_diff(want.depth[i]);
            depth += usize::from(dz != 0);
            depth_max = depth_max.max(dz);
            stencil += usize::from(fb.stencil_at(x, y).unwrap() != want.stencil[i]);
        }
    }
    let got = Budget {
        color_pixels: color,
        coverage,
        depth_values: depth,
        depth_max,
    };
    let within = color <= budget.color_pixels
        && coverage <= budget.coverage
        && depth <= budget.depth_values
        && depth_max <= budget.depth_max;
    eprintln!("scene {name}: {got:?}");
    assert!(within, "scene {name}: measured {got:?}, budget {budget:?}");
    assert_eq!(stencil, 0, "scene {name}: stencil values differing from llvmpipe");
}

#[test]
fn random_smooth_triangles_depth_tested() {
    check("1", EXACT);
}

#[test]
fn perspective_triangles_clipped_at_near_and_sides() {
    check("2", EXACT);
}

#[test]
fn triangles_with_huge_coordinates() {
    check("3", EXACT);
}

#[test]
fn thin_lines() {
    // Endpoint ties (an end exactly on k or k + 0.5) where llvmpipe's diamond tests are asymmetric.
    check(
        "4a",
        Budget {
            color_pixels: 21,
            coverage: 9,
            ..EXACT
        },
    );
}

#[test]
fn wide_lines() {
    check(
        "4b",
        Budget {
            color_pixels: 6,
            coverage: 6,
            ..EXACT
        },
    );
}

#[test]
fn points_of_many_sizes() {
    check("5", EXACT);
}

#[test]
fn flat_shading_in_all_ten_modes() {
    check("6", EXACT);
}

#[test]
fn translucent_blending() {
    check("7a", EXACT);
}

#[test]
fn additive_blending() {
    check("7b", EXACT);
}

#[test]
fn xor_logic_op() {
    check("7c", EXACT);
}

#[test]
fn stencil_counts_overlaps() {
    check("7d", EXACT);
}

#[test]
fn polygon_offset_decides_coplanar_quads() {
    // Depth: the offset sum's last bits.
    check(
        "8",
        Budget {
            depth_values: 214,
            depth_max: 2,
            ..EXACT
        },
    );
}

#[test]
fn polygon_offset_depth_values() {
    check(
        "8b",
        Budget {
            depth_values: 119,
            depth_max: 2,
            ..EXACT
        },
    );
}

#[test]
fn polygon_mode_line_and_point() {
    // Colour along polygon edges drawn as lines: llvmpipe's line plane differs by a few steps.
    check(
        "9",
        Budget {
            color_pixels: 3,
            ..EXACT
        },
    );
}

#[test]
fn viewport_inside_a_larger_framebuffer() {
    check(
        "10",
        Budget {
            depth_values: 397,
            depth_max: 36,
            ..EXACT
        },
    );
}
