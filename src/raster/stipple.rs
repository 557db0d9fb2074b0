//! Line and polygon stipple, as llvmpipe draws them (`docs/llvmpipe-facts.md`
//! §30). Each is a wrapper put around a sink only while its enable is on,
//! so that a stage that is off costs nothing:
//!
//! - [`LineStipple`] wraps the draw's [`PrimSink`] and cuts each line into the
//!   dashes its pattern keeps, as draw's `draw_pipe_stipple.c` does: each dash
//!   is a line of its own (the diamond-exit rule and width apply to it), its
//!   ends and attributes interpolated linearly in window space.
//! - [`PolygonStipple`] wraps a tile's [`SpanSink`] for a draw's triangles and
//!   masks their spans with the pattern's row at window `(x mod 32, y mod 32)`
//!   (llvmpipe kills those fragments in the shader: `draw_pipe_pstipple.c`,
//!   the pattern flipped for a y-down framebuffer by `st_atom_stipple.c`, so
//!   it is anchored at GL's window origin).

use super::{row_spans, PrimSink, RasterParams, RasterVertex, SpanSink};
use crate::geometry::varying::Varyings;
use crate::texture::PixelStore;
use softgl_jit::{FragmentSpan, Planes};

/// Where bit `(x, y)` of a 32×32 bitmap under `store` is: its byte offset
/// and mask (GL 1.5 §3.6.4 for `GL_BITMAP`; Mesa's `_mesa_image_address`,
/// `_mesa_image_row_stride`). `None` when the layout overflows.
fn bit_at(store: &PixelStore, x: usize, y: usize) -> Option<(usize, u8)> {
    let row_bits = if store.row_length > 0 {
        store.row_length as usize
    } else {
        32
    };
    let align = store.alignment.max(1) as usize;
    let stride = row_bits.div_ceil(8).checked_next_multiple_of(align)?;
    let bit = (store.skip_pixels.max(0) as usize).checked_add(x)?;
    let row = (store.skip_rows.max(0) as usize).checked_add(y)?;
    let byte = row.checked_mul(stride)?.checked_add(bit / 8)?;
    let mask = if store.lsb_first {
        1 << (bit % 8)
    } else {
        0x80 >> (bit % 8)
    };
    Some((byte, mask))
}

/// The bytes a 32×32 bitmap takes under `store` (from the start of client
/// memory to its last byte); `None` when it overflows.
pub fn bitmap_len(store: &PixelStore) -> Option<usize> {
    bit_at(store, 31, 31).map(|(byte, _)| byte + 1)
}

/// A polygon stipple read from client memory as a 32×32 bitmap under the
/// unpack state `store` (Mesa's `_mesa_unpack_polygon_stipple`): row `i`
/// with column 0 in bit 31. `None` when `bytes` is shorter than the layout.
pub fn unpack(bytes: &[u8], store: &PixelStore) -> Option<[u32; 32]> {
    if bytes.len() < bitmap_len(store)? {
        return None;
    }
    let mut rows = [0u32; 32];
    for (y, row) in rows.iter_mut().enumerate() {
        for x in 0..32 {
            let (byte, mask) = bit_at(store, x, y)?;
            if bytes.get(byte)? & mask != 0 {
                *row |= 1 << (31 - x);
            }
        }
    }
    Some(rows)
}

/// Writes `rows` into client memory as a 32×32 bitmap under the pack state
/// `store`. The bytes a row touches are written whole: the skipped bits of
/// its first byte and the bits after its last are 0, as Mesa's
/// `_mesa_pack_bitmap` leaves them. `None` (nothing written) when `out` is
/// shorter than the layout.
pub fn pack(rows: &[u32; 32], out: &mut [u8], store: &PixelStore) -> Option<()> {
    if out.len() < bitmap_len(store)? {
        return None;
    }
    for (y, row) in rows.iter().enumerate() {
        let (first, _) = bit_at(store, 0, y)?;
        let (last, _) = bit_at(store, 31, y)?;
        out.get_mut(first..=last)?.fill(0);
        for x in 0..32 {
            let (byte, mask) = bit_at(store, x, y)?;
            if row & (1 << (31 - x)) != 0 {
                *out.get_mut(byte)? |= mask;
            }
        }
    }
    Some(())
}

/// Cuts lines into the dashes of `glLineStipple`'s pattern before `inner`.
/// The counter runs on along a strip or a loop (one wrapper a draw) and
/// starts again at each independent line (`reset_each`: `GL_LINES`), at
/// each polygon drawn as lines, and after a point or a triangle, as draw's
/// stipple stage resets it (`DRAW_PIPE_RESET_STIPPLE`, `stipple_reset_tri`).
pub struct LineStipple<'a> {
    pub inner: &'a mut dyn PrimSink,
    pub pattern: u16,
    /// 1 to 256.
    pub factor: u32,
    pub reset_each: bool,
    pub counter: u32,
}

impl<'a> LineStipple<'a> {
    pub fn new(inner: &'a mut dyn PrimSink, factor: i32, pattern: u16, reset_each: bool) -> Self {
        LineStipple {
            inner,
            pattern,
            factor: factor.clamp(1, 256) as u32,
            reset_each,
            counter: 0,
        }
    }

    /// Whether the pattern keeps the `i`-th pixel of the counter.
    fn keeps(&self, i: u32) -> bool {
        (self.pattern >> ((i / self.factor) & 0xF)) & 1 != 0
    }
}

/// The vertex at `t` of `a → b`, every attribute linear in window space
/// (draw's `screen_interp`: its position holds x, y, z and 1/w).
/// llvmpipe interpolates in its y-down frame: y (up) is `height - y_down`.
fn lerp(a: &RasterVertex, b: &RasterVertex, t: f32, n: usize, height: u32) -> RasterVertex {
    let l = |p: f32, q: f32| p + t * (q - p);
    let mut v = a.v;
    for (k, out) in v[..n].iter_mut().enumerate() {
        *out = l(a.v[k], b.v[k]);
    }
    let y_down = l(a.y_down, b.y_down);
    RasterVertex {
        x: l(a.x, b.x),
        y: height as f32 - y_down,
        y_down,
        z: a.z + f64::from(t) * (b.z - a.z),
        inv_w: l(a.inv_w, b.inv_w),
        v,
    }
}

impl PrimSink for LineStipple<'_> {
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) {
        self.counter = 0;
        self.inner.triangle(v, flat, params)
    }

    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams) {
        self.counter = 0;
        self.inner.point(v, size, params)
    }

    fn reset_stipple(&mut self) {
        self.counter = 0;
    }

    /// `stipple_line` of `draw_pipe_stipple.c`: the line's length is its
    /// longer axis (non-smooth lines), counted in `ceil(length)` pixels.
    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams) {
        if self.reset_each {
            self.counter = 0;
        }
        let length = (b.x - a.x).abs().max((b.y_down - a.y_down).abs());
        let pixels = if length.is_finite() { length.ceil() as u32 } else { 0 };
        let n = params.layout.len();
        let emit = |sink: &mut dyn PrimSink, t0: f32, t1: f32| {
            let p = if t0 > 0.0 { lerp(a, b, t0, n, params.height) } else { *a };
            let q = if t1 < 1.0 { lerp(a, b, t1, n, params.height) } else { *b };
            sink.line(&p, &q, width, flat, params);
        };
        let (mut start, mut on) = (0.0f32, false);
        for i in 0..pixels {
            let keep = self.keeps(self.counter.wrapping_add(i));
            if keep != on {
                if on {
                    emit(self.inner, start / length, i as f32 / length);
                } else {
                    start = i as f32;
                }
                on = keep;
            }
        }
        if on && start < length {
            emit(self.inner, start / length, 1.0);
        }
        self.counter = self.counter.wrapping_add(pixels);
    }
}

/// Masks the spans of a draw's triangles with a polygon stipple before `inner`.
pub struct PolygonStipple<'a, S: SpanSink> {
    pub inner: &'a mut S,
    pub rows: &'a [u32; 32],
    /// A span for rows, whose colours and depths stay zero.
    pub scratch: &'a mut FragmentSpan,
}

/// The stipple's mask of the 64 pixels from `x` in row `row` of the pattern
/// (column 0 in bit 31): bit `i` for pixel `x + i`.
#[inline]
pub fn row_mask(row: u32, x: u32) -> u64 {
    let r = u64::from(row.reverse_bits());
    (r | r << 32).rotate_right(x % 32)
}

impl<S: SpanSink> SpanSink for PolygonStipple<'_, S> {
    fn span(&mut self, span: &FragmentSpan) {
        let keep = row_mask(self.rows[(span.y % 32) as usize], span.x);
        if span.mask & keep == span.mask {
            return self.inner.span(span);
        }
        if span.mask & keep == 0 {
            return;
        }
        let mut s = span.clone();
        s.mask &= keep;
        self.inner.span(&s)
    }

    fn row(&mut self, y: u32, x0: u32, x1: u32) {
        let row = self.rows[(y % 32) as usize];
        for (x, len, mask) in row_spans(x0, x1) {
            let s = &mut *self.scratch;
            (s.x, s.y, s.len, s.mask) = (x, y, len, mask & row_mask(row, x));
            if s.mask != 0 {
                self.inner.span(s);
            }
        }
    }

    fn planes_mut(&mut self) -> Option<&mut Planes> {
        self.inner.planes_mut()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn row_masks_repeat_every_32_pixels_from_the_window_origin() {
        // Columns 0 and 33 mod 32 = 1 set.
        let row = (1 << 31) | (1 << 30);
        let m = row_mask(row, 0);
        assert_eq!(m, 0b11 | 0b11 << 32);
        // From x = 31: pixel 31 is off, 32 (column 0) and 33 (column 1) on.
        assert_eq!(row_mask(row, 31) & 0b111, 0b110);
        assert_eq!(row_mask(row, 64), m);
    }

    /// Records the lines it is handed: their x ranges.
    #[derive(Default)]
    struct Dashes(Vec<(f32, f32)>);

    impl PrimSink for Dashes {
        fn triangle(&mut self, _: [&RasterVertex; 3], _: Option<&Varyings>, _: &RasterParams) {}
        fn point(&mut self, _: &RasterVertex, _: f32, _: &RasterParams) {}
        fn line(&mut self, a: &RasterVertex, b: &RasterVertex, _: f32, _: Option<&Varyings>, _: &RasterParams) {
            self.0.push((a.x, b.x));
        }
    }

    fn at(x: f32, y: f32) -> RasterVertex {
        RasterVertex {
            x,
            y,
            y_down: 64.0 - y,
            z: 0.5,
            inv_w: 1.0,
            v: [0.0; crate::geometry::varying::MAX_VARYINGS],
        }
    }

    fn params() -> RasterParams {
        RasterParams {
            bounds: crate::framebuffer::Rect {
                x0: 0,
                y0: 0,
                x1: 64,
                y1: 64,
            },
            depth: None,
            height: 64,
            layout: Default::default(),
            offset: None,
        }
    }

    #[test]
    fn dashes_follow_the_counter_along_a_strip_and_restart_at_separate_lines() {
        let mut out = Dashes::default();
        // Factor 2, pattern 0x00FF: 16 pixels on, 16 off.
        let mut s = LineStipple::new(&mut out, 2, 0x00FF, false);
        let p = params();
        // 20 pixels: on 0..16, off 16..20; then 20 more: off 20..32, on 32..40.
        s.line(&at(0.5, 3.5), &at(20.5, 3.5), 1.0, None, &p);
        s.line(&at(20.5, 3.5), &at(40.5, 3.5), 1.0, None, &p);
        assert_eq!(s.counter, 40);
        // Separate lines: each starts at the pattern's first bit.
        s.reset_each = true;
        s.line(&at(0.5, 9.5), &at(20.5, 9.5), 1.0, None, &p);
        // A NaN line counts nothing and draws nothing.
        s.line(&at(f32::NAN, 9.5), &at(20.5, 9.5), 1.0, None, &p);
        assert_eq!(out.0, [(0.5, 16.5), (32.5, 40.5), (0.5, 16.5)]);
        // Factors clamp to [1, 256].
        let mut sink = Dashes::default();
        assert_eq!(LineStipple::new(&mut sink, 0, 1, false).factor, 1);
        assert_eq!(LineStipple::new(&mut sink, 1000, 1, false).factor, 256);
    }

    #[test]
    fn unpack_and_pack_follow_the_pixel_store() {
        let mut bytes = [0u8; 4 * 32];
        bytes[0] = 0x80; // (0, 0)
        bytes[4 * 31 + 3] = 0x01; // (31, 31)
        let rows = unpack(&bytes, &PixelStore::DEFAULT).unwrap();
        assert_eq!((rows[0], rows[31]), (1 << 31, 1));
        let lsb = PixelStore {
            lsb_first: true,
            ..PixelStore::DEFAULT
        };
        let rows = unpack(&bytes, &lsb).unwrap();
        assert_eq!((rows[0], rows[31]), (1 << 24, 1 << 7));
        // Skips and a row length: bit (3 + x) of row (2 + y), rows of 6 bytes (alignment 2).
        let store = PixelStore {
            skip_pixels: 3,
            skip_rows: 2,
            row_length: 41,
            alignment: 2,
            ..PixelStore::DEFAULT
        };
        assert_eq!(bitmap_len(&store), Some(33 * 6 + 5));
        let mut out = vec![0u8; 33 * 6 + 5];
        let pattern: [u32; 32] = std::array::from_fn(|i| 0x9E37_79B9u32.rotate_left(i as u32));
        pack(&pattern, &mut out, &store).unwrap();
        assert_eq!(out[2 * 6] & 0x1F, (pattern[0] >> 27) as u8);
        assert_eq!(unpack(&out, &store), Some(pattern));
        assert_eq!(unpack(&out[..out.len() - 1], &store), None);
        assert_eq!(pack(&pattern, &mut out[..10], &store), None);
    }
}
