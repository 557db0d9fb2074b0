//! Lines. Width 1 follows GL's diamond-exit rule; wider lines are the
//! parallelogram llvmpipe draws: the segment offset by ±width/2 across its
//! major axis, no end caps, filled with the triangle rule.

use super::{color_to_unorm8, depth_value, triangle, RasterParams, RasterVertex, SpanSink};
use softgl_jit::FragmentSpan;

/// The integer width GL rasterizes for `width`: rounded half up, at least 1.
pub fn line_width_pixels(width: f32) -> u32 {
    if width.is_nan() {
        return 1;
    }
    (width + 0.5).floor().clamp(1.0, 255.0) as u32
}

/// Rasterizes the segment `a → b`. `flat` replaces the interpolated color.
pub fn line(
    a: &RasterVertex,
    b: &RasterVertex,
    width: f32,
    flat: Option<[f32; 4]>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    if !(dx.is_finite() && dy.is_finite()) || (dx == 0.0 && dy == 0.0) {
        return;
    }
    let w = line_width_pixels(width);
    if w > 1 {
        wide_line(a, b, w as f32, dx.abs() >= dy.abs(), flat, params, sink);
    } else {
        thin_line(a, b, flat, params, sink);
    }
}

fn wide_line(
    a: &RasterVertex,
    b: &RasterVertex,
    w: f32,
    x_major: bool,
    flat: Option<[f32; 4]>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    let (ox, oy) = if x_major { (0.0, w / 2.0) } else { (w / 2.0, 0.0) };
    let shift = |v: &RasterVertex, s: f32| RasterVertex {
        x: v.x + ox * s,
        y: v.y + oy * s,
        ..*v
    };
    let (a0, a1, b0, b1) = (shift(a, -1.0), shift(a, 1.0), shift(b, -1.0), shift(b, 1.0));
    let params = RasterParams {
        offset: None,
        ..*params
    };
    triangle([&a0, &b0, &b1], flat, &params, sink);
    triangle([&a0, &b1, &a1], flat, &params, sink);
}

/// Whether `(x, y)` lies strictly inside the diamond of pixel `(i, j)`.
fn in_diamond(x: f32, y: f32, i: i64, j: i64) -> bool {
    (x - (i as f32 + 0.5)).abs() + (y - (j as f32 + 0.5)).abs() < 0.5
}

/// Diamond exit: along the major axis, each pixel column (row) crossed gives the
/// fragment whose row (column) holds the line at the column's center; that
/// fragment is produced when the segment exits its diamond — so it is not when
/// the end point lies inside it, and it is when the start point does.
fn thin_line(
    a: &RasterVertex,
    b: &RasterVertex,
    flat: Option<[f32; 4]>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    let x_major = (b.x - a.x).abs() >= (b.y - a.y).abs();
    // Work in (u, v) = (major, minor) coordinates.
    let swap = |x: f32, y: f32| if x_major { (x, y) } else { (y, x) };
    let (u0, v0) = swap(a.x, a.y);
    let (u1, v1) = swap(b.x, b.y);
    let du = u1 - u0;
    let (umin, umax) = (u0.min(u1), u0.max(u1));
    let r = params.bounds;
    let (major, minor) = if x_major {
        ((r.x0, r.x1), (r.y0, r.y1))
    } else {
        ((r.y0, r.y1), (r.x0, r.x1))
    };
    let first = (umin.floor() as i64).max(i64::from(major.0));
    let last = (umax.floor() as i64).min(i64::from(major.1) - 1);

    let mut span = FragmentSpan::new(0, 0);
    for i in first..=last {
        let cu = i as f32 + 0.5;
        let t = (cu - u0) / du;
        let v_at = v0 + (v1 - v0) * t;
        // A line exactly on a pixel boundary belongs to the pixel below/left of it.
        let j = v_at.ceil() as i64 - 1;
        if j < i64::from(minor.0) || j >= i64::from(minor.1) {
            continue;
        }
        let (ex, ey) = if x_major { (i, j) } else { (j, i) };
        let crosses = cu >= umin && cu <= umax;
        if !(crosses || in_diamond(a.x, a.y, ex, ey)) || in_diamond(b.x, b.y, ex, ey) {
            continue;
        }
        let t = t.clamp(0.0, 1.0);
        span.x = ex as u32;
        span.y = ey as u32;
        span.len = 1;
        span.mask = 1;
        let c = flat.unwrap_or_else(|| lerp_color(a, b, t));
        if params.color {
            span.r[0] = color_to_unorm8(c[0]);
            span.g[0] = color_to_unorm8(c[1]);
            span.b[0] = color_to_unorm8(c[2]);
            span.a[0] = color_to_unorm8(c[3]);
        }
        span.z[0] = depth_value(a.z + (b.z - a.z) * f64::from(t), params.depth);
        sink.span(&span);
    }
}

/// Perspective-correct color at parameter `t` (in window space) along `a → b`.
fn lerp_color(a: &RasterVertex, b: &RasterVertex, t: f32) -> [f32; 4] {
    let iw = a.inv_w + (b.inv_w - a.inv_w) * t;
    let ta = (1.0 - t) * a.inv_w / iw;
    let tb = t * b.inv_w / iw;
    if !(ta.is_finite() && tb.is_finite()) {
        return [0, 1, 2, 3].map(|c| a.color[c] + (b.color[c] - a.color[c]) * t);
    }
    [0, 1, 2, 3].map(|c| a.color[c] * ta + b.color[c] * tb)
}
