//! Points: squares of an integer size around the snapped position.

use super::{
    constant_planes, depth_value, emit_row, floor_div, snap, with_planes, FillSlot, RasterParams, RasterVertex,
    SpanSink, ONE,
};
use softgl_jit::FragmentSpan;

/// The integer size llvmpipe rasterizes for `size`: the size on the 1/256
/// grid, rounded up from half a step past one half (`(rint(s·256) + 127) >> 8`:
/// 2.5 → 2, 5.50098 → 5, 2.9 → 3), 1 to 255.
pub fn point_size_pixels(size: f32) -> u32 {
    if size.is_nan() {
        return 1;
    }
    let fixed = (size.clamp(0.0, 255.0) * 256.0).round_ties_even() as u32;
    ((fixed + 127) >> 8).clamp(1, 255)
}

/// Rasterizes a point of `size` at `v`: pixels whose centers satisfy
/// `p - s/2 < center <= p + s/2` on both axes (llvmpipe's convention).
pub fn point(v: &RasterVertex, size: f32, params: &RasterParams, sink: &mut dyn SpanSink) {
    if !(v.x.is_finite() && v.y.is_finite()) {
        return;
    }
    let half = i64::from(point_size_pixels(size)) * ONE / 2;
    let range = |p: i64, min: u32, end: u32| {
        let lo = (floor_div(p - half, ONE) + 1).max(i64::from(min));
        let hi = floor_div(p + half, ONE).min(i64::from(end) - 1);
        (lo, hi)
    };
    let b = params.bounds;
    let (x0, x1) = range(snap(v.x), b.x0, b.x1);
    let (y0, y1) = range(snap(v.y), b.y0, b.y1);
    if x0 > x1 || y0 > y1 {
        return;
    }
    with_planes(sink, |p| constant_planes(p, &v.v, v.z as f32, v.inv_w, params));
    // 32-bit depth is the span's (computed in f64, as for triangles).
    let z = depth_value(v.z, params.depth);
    let mut span = FragmentSpan::new(0, 0);
    for y in y0..=y1 {
        let mut fill_z = |_: u32, s: &mut FragmentSpan, i: usize| s.z[i] = z;
        let shade: Option<&mut FillSlot<'_>> = if params.depth.is_some() {
            Some(&mut fill_z)
        } else {
            None
        };
        emit_row(sink, &mut span, y as u32, x0 as u32, x1 as u32, shade);
    }
}
