//! DESIGN.md's stiff and extreme input. None may crash a softgl back end.

use super::oracle::{self, ClipTriangle, SmoothTriangle};
use super::stages::show_stencil;
use super::{panels, random_triangles, Group, Near, Rng, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{BlendFactor, Capability, CompareFunc, MatrixMode, PrimitiveMode, ShadeModel, StencilOp};

const G: Group = Group::Stiff;
const E: Tolerance = Tolerance::EXACT;

/// Identical to llvmpipe, and as close as llvmpipe to the f64 answer (`oracle::depth_tested_image`,
/// test `huge_coordinates_against_the_f64_answer`): exact at 96x96, 1 pixel over 1 LSB and 2 at 1 LSB
/// at 256x256, where both clip in f32 from the endpoint nearer each plane.
const HUGE: Tolerance = Tolerance {
    reason: "Identical to llvmpipe: both clip vertices at 1e8..1e38 in f32 from the endpoint nearer the plane; \
             against the f64 answer both are exact at 96x96 and 1 pixel over 1 LSB, 2 at 1 LSB at 256x256 \
             (test huge_coordinates_against_the_f64_answer).",
    ..Tolerance::EXACT
};

/// Offsets of 1e6..1e30 saturate the depth range; where llvmpipe's f32 clamp order differs, a few depth tests flip (measured 6 pixels at 256x256).
const OFFSET_EXTREME: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.0001,
    coverage: 0,
    reason: "Offsets of 1e6..1e30 saturate the depth range; where llvmpipe's f32 clamp order differs, a few depth tests flip (measured 6 pixels at 256x256).",
};

/// Judged against the exact oracle, not Mesa: softgl draws these as the real numbers say.
const EXACT_ORACLE: Tolerance = Tolerance {
    reason: "Exact against the oracle (coverage decided in exact arithmetic from the clip-space vertices): \
             softgl clips in f32 without losing the triangles; llvmpipe's and softpipe's clippers lose most of them.",
    ..Tolerance::EXACT
};

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("w_near_zero", G, Tolerance::one_lsb(1, 2), w_near_zero),
        Scene::new("negative_w", G, E, negative_w),
        Scene::new("huge_coordinates", G, HUGE, huge_coordinates),
        Scene::new("huge_triangles_exact", G, EXACT_ORACLE, huge_triangles).with_oracle(huge_triangles_oracle),
        Scene::new("nan_inf", G, E, nan_inf),
        Scene::new("degenerate_triangles", G, E, degenerate),
        Scene::new("slivers", G, E, slivers),
        Scene::new("subpixel_triangles", G, E, subpixel),
        Scene::new("edges_through_centers", G, E, edges_through_centers),
        Scene::new("shared_edges", G, E, shared_edges),
        Scene::new("near_far_1e-7", G, E, near_tiny),
        Scene::new("near_far_1e7", G, E, far_huge),
        Scene::new("near_singular_modelview", G, Tolerance::one_lsb(1, 0), near_singular),
        Scene::new("viewport_1x1", G, E, viewport_1x1),
        Scene::new("framebuffer_1x1", G, E, framebuffer_1x1).sized((1, 1), (1, 1)),
        Scene::new("huge_viewport", G, E, huge_viewport),
        Scene::new("stencil_wrap", G, E, stencil_wrap),
        Scene::new("zero_length_lines", G, E, zero_length_lines),
        Scene::new("polygon_offset_extreme", G, OFFSET_EXTREME, polygon_offset_extreme),
        Scene::new("extreme_colors", G, E, extreme_colors),
        Scene::new("coverage_ties", G, E, coverage_ties).sized((1024, 1024), (1024, 1024)),
    ]
}

/// Clip-space triangles drawn with identity matrices.
fn clip_space(r: &mut Rec) {
    r.matrix_mode(MatrixMode::Projection)
        .load_identity()
        .matrix_mode(MatrixMode::Modelview)
        .load_identity();
}

fn w_near_zero(r: &mut Rec, s: Size) {
    clip_space(r);
    let mut rng = Rng::new(50);
    r.begin(PrimitiveMode::Triangles);
    for i in 0..s.count(60) {
        for k in 0..3 {
            let w = if k == i % 3 {
                [1e-7, -1e-7, 1e-4, 0.0, 1e-30][i % 5]
            } else {
                rng.range(0.5, 1.5)
            };
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex4(
                rng.range(-1.0, 1.0) * 0.5,
                rng.range(-1.0, 1.0) * 0.5,
                0.0,
                w,
            );
        }
    }
    r.end();
}

fn negative_w(r: &mut Rec, s: Size) {
    clip_space(r);
    let mut rng = Rng::new(51);
    r.begin(PrimitiveMode::Triangles);
    for i in 0..s.count(60) {
        let all_negative = i % 4 == 0;
        for k in 0..3 {
            let w = if all_negative || k == i % 3 {
                -rng.range(0.2, 2.0)
            } else {
                rng.range(0.5, 2.0)
            };
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex4(
                rng.range(-1.0, 1.0) * w.abs(),
                rng.range(-1.0, 1.0) * w.abs(),
                rng.range(-0.5, 0.5) * w.abs(),
                w,
            );
        }
    }
    r.end();
}

/// The triangles of `huge_coordinates`: each with one vertex at up to
/// ±1e38 and two in the window.
fn huge_coordinate_triangles(s: Size) -> Vec<SmoothTriangle> {
    let mut rng = Rng::new(52);
    (0..s.count(40))
        .map(|i| {
            let big = [1e38f32, 1e20, 1e8, 3e3][i % 4];
            let c0 = [rng.unit(), rng.unit(), rng.unit(), 1.0];
            let v0 = [rng.range(0.0, s.wf()), rng.range(0.0, s.hf()), rng.range(-1.0, 1.0)];
            let c1 = [rng.unit(), rng.unit(), rng.unit(), 1.0];
            let v1 = [
                rng.range(-1.0, 1.0) * big,
                rng.range(-1.0, 1.0) * big,
                rng.range(-1.0, 1.0),
            ];
            let c2 = [rng.unit(), rng.unit(), rng.unit(), 1.0];
            let v2 = [rng.range(0.0, s.wf()), rng.range(0.0, s.hf()), rng.range(-1.0, 1.0)];
            SmoothTriangle {
                vertices: [v0, v1, v2],
                colors: [c0, c1, c2],
            }
        })
        .collect()
}

fn huge_coordinates(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    r.begin(PrimitiveMode::Triangles);
    for t in huge_coordinate_triangles(s) {
        for (c, v) in t.colors.iter().zip(t.vertices) {
            r.color(c[0], c[1], c[2], c[3]).vertex(v[0], v[1], v[2]);
        }
    }
    r.end();
}

/// Triangles with vertices at ±1e30 in clip space, each in one colour: the
/// first covers the whole viewport, the second the part below the clip
/// line y = 0.2, the third the part left of x = -0.3 (edges that stay exact
/// through any clipper: they are parallel to an axis).
const HUGE_TRIANGLES: [ClipTriangle; 3] = [
    ClipTriangle {
        vertices: [[-1e30, -1e30], [1e30, -1e30], [0.0, 1e30]],
        color: [1.0, 0.2, 0.6, 1.0],
    },
    ClipTriangle {
        vertices: [[-1e30, 0.2], [1e30, 0.2], [0.0, -1e30]],
        color: [0.0, 0.4, 1.0, 1.0],
    },
    ClipTriangle {
        vertices: [[-0.3, -1e30], [-0.3, 1e30], [-1e30, 0.0]],
        color: [0.2, 1.0, 0.4, 1.0],
    },
];

fn huge_triangles(r: &mut Rec, _s: Size) {
    clip_space(r);
    r.call(Call::ShadeModel(ShadeModel::Flat))
        .begin(PrimitiveMode::Triangles);
    for t in HUGE_TRIANGLES {
        let [cr, cg, cb, ca] = t.color;
        r.color(cr, cg, cb, ca);
        for [x, y] in t.vertices {
            r.vertex4(x, y, 0.0, 1.0);
        }
    }
    r.end();
}

fn huge_triangles_oracle(s: Size) -> image::RgbaImage {
    oracle::image(&HUGE_TRIANGLES, s)
}

/// NaN and infinity in positions, colours and a matrix, between ordinary
/// triangles that must still come out right.
fn nan_inf(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(53);
    let bad = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
    random_triangles(r, &mut rng, s.count(30), s, 12.0, (1.0, 1.0));
    r.begin(PrimitiveMode::Triangles);
    for i in 0..12 {
        for k in 0..3 {
            let (mut x, mut y) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
            if k == i % 3 {
                if i % 2 == 0 {
                    x = bad[i % 3];
                } else {
                    y = bad[(i + 1) % 3];
                }
            }
            r.color(1.0, 0.5, 0.0, 1.0).vertex(x, y, 0.0);
        }
    }
    r.end();
    r.call(Call::PushMatrix)
        .call(Call::LoadMatrix({
            let mut m = [0.0; 16];
            m[0] = 1.0;
            m[5] = f32::NAN;
            m[10] = 1.0;
            m[15] = 1.0;
            m
        }))
        .color(0.0, 1.0, 0.0, 1.0)
        .rect(0.0, 0.0, s.wf(), s.hf(), 0.0)
        .call(Call::PopMatrix);
    random_triangles(r, &mut rng, s.count(30), s, 12.0, (1.0, 1.0));
}

fn degenerate(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(54);
    r.call(Call::Enable(Capability::Blend))
        .call(Call::BlendFunc(BlendFactor::One, BlendFactor::One));
    r.begin(PrimitiveMode::Triangles);
    for i in 0..s.count(80) {
        let (x, y) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
        let (dx, dy) = (rng.range(-20.0, 20.0), rng.range(-20.0, 20.0));
        r.color(0.3, 0.2, 0.1, 1.0).vertex(x, y, 0.0);
        if i % 2 == 0 {
            // Collinear.
            r.vertex(x + dx, y + dy, 0.0).vertex(x + 2.0 * dx, y + 2.0 * dy, 0.0);
        } else {
            // Two vertices the same.
            r.vertex(x + dx, y + dy, 0.0).vertex(x, y, 0.0);
        }
    }
    r.end();
    random_triangles(r, &mut rng, s.count(40), s, 10.0, (1.0, 1.0));
}

fn slivers(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(55);
    r.begin(PrimitiveMode::Triangles);
    for _ in 0..s.count(200) {
        let (x0, y0) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
        let (x1, y1) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
        let t = rng.range(0.0, 1.0);
        let e = rng.range(0.01, 0.6);
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
            .vertex(x0, y0, 0.0)
            .vertex(x1, y1, 0.0)
            .vertex(x0 + (x1 - x0) * t + e, y0 + (y1 - y0) * t - e, 0.0);
    }
    r.end();
}

fn subpixel(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(56);
    r.begin(PrimitiveMode::Triangles);
    for _ in 0..s.count(2000) {
        let (x, y) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0);
        for _ in 0..3 {
            r.vertex(x + rng.range(-0.7, 0.7), y + rng.range(-0.7, 0.7), 0.0);
        }
    }
    r.end();
}

/// Triangles with vertices on pixel centres, so edges run through centres.
fn edges_through_centers(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(57);
    r.begin(PrimitiveMode::Triangles);
    for _ in 0..s.count(200) {
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0);
        let (x, y) = (rng.range(0.0, s.wf()).floor(), rng.range(0.0, s.hf()).floor());
        for _ in 0..3 {
            r.vertex(
                x + rng.range(-12.0, 12.0).round() + 0.5,
                y + rng.range(-12.0, 12.0).round() + 0.5,
                0.0,
            );
        }
    }
    r.end();
}

/// A jittered mesh drawn additively in dim grey: a pixel hit twice or missed
/// shows as a different value.
fn shared_edges(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(58);
    let n = 9;
    let grid: Vec<(f32, f32)> = (0..=n)
        .flat_map(|j| (0..=n).map(move |i| (i, j)))
        .map(|(i, j)| {
            let jitter = |v: usize| if v == 0 || v == n { 0.0 } else { 1.0 };
            (
                s.wf() * i as f32 / n as f32 + jitter(i) * rng.range(-3.0, 3.0),
                s.hf() * j as f32 / n as f32 + jitter(j) * rng.range(-3.0, 3.0),
            )
        })
        .collect();
    r.enable(Capability::Blend)
        .call(Call::BlendFunc(BlendFactor::One, BlendFactor::One))
        .color(0.25, 0.25, 0.25, 0.25);
    r.begin(PrimitiveMode::Triangles);
    for j in 0..n {
        for i in 0..n {
            let v = |a: usize, b: usize| grid[b * (n + 1) + a];
            for (x, y) in [
                v(i, j),
                v(i + 1, j),
                v(i + 1, j + 1),
                v(i, j),
                v(i + 1, j + 1),
                v(i, j + 1),
            ] {
                r.vertex(x, y, 0.0);
            }
        }
    }
    r.end();
}

fn frustum_scene(r: &mut Rec, s: Size, near: f64, far: f64, seed: u32) {
    r.matrix_mode(MatrixMode::Projection)
        .load_identity()
        .frustum(-near, near, -near, near, near, far)
        .matrix_mode(MatrixMode::Modelview)
        .load_identity()
        .enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Less));
    let mut rng = Rng::new(seed);
    r.begin(PrimitiveMode::Triangles);
    for _ in 0..s.count(300) {
        // Depths spread logarithmically over the whole range.
        let t = rng.unit() as f64;
        let z = -(near * (far / near).powf(t)) as f32;
        let sc = -z;
        let (cx, cy) = (rng.range(-1.0, 1.0) * sc, rng.range(-1.0, 1.0) * sc);
        for _ in 0..3 {
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
                cx + rng.range(-0.3, 0.3) * sc,
                cy + rng.range(-0.3, 0.3) * sc,
                z * rng.range(0.9, 1.1),
            );
        }
    }
    r.end();
}

fn near_tiny(r: &mut Rec, s: Size) {
    frustum_scene(r, s, 1e-7, 1.0, 59);
}

fn far_huge(r: &mut Rec, s: Size) {
    frustum_scene(r, s, 1.0, 1e7, 60);
}

fn near_singular(r: &mut Rec, s: Size) {
    r.call(Call::Scale([1e-7, 1e-7, 1.0]))
        .call(Call::Rotate(30.0, [0.0, 0.0, 1.0]))
        .call(Call::Scale([1e7, 1e7, 1.0]));
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    random_triangles(r, &mut Rng::new(61), s.count(200), s, 16.0, (1.0, 1.0));
}

/// A 1x1 viewport in several places; full-window geometry must land in it.
fn viewport_1x1(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(62);
    for i in 0..8 {
        let (x, y) = ((s.w as i32 * i) / 8, (s.h as i32 * (7 - i)) / 8);
        r.viewport(x, y, 1, 1);
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
            .rect(0.0, 0.0, s.wf(), s.hf(), 0.0);
    }
}

fn framebuffer_1x1(r: &mut Rec, _s: Size) {
    r.color(0.2, 0.4, 0.6, 1.0).rect(0.0, 0.0, 1.0, 1.0, 0.0);
    r.begin(PrimitiveMode::Triangles)
        .color(1.0, 0.0, 0.0, 1.0)
        .vertex(0.5, 0.5, 0.0)
        .vertex(0.9, 0.5, 0.0)
        .vertex(0.5, 0.9, 0.0)
        .end();
}

/// A viewport much larger than the window (8192 pixels, off to one side).
fn huge_viewport(r: &mut Rec, s: Size) {
    r.viewport(-3000, -5000, 8192, 8192);
    random_triangles(r, &mut Rng::new(63), s.count(200), s, 4.0, (1.0, 1.0));
}

/// 300 layers with INCR_WRAP (300 = 44 mod 256), and with DECR_WRAP from 0.
fn stencil_wrap(r: &mut Rec, s: Size) {
    r.enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 0, 0xff))
        .call(Call::ColorMask([false; 4]));
    for (i, op) in [
        StencilOp::IncrWrap,
        StencilOp::DecrWrap,
        StencilOp::Incr,
        StencilOp::Decr,
    ]
    .into_iter()
    .enumerate()
    {
        let p = panels(4, s)[i];
        r.call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, op));
        for k in 0..300 {
            let d = (k % 7) as f32;
            r.rect(p[0] + d, p[1] + d, p[2] - d, p[3] - d, 0.0);
        }
    }
    let values: Vec<u8> = (0..=3).chain(40..=45).chain(209..=216).chain(252..=255).collect();
    show_stencil(r, s, &values);
}

fn zero_length_lines(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(64);
    for w in [1.0, 3.0] {
        r.call(Call::LineWidth(w)).begin(PrimitiveMode::Lines);
        for i in 0..s.count(60) {
            let (mut x, mut y) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
            if i % 3 == 0 {
                (x, y) = (x.floor() + 0.5, y.floor() + 0.5);
            }
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
                .vertex(x, y, 0.0)
                .vertex(x, y, 0.0);
        }
        r.end();
    }
    r.call(Call::LineWidth(1.0)).begin(PrimitiveMode::LineLoop);
    r.vertex(10.5, 10.5, 0.0).end();
}

fn polygon_offset_extreme(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Lequal))
        .enable(Capability::PolygonOffsetFill);
    let mut rng = Rng::new(65);
    for (factor, units) in [(1e6, 0.0), (-1e6, 0.0), (0.0, 1e6), (0.0, -1e6), (1e30, -1e30)] {
        r.call(Call::PolygonOffset(factor, units));
        random_triangles(r, &mut rng, s.count(40), s, 16.0, (1.0, 1.0));
    }
}

fn extreme_colors(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(66);
    r.begin(PrimitiveMode::Triangles);
    for _ in 0..s.count(150) {
        for _ in 0..3 {
            let v = |rng: &mut Rng| [-5.0, 7.0, 1e30, -1e30, 0.5, 1.0 + 1e-7][(rng.unit() * 6.0) as usize % 6];
            r.color(v(&mut rng), v(&mut rng), v(&mut rng), v(&mut rng)).vertex(
                rng.range(0.0, s.wf()),
                rng.range(0.0, s.hf()),
                0.0,
            );
        }
    }
    r.end();
}

/// Triangles 10389 and 4854 of `random_20k_depth`, alone: softgl lights
/// pixel (64, 147) where llvmpipe does not, and misses (1012, 801).
/// The two triangles of random_20k_depth whose coverage once differed from
/// llvmpipe's: llvmpipe snaps its top-down y, and there a vertex's f32 y
/// lands on a subpixel tie (875.134765625, rounded to even) or the other
/// side of one, which the bottom-up y does not (docs/llvmpipe-facts.md 2).
fn coverage_ties(r: &mut Rec, _s: Size) {
    r.begin(PrimitiveMode::Triangles)
        .color(1.0, 0.5, 0.0, 1.0)
        .vertex(47.370697, 142.39249, -0.3981905)
        .vertex(69.0798, 148.8652, -0.13174462)
        .vertex(67.26863, 166.61145, -0.39922643)
        .color(0.0, 0.5, 1.0, 1.0)
        .vertex(997.6679, 818.7948, 0.53879595)
        .vertex(995.8139, 801.3328, -0.3328477)
        .vertex(1039.3273, 801.76874, 0.3715731)
        .end();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::backend::{softgl::Softgl, Backend, Outcome};
    use crate::metrics::compare;

    /// softgl against the f64 answer of `huge_coordinates`, at the tests'
    /// size and the report's: llvmpipe's distance from it, measured (its
    /// image is identical at both sizes).
    #[test]
    fn huge_coordinates_against_the_f64_answer() {
        let scene = crate::scenes::by_name("huge_coordinates").expect("scene");
        for (full, want) in [(false, (0, 0, 0)), (true, (1, 2, 0))] {
            let Outcome::Rendered { image, .. } = Softgl::new(softgl::Backend::Jit).render(&scene, full, 0) else {
                panic!("softgl renders the scene");
            };
            let size = scene.size(full);
            let exact = oracle::depth_tested_image(&huge_coordinate_triangles(size), size);
            let m = compare(&exact, &image, [0; 4], 1).expect("same size");
            assert_eq!(
                (m.over, m.near, m.coverage),
                want,
                "pixels over 1 LSB, at 1 LSB, coverage at {size:?}"
            );
        }
    }
}
