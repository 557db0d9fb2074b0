//! Bitmaps as fragments: the set bits of a placed bitmap inside the
//! bounds, as spans of up to 64 fragments with the raster position's
//! constant planes (its colours, fog distance, texture coordinates, depth);
//! pixel rectangles as spans of their own colours and depths, or stencil
//! values written straight into the buffer.

use super::{constant_planes, depth_value, with_planes, RasterParams, RasterVertex, SpanSink};
use crate::framebuffer::Rect;
use crate::pixel_rect::{PlacedBitmap, PlacedImage, RectPixels};
use softgl_jit::FragmentSpan;
use softgl_jit::Target;

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

/// Rasterizes the colour or depth rectangle `img` inside `params.bounds`:
/// each covered pixel's colour and depth from its source pixel.
pub fn image(img: &PlacedImage, params: &RasterParams, sink: &mut dyn SpanSink) {
    let Some(r) = img.rect(params.bounds) else { return };
    // No planes are read (no shading stage), but a span names some.
    with_planes(sink, |_| ());
    let mut span = FragmentSpan::new(0, 0);
    for y in r.y0..r.y1 {
        let mut x = r.x0;
        while x < r.x1 {
            let n = (r.x1 - x).min(softgl_jit::SPAN_MAX as u32);
            for i in 0..n as usize {
                let at = img.at(x + i as u32, y);
                let (c, z) = match &img.pixels {
                    RectPixels::Color { rgba, z } => (rgba[at], *z),
                    RectPixels::Depth { z, rgba } => (*rgba, z[at]),
                    RectPixels::Stencil { .. } => return,
                };
                (span.r[i], span.g[i], span.b[i], span.a[i], span.z[i]) = (c[0], c[1], c[2], c[3], z);
            }
            (span.x, span.y, span.len) = (x, y, n);
            span.mask = if n == 64 { u64::MAX } else { (1u64 << n) - 1 };
            sink.span(&span);
            x += n;
        }
    }
}

/// Writes the stencil rectangle `img` inside `bounds` (and its scissor box)
/// into `t`'s stencil buffer, through its write mask.
pub fn write_stencil(img: &PlacedImage, bounds: Rect, t: &mut Target<'_>) {
    let RectPixels::Stencil {
        s,
        write_mask,
        scissor,
        z,
    } = &img.pixels
    else {
        return;
    };
    let bounds = scissor.map_or(bounds, |sc| bounds.intersect(sc));
    let Some(r) = img.rect(bounds) else { return };
    for y in r.y0..r.y1 {
        if !t.rows().contains(&y) {
            continue;
        }
        for x in r.x0..r.x1 {
            let idx = t.index(x, y);
            let v = s[img.at(x, y)];
            if let Some(buf) = t.stencil_mut() {
                if let Some(d) = buf.get_mut(idx) {
                    *d = (v & write_mask) | (*d & !write_mask);
                }
            }
            if let (Some(z), Some(depth)) = (z, t.depth_mut()) {
                let v = z[img.at(x, y)];
                match depth {
                    softgl_jit::DepthTarget::D16(b) => b.get_mut(idx).map(|d| *d = v as u16),
                    softgl_jit::DepthTarget::D24(b)
                    | softgl_jit::DepthTarget::D32(b)
                    | softgl_jit::DepthTarget::D32F(b) => b.get_mut(idx).map(|d| *d = v),
                };
            }
        }
    }
}
