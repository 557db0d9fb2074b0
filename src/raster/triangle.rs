//! Triangles: exact fixed-point edge functions, one span interval per row.

use super::edges::{Edge, Edges};
use super::{ceil_div, emit_row, floor_div, snap, with_planes, FillSlot, RasterParams, RasterVertex, SpanSink, ONE};
use crate::framebuffer::Rect;
use crate::geometry::varying::Varyings;
use softgl_jit::interp::row_of;
use softgl_jit::shade::{slot, Planes};
use softgl_jit::{DepthFormat, FragmentSpan};

/// An attribute plane in llvmpipe's frame: x right, y down from the top row,
/// evaluated at integer pixel coordinates for the pixel centers (by the
/// fragment stage: `Planes::at`).
#[derive(Clone, Copy, Debug)]
struct Plane {
    a0: f32,
    dadx: f32,
    dady: f32,
}

/// Triangle setup in f32 from the unsnapped window positions, step for step
/// as llvmpipe computes it, so interpolated colors and depths match its bits
/// (docs/llvmpipe-facts.md, "attribute interpolation").
struct Setup {
    x0c: f32,
    y0c: f32,
    dx20o: f32,
    dy20o: f32,
    dx01o: f32,
    dy01o: f32,
}

impl Setup {
    fn new(p: [(f32, f32); 3]) -> Setup {
        let (dx01, dy01) = (p[0].0 - p[1].0, p[0].1 - p[1].1);
        let (dx20, dy20) = (p[2].0 - p[0].0, p[2].1 - p[0].1);
        let ooa = 1.0 / (dx01 * dy20 - dy01 * dx20);
        Setup {
            x0c: p[0].0 - 0.5,
            y0c: p[0].1 - 0.5,
            dx20o: dx20 * ooa,
            dy20o: dy20 * ooa,
            dx01o: dx01 * ooa,
            dy01o: dy01 * ooa,
        }
    }

    fn plane(&self, a: [f32; 3]) -> Plane {
        let (da01, da20) = (a[0] - a[1], a[2] - a[0]);
        let dadx = da01 * self.dy20o - da20 * self.dy01o;
        let dady = da20 * self.dx01o - da01 * self.dx20o;
        Plane {
            a0: a[0] - (dadx * self.x0c + dady * self.y0c),
            dadx,
            dady,
        }
    }
}

/// Rasterizes a triangle, either winding. `flat` (the provoking vertex's
/// varyings) replaces the interpolated colours.
pub fn triangle(v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams, sink: &mut dyn SpanSink) {
    // docs/llvmpipe-facts.md 2: the y snapped top-down, reflected into GL rows.
    cover(Edges::window_points(v, params.height), v, flat, params, sink);
}

/// The pixels [`triangle`] may cover: its snapped bounding box within
/// `params.bounds`, as `cover` finds it; `None` when it covers nothing.
pub fn triangle_box(v: [&RasterVertex; 3], params: &RasterParams) -> Option<Rect> {
    let e = Edges::window(v, params.height)?;
    let b = params.bounds;
    let x0 = e.px.0.max(i64::from(b.x0));
    let x1 = e.px.1.min(i64::from(b.x1) - 1);
    let y0 = e.py.0.max(i64::from(b.y0));
    let y1 = e.py.1.min(i64::from(b.y1) - 1);
    (x0 <= x1 && y0 <= y1).then(|| Rect {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32 + 1,
        y1: y1 as u32 + 1,
    })
}

/// [`triangle`] for a wide line's quad, whose corners are made in GL's
/// bottom-up frame and snapped there.
pub(super) fn triangle_y_up(
    v: [&RasterVertex; 3],
    flat: Option<&Varyings>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    cover(v.map(|v| (snap(v.x), snap(v.y))), v, flat, params, sink);
}

/// Covers the triangle of the snapped bottom-up positions `p` of `v`.
pub(super) fn cover(
    p: [(i64, i64); 3],
    v: [&RasterVertex; 3],
    flat: Option<&Varyings>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    let Some(e) = Edges::new(p) else { return };
    if params.bounds.is_empty() {
        return;
    }
    let edges = e.edges;
    let b = params.bounds;
    let px0 = e.px.0.max(i64::from(b.x0));
    let px1 = e.px.1.min(i64::from(b.x1) - 1);
    let py0 = e.py.0.max(i64::from(b.y0));
    let py1 = e.py.1.min(i64::from(b.y1) - 1);
    if px0 > px1 || py0 > py1 {
        return;
    }

    let per_fragment_z = with_planes(sink, |planes| setup_planes(v, flat, params, planes));
    // A box wholly inside (a tile a large triangle covers) needs no edge
    // per row: every row is the box's (the fill frame's tiles, mostly).
    let inside = e.contains_box((px0, px1), (py0, py1));
    let mut span = FragmentSpan::new(0, 0);
    for py in py0..=py1 {
        let sy = py * ONE;
        let (mut lo, mut hi) = (px0, px1);
        for &Edge { a: (ax, ay), dx, dy, k } in edges.iter().filter(|_| !inside) {
            // E(px) = dx * (sy - ay) - dy * (px * ONE - ax) must be >= k.
            let c = dx * (sy - ay) + dy * ax;
            let m = dy * ONE;
            if m == 0 {
                if c < k {
                    lo = 1;
                    hi = 0;
                }
            } else if m > 0 {
                hi = hi.min(floor_div(c - k, m));
            } else {
                lo = lo.max(ceil_div(k - c, -m));
            }
        }
        if lo > hi {
            continue;
        }
        let row = row_of(py as u32, params.height);
        let mut fill_z = |x: u32, s: &mut FragmentSpan, i: usize| {
            if let Some((format, z)) = per_fragment_z {
                let z = z.dady.mul_add(row, z.dadx.mul_add(x as f32, z.a0));
                s.z[i] = crate::framebuffer::depth_to_unorm(f64::from(z), format);
            }
        };
        let shade: Option<&mut FillSlot<'_>> = if per_fragment_z.is_some() {
            Some(&mut fill_z)
        } else {
            None
        };
        emit_row(sink, &mut span, py as u32, lo as u32, hi as u32, shade);
    }
}

/// Writes the planes of a triangle's attributes for the fragment stage into
/// `planes`, set up in llvmpipe's order: colours (the flat ones constant), the
/// secondary colour, the fog coordinate and the texture coordinates over w,
/// 1/w, depth (with polygon offset). Only the slots the layout uses are
/// written. Returns the depth format and plane of the depth values the
/// rasterizer computes per fragment itself (32-bit depth, which the shading
/// stage leaves to the span).
fn setup_planes(
    v: [&RasterVertex; 3],
    flat: Option<&Varyings>,
    params: &RasterParams,
    planes: &mut Planes,
) -> Option<(DepthFormat, Plane)> {
    // llvmpipe orders the vertices by the sign of the snapped area in its
    // y-down frame, and swaps the first two when it is negative.
    let mut v = v;
    let q = v.map(|v| (snap(v.x), snap(v.y_down)));
    let area = (q[0].0 - q[1].0) * (q[2].1 - q[0].1) - (q[2].0 - q[0].0) * (q[0].1 - q[1].1);
    if area < 0 {
        v.swap(0, 1);
    }
    let setup = Setup::new(v.map(|v| (v.x, v.y_down)));
    let mut put = |k: usize, p: Plane| planes.set(k, p.a0, p.dadx, p.dady);
    let layout = params.layout;
    let over_w = |k: usize| setup.plane(v.map(|v| v.v[k] * v.inv_w));
    put(slot::INV_W, setup.plane(v.map(|v| v.inv_w)));
    let colours = [
        (layout.color(), slot::COLOR, 4),
        (layout.secondary(), slot::SECONDARY, 3),
    ];
    for (at, to, n) in colours {
        let Some(o) = at else { continue };
        for c in 0..n {
            let p = match flat {
                Some(f) => Plane {
                    a0: f[o + c],
                    dadx: 0.0,
                    dady: 0.0,
                },
                None => over_w(o + c),
            };
            put(to + c, p);
        }
    }
    if let Some(o) = layout.fog() {
        put(slot::FOG, over_w(o));
    }
    for (unit, o) in layout.tex_units() {
        for c in 0..4 {
            put(slot::tex(unit) + c, over_w(o + c));
        }
    }
    let mut per_fragment_z = None;
    if let Some(f) = params.depth {
        let mut z = v.map(|v| v.z as f32);
        if let Some((factor, units)) = params.offset {
            let slope = setup.plane(z);
            let o = offset(factor, units, slope.dadx, slope.dady, f);
            z = z.map(|z| (z + o).clamp(0.0, 1.0));
        }
        let plane = setup.plane(z);
        put(slot::Z, plane);
        if f == DepthFormat::D32 {
            per_fragment_z = Some((f, plane));
        }
    }
    per_fragment_z
}

/// Polygon offset in window depth, as llvmpipe computes it in f32:
/// `units · 2 / max + max(|dz/dx|, |dz/dy|) · factor`, where `max` is the
/// largest depth value (llvmpipe's unit is twice the minimum resolvable
/// difference: measured, docs/llvmpipe-facts.md). Not-a-number offsets are 0;
/// infinite ones saturate like huge finite ones once depth is clamped.
pub fn offset(factor: f32, units: f32, dzdx: f32, dzdy: f32, format: DepthFormat) -> f32 {
    let o = units * (2.0 / format.max_value() as f32) + dzdx.abs().max(dzdy.abs()) * factor;
    if o.is_nan() {
        0.0
    } else {
        o.clamp(-2.0, 2.0)
    }
}
