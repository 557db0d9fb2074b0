//! Primitive modes, shading, culling, polygon mode and offset.

use super::{panels, random_triangles, Group, Near, Rng, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{Capability, CompareFunc, Face, FrontFace, MatrixMode, PolygonMode, PrimitiveMode, ShadeModel};

const G: Group = Group::Primitive;
const E: Tolerance = Tolerance::EXACT;

/// Line end points exactly on k or k+0.5: llvmpipe's diamond-exit tests are asymmetric there and softgl's are not (measured at 256x256: 40 pixels, 26 of them coverage).
const LINE_TIES: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.00065,
    coverage: 26,
    reason: "Line end points exactly on k or k+0.5: llvmpipe's diamond-exit tests are asymmetric there and softgl's are not (measured at 256x256: 40 pixels, 26 of them coverage).",
};

/// Quads in a draw that needs clipping split along v1-v3 in llvmpipe (its draw pipeline), else along v0-v2; softgl follows the same rule (docs/llvmpipe-facts.md 12), so the scene matches exactly.
const QUAD_DIAGONAL: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.0,
    coverage: 0,
    reason: "Exact: softgl splits GL_QUADS as llvmpipe does per draw (v1-v3 when a vertex needs clipping or a face is unfilled, v0-v2 otherwise; docs/llvmpipe-facts.md 12).",
};

/// Polygon-mode edges are lines between the triangle's vertices: line end-point ties as for lines (measured 121 pixels, 7 coverage at 256x256).
const POLYGON_EDGES: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.0019,
    coverage: 7,
    reason: "Polygon-mode edges are lines between the triangle's vertices: line end-point ties as for lines (measured 121 pixels, 7 coverage at 256x256).",
};

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("points", G, E, points),
        Scene::new("lines_thin", G, LINE_TIES, lines_thin),
        Scene::new("lines_wide", G, LINE_TIES, lines_wide),
        Scene::new("line_strip_loop", G, LINE_TIES, line_strip_loop),
        Scene::new("triangle_strip_fan", G, E, triangle_strip_fan),
        Scene::new("quads", G, QUAD_DIAGONAL, quads),
        Scene::new("quad_single", G, E, quad_single),
        // Measured 2026-11-23: 1 pixel 1 LSB off at 96x96 since softgl's viewport transform is
        // fused as draw's (docs/llvmpipe-facts.md 11), which made 24 texture scenes exact.
        Scene::new("quad_strip", G, Tolerance::one_lsb(1, 0), quad_strip),
        Scene::new("polygon", G, Tolerance::one_lsb(1, 3), polygon),
        Scene::new("modes_flat", G, E, modes_flat),
        Scene::new("modes_smooth", G, Tolerance::one_lsb(0, 1), modes_smooth),
        Scene::new("culling", G, E, culling),
        Scene::new("polygon_mode", G, POLYGON_EDGES, polygon_mode),
        Scene::new("polygon_offset", G, E, polygon_offset),
        Scene::new("vertex_arrays", G, E, vertex_arrays),
        Scene::new("perspective_clipped", G, E, perspective),
    ]
}

fn points(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(30);
    for size in 1..=6 {
        r.call(Call::PointSize(size as f32 + if size % 2 == 0 { 0.4 } else { 0.0 }));
        r.begin(PrimitiveMode::Points);
        for _ in 0..s.count(80) {
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
                rng.range(0.0, s.wf()),
                rng.range(0.0, s.hf()),
                0.0,
            );
        }
        r.end();
    }
}

fn random_lines(r: &mut Rec, rng: &mut Rng, n: usize, s: Size) {
    r.begin(PrimitiveMode::Lines);
    for _ in 0..n {
        for _ in 0..2 {
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
                rng.range(-4.0, s.wf() + 4.0),
                rng.range(-4.0, s.hf() + 4.0),
                0.0,
            );
        }
    }
    r.end();
}

fn lines_thin(r: &mut Rec, s: Size) {
    random_lines(r, &mut Rng::new(31), s.count(300), s);
}

fn lines_wide(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(32);
    for w in [2.0, 3.0, 5.0] {
        r.call(Call::LineWidth(w));
        random_lines(r, &mut rng, s.count(40), s);
    }
}

fn line_strip_loop(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(33);
    for mode in [PrimitiveMode::LineStrip, PrimitiveMode::LineLoop] {
        r.begin(mode);
        for _ in 0..s.count(40) {
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
                rng.range(0.0, s.wf()),
                rng.range(0.0, s.hf()),
                0.0,
            );
        }
        r.end();
    }
}

/// A ring of vertices around a centre, for strips and fans.
fn ring(r: &mut Rec, rng: &mut Rng, c: (f32, f32), radius: f32, n: usize, strip: bool) {
    for i in 0..n {
        let a = i as f32 / (n - 1) as f32 * std::f32::consts::PI * 1.7;
        let rad = if strip && i % 2 == 1 { radius * 0.45 } else { radius };
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
            .vertex(c.0 + rad * a.cos(), c.1 + rad * a.sin(), 0.0);
    }
}

fn triangle_strip_fan(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(34);
    let rad = s.wf().min(s.hf()) * 0.22;
    r.begin(PrimitiveMode::TriangleStrip);
    ring(r, &mut rng, (s.wf() * 0.27, s.hf() * 0.5), rad, 14, true);
    r.end();
    r.begin(PrimitiveMode::TriangleFan);
    r.color(1.0, 1.0, 1.0, 1.0).vertex(s.wf() * 0.73, s.hf() * 0.5, 0.0);
    ring(r, &mut rng, (s.wf() * 0.73, s.hf() * 0.5), rad, 12, false);
    r.end();
}

fn quads(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(35);
    r.begin(PrimitiveMode::Quads);
    for _ in 0..s.count(120) {
        let (cx, cy) = (rng.range(0.0, s.wf()), rng.range(0.0, s.hf()));
        for k in 0..4 {
            let a = k as f32 * std::f32::consts::FRAC_PI_2 + rng.range(-0.4, 0.4);
            let d = rng.range(4.0, 16.0);
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
                .vertex(cx + d * a.cos(), cy + d * a.sin(), 0.0);
        }
    }
    r.end();
}

/// One smooth quad alone in its `glBegin`/`glEnd`, red at v0 and v2, black at
/// v1 and v3: llvmpipe splits a lone quad along v0-v2 (red diagonal), but a
/// batch of two or more along v1-v3, as softpipe always does (measured with
/// OSMesa, Mesa 22.3.6), which is what the `quads` scene shows.
fn quad_single(r: &mut Rec, s: Size) {
    let (w, h) = (s.wf(), s.hf());
    r.begin(PrimitiveMode::Quads)
        .color(1.0, 0.0, 0.0, 1.0)
        .vertex(w * 0.15, h * 0.15, 0.0)
        .color(0.0, 0.0, 0.0, 1.0)
        .vertex(w * 0.8, h * 0.2, 0.0)
        .color(1.0, 0.0, 0.0, 1.0)
        .vertex(w * 0.75, h * 0.8, 0.0)
        .color(0.0, 0.0, 0.0, 1.0)
        .vertex(w * 0.2, h * 0.7, 0.0)
        .end();
}

fn quad_strip(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(36);
    for row in 0..3 {
        let y = s.hf() * (0.2 + 0.3 * row as f32);
        r.begin(PrimitiveMode::QuadStrip);
        for i in 0..9 {
            let x = s.wf() * (0.05 + 0.11 * i as f32);
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
                .vertex(x, y - 8.0 + rng.range(-3.0, 3.0), 0.0)
                .color(rng.unit(), rng.unit(), rng.unit(), 1.0)
                .vertex(x + rng.range(-3.0, 3.0), y + 8.0, 0.0);
        }
        r.end();
    }
}

fn polygon(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(37);
    for (i, p) in panels(4, s).into_iter().enumerate() {
        let c = ((p[0] + p[2]) / 2.0, (p[1] + p[3]) / 2.0);
        let n = 5 + 2 * i;
        r.begin(PrimitiveMode::Polygon);
        for k in 0..n {
            let a = k as f32 / n as f32 * std::f32::consts::TAU;
            // The last panel's polygon is concave: the fan overlaps itself.
            let rad = (p[2] - p[0]) * if i == 3 && k % 2 == 1 { 0.15 } else { 0.45 };
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
                .vertex(c.0 + rad * a.cos(), c.1 + rad * a.sin(), 0.0);
        }
        r.end();
    }
}

/// One panel per primitive mode, the same eight vertices in each.
fn all_modes(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(38);
    r.call(Call::PointSize(3.0));
    for (p, mode) in panels(10, s).into_iter().zip(PrimitiveMode::ALL) {
        let (w, h) = (p[2] - p[0], p[3] - p[1]);
        r.begin(mode);
        for k in 0..8 {
            let (fx, fy) = ((k / 2) as f32 / 3.0, (k % 2) as f32);
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
                p[0] + 2.0 + fx * (w - 4.0),
                p[1] + 2.0 + fy * (h - 4.0) + (k as f32 * 1.7) % 3.0,
                0.0,
            );
        }
        r.end();
    }
}

fn modes_flat(r: &mut Rec, s: Size) {
    r.shade_model(ShadeModel::Flat);
    all_modes(r, s);
}

fn modes_smooth(r: &mut Rec, s: Size) {
    all_modes(r, s);
}

/// Four panels (cull back, cull front, cull both, cull back with CW front
/// faces), each with a CCW and a CW triangle.
fn culling(r: &mut Rec, s: Size) {
    r.enable(Capability::CullFace);
    let setups = [
        (Face::Back, FrontFace::Ccw),
        (Face::Front, FrontFace::Ccw),
        (Face::FrontAndBack, FrontFace::Ccw),
        (Face::Back, FrontFace::Cw),
    ];
    for (p, (face, front)) in panels(4, s).into_iter().zip(setups) {
        r.call(Call::CullFace(face)).call(Call::FrontFace(front));
        let xm = (p[0] + p[2]) / 2.0;
        r.begin(PrimitiveMode::Triangles)
            .color(1.0, 0.0, 0.0, 1.0)
            .vertex(p[0] + 1.0, p[1] + 1.0, 0.0)
            .color(0.0, 1.0, 0.0, 1.0)
            .vertex(xm - 1.0, p[1] + 1.0, 0.0)
            .color(0.0, 0.0, 1.0, 1.0)
            .vertex(p[0] + 1.0, p[3] - 1.0, 0.0)
            .color(1.0, 1.0, 0.0, 1.0)
            .vertex(xm + 1.0, p[1] + 1.0, 0.0)
            .color(0.0, 1.0, 1.0, 1.0)
            .vertex(xm + 1.0, p[3] - 1.0, 0.0)
            .color(1.0, 0.0, 1.0, 1.0)
            .vertex(p[2] - 1.0, p[1] + 1.0, 0.0)
            .end();
    }
}

fn polygon_mode(r: &mut Rec, s: Size) {
    r.call(Call::PolygonMode(Face::Front, PolygonMode::Line))
        .call(Call::PolygonMode(Face::Back, PolygonMode::Point))
        .call(Call::PointSize(2.0));
    random_triangles(r, &mut Rng::new(39), s.count(120), s, 20.0, (1.0, 1.0));
}

/// Coplanar pairs: a second draw at the same depth with offset passes or
/// fails LESS depending on the offset's sign.
fn polygon_offset(r: &mut Rec, s: Size) {
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    let mut rng = Rng::new(40);
    let tri = |r: &mut Rec, rng: &mut Rng, v: &[(f32, f32, f32); 3]| {
        r.begin(PrimitiveMode::Triangles);
        for &(x, y, z) in v {
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(x, y, z);
        }
        r.end();
    };
    for (i, (factor, units)) in [
        (0.0, -1.0),
        (0.0, 1.0),
        (-1.0, 0.0),
        (1.0, -2.0),
        (-2.0, -4.0),
        (0.5, 0.0),
    ]
    .into_iter()
    .enumerate()
    {
        let p = panels(6, s)[i];
        let v = [
            (p[0] + 1.0, p[1] + 1.0, rng.range(-0.8, 0.8)),
            (p[2] - 1.0, p[1] + 3.0, rng.range(-0.8, 0.8)),
            (p[0] + 5.0, p[3] - 1.0, rng.range(-0.8, 0.8)),
        ];
        r.disable(Capability::PolygonOffsetFill);
        tri(r, &mut rng, &v);
        r.enable(Capability::PolygonOffsetFill)
            .call(Call::PolygonOffset(factor, units));
        tri(r, &mut rng, &v);
    }
}

fn vertex_arrays(r: &mut Rec, s: Size) {
    let mut rng = Rng::new(41);
    let n = s.count(300) * 3;
    let positions = (0..n)
        .map(|_| {
            [
                rng.range(0.0, s.wf()),
                rng.range(0.0, s.hf()),
                rng.range(-1.0, 1.0),
                1.0,
            ]
        })
        .collect();
    let colors = (0..n).map(|_| [rng.unit(), rng.unit(), rng.unit(), 1.0]).collect();
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    r.call(Call::DrawArrays {
        mode: PrimitiveMode::Triangles,
        positions,
        colors,
    });
}

/// Random triangles in a perspective frustum, many crossing the near plane.
fn perspective(r: &mut Rec, s: Size) {
    r.matrix_mode(MatrixMode::Projection)
        .load_identity()
        .frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0)
        .matrix_mode(MatrixMode::Modelview)
        .enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Less));
    let mut rng = Rng::new(42);
    r.begin(PrimitiveMode::Triangles);
    for _ in 0..s.count(400) {
        let cz = -rng.range(0.3, 11.0);
        let sc = -cz;
        let (cx, cy) = (rng.range(-1.3, 1.3) * sc, rng.range(-1.3, 1.3) * sc);
        for _ in 0..3 {
            r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
                cx + rng.range(-0.25, 0.25) * sc,
                cy + rng.range(-0.25, 0.25) * sc,
                cz + rng.range(-1.5, 1.5),
            );
        }
    }
    r.end();
}
