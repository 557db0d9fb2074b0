//! Bitmaps as fragments: the set bits of a placed bitmap inside the
//! bounds, as spans of up to 64 fragments with the raster position's
//! constant planes (its colours, fog distance, texture coordinates, depth).

use super::{constant_planes, depth_value, with_planes, RasterParams, RasterVertex, SpanSink};
use crate::pixel_rect::PlacedBitmap;
use softgl_jit::FragmentSpan;

/// Rasterizes `b` inside `params.bounds` with the constants of `v`.
pub fn bitmap(v: &RasterVertex, b: &PlacedBitmap, params: &RasterParams, sink: &mut dyn SpanSink) {
    let Some(r) = b.rect(params.bounds) else { return };
    with_planes(sink, |p| constant_planes(p, &v.v, v.z as f32, v.inv_w, params));
    let z = depth_value(v.z, params.depth);
    let mut span = FragmentSpan::new(0, 0);
    if params.depth.is_some() {
        span.z = [z; softgl_jit::SPAN_MAX];
    }
    for y in r.y0..r.y1 {
        let row = (i64::from(y) - b.y) as u32;
        let mut x = r.x0;
        while x < r.x1 {
            let n = (r.x1 - x).min(softgl_jit::SPAN_MAX as u32);
            let mut mask = b.image.row_bits(row, (i64::from(x) - b.x) as u32);
            if n < 64 {
                mask &= (1u64 << n) - 1;
            }
            if mask != 0 {
                (span.x, span.y, span.len, span.mask) = (x, y, n, mask);
                sink.span(&span);
            }
            x += n;
        }
    }
}
