//! Lines, every width, as the parallelogram llvmpipe draws: along the major
//! axis it runs between pixel boundaries, from the first to the last pixel
//! column (row) the diamond-exit rule lights; across, it is offset by ±width/2;
//! it is filled with the triangle rule.

use super::triangle::triangle_y_up;
use super::{RasterParams, RasterVertex, SpanSink};
use crate::geometry::varying::Varyings;

/// The integer width GL rasterizes for `width`: rounded half up, 1 to 255.
pub fn line_width_pixels(width: f32) -> u32 {
    if width.is_nan() {
        return 1;
    }
    (width + 0.5).floor().clamp(1.0, 255.0) as u32
}

/// Whether `(x, y)` lies strictly inside the diamond of pixel `(i, j)`.
fn in_diamond(x: f32, y: f32, i: i64, j: i64) -> bool {
    (x - (i as f32 + 0.5)).abs() + (y - (j as f32 + 0.5)).abs() < 0.5
}

/// Rasterizes the segment `a → b`. `flat` (the provoking vertex's varyings)
/// replaces the interpolated colours.
pub fn line(
    a: &RasterVertex,
    b: &RasterVertex,
    width: f32,
    flat: Option<&Varyings>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    if !(dx.is_finite() && dy.is_finite()) || (dx == 0.0 && dy == 0.0) {
        return;
    }
    // (u, v): major and minor axis; an exact diagonal is x-major.
    let x_major = dx.abs() >= dy.abs();
    let uv = |x: f32, y: f32| if x_major { (x, y) } else { (y, x) };
    let ((u0, v0), (u1, v1)) = (uv(a.x, a.y), uv(b.x, b.y));
    let (du, dv) = (u1 - u0, v1 - v0);
    let (umin, umax) = (u0.min(u1), u0.max(u1));
    let minor_at = |u: f32| v0 + dv * ((u - u0) / du);

    // Diamond exit: the fragment of column i is the one whose row holds the
    // line at the column's center; it is lit when the segment exits its
    // diamond — not when the end point lies inside it, and yes when the start
    // point does. Columns strictly between the ends always are.
    let lit = |i: i64| {
        let cu = i as f32 + 0.5;
        let j = minor_at(cu).ceil() as i64 - 1;
        let (px, py) = if x_major { (i, j) } else { (j, i) };
        let crosses = cu >= umin && cu <= umax;
        (crosses || in_diamond(a.x, a.y, px, py)) && !in_diamond(b.x, b.y, px, py)
    };
    let (first, last) = (umin.floor() as i64, umax.floor() as i64);
    let lo = if lit(first) { first } else { first + 1 };
    let hi = if last == first || lit(last) { last } else { last - 1 };
    if lo > hi || (lo == hi && !lit(lo)) {
        return;
    }

    // The parallelogram's corners, with attributes varying along the major
    // axis only, as llvmpipe 22.3 interpolates them (perspective-correct
    // through 1/w, like triangles).
    let half = line_width_pixels(width) as f32 / 2.0;
    let corner = |u: f32, side: f32| {
        let v = minor_at(u) + side * half;
        let (x, y) = if x_major { (u, v) } else { (v, u) };
        let t = (u - u0) / du;
        let inv_w = a.inv_w + (b.inv_w - a.inv_w) * t;
        let mut vary = a.v;
        for (k, out) in vary[..params.layout.len()].iter_mut().enumerate() {
            let cw = a.v[k] * a.inv_w + (b.v[k] * b.inv_w - a.v[k] * a.inv_w) * t;
            *out = cw / inv_w;
        }
        RasterVertex {
            x,
            y,
            y_down: params.height as f32 - y,
            z: a.z + (b.z - a.z) * f64::from(t),
            inv_w,
            v: vary,
        }
    };
    let (ulo, uhi) = (lo as f32, (hi + 1) as f32);
    let quad = [corner(ulo, -1.0), corner(uhi, -1.0), corner(uhi, 1.0), corner(ulo, 1.0)];
    let params = RasterParams {
        offset: None,
        ..*params
    };
    triangle_y_up([&quad[0], &quad[1], &quad[2]], flat, &params, sink);
    triangle_y_up([&quad[0], &quad[2], &quad[3]], flat, &params, sink);
}
