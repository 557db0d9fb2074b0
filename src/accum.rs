//! The accumulation buffer: `glAccum`, `glClearAccum`, and its clear.
//!
//! As Mesa 22.3.6's OSMesa keeps it (`docs/llvmpipe-facts.md`, "The
//! accumulation buffer"): RGBA16 snorm, 16 bits a channel, allocated only
//! when a context asks for accumulation bits. Each operation is Mesa's `src/mesa/main/accum.c`, step
//! for step and in its precision (f32 products truncated to shorts that wrap,
//! as C's conversions do on x86-64), over the framebuffer's bounds cut by the
//! scissor box. `GL_RETURN` writes the colour buffer through the colour mask
//! only: no other per-fragment operation (llvmpipe does not dither).

use crate::error::{GlError, GlResult};
use crate::framebuffer::{Framebuffer, Rect};
use softgl_jit::{deep, pixel, ColorFormat, ColorMask};

/// Bits per channel of the accumulation buffer (`GL_ACCUM_RED_BITS`, …).
pub const ACCUM_BITS: u32 = 16;

/// A `glAccum` operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AccumOp {
    /// `GL_ACCUM`: adds the colour buffer times `value`.
    Accum,
    /// `GL_LOAD`: replaces with the colour buffer times `value`.
    Load,
    /// `GL_RETURN`: writes the accumulation buffer times `value` to the colour buffer.
    Return,
    /// `GL_MULT`: multiplies by `value`.
    Mult,
    /// `GL_ADD`: adds `value`.
    Add,
}

impl AccumOp {
    /// The operation named by a GL enum, or `InvalidEnum`.
    pub fn from_gl(e: u32) -> GlResult<AccumOp> {
        Ok(match e {
            0x0100 => AccumOp::Accum,
            0x0101 => AccumOp::Load,
            0x0102 => AccumOp::Return,
            0x0103 => AccumOp::Mult,
            0x0104 => AccumOp::Add,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// The GL enum.
    pub fn to_gl(self) -> u32 {
        match self {
            AccumOp::Accum => 0x0100,
            AccumOp::Load => 0x0101,
            AccumOp::Return => 0x0102,
            AccumOp::Mult => 0x0103,
            AccumOp::Add => 0x0104,
        }
    }
}

/// C's `(GLshort) f` on x86-64: `cvttss2si` to 32 bits (truncation toward
/// zero; `0x80000000` for NaN and out of range), then the low 16 bits.
#[inline]
fn c_short(f: f32) -> i16 {
    if (-2_147_483_648.0..2_147_483_648.0).contains(&f) {
        (f as i32) as i16
    } else {
        0
    }
}

/// Mesa's `FLOAT_TO_SHORT`: `((GLint)(65535.0F * x) - 1) / 2`, for `x` in `[-1, 1]`.
#[inline]
fn float_to_short(x: f32) -> i16 {
    (((65535.0f32 * x) as i32 - 1) / 2) as i16
}

/// Mesa's unpack of a stored pixel to float RGBA (`util_format`'s
/// `unpack_rgba_float`: `v * (1.0f / max)`; alpha 1 where none is stored).
fn unpack_float(format: ColorFormat, bytes: &[u8]) -> [f32; 4] {
    if format.is_deep() {
        return deep::to_float(format, deep::load(format, bytes));
    }
    let v = pixel::load(format, bytes);
    let n = |c: u32, max: u32| c as f32 * (1.0 / max as f32);
    match format {
        ColorFormat::Rgb565 => [n((v >> 11) & 31, 31), n((v >> 5) & 63, 63), n(v & 31, 31), 1.0],
        _ => {
            let [r, g, b, a] = pixel::unpack(format, v);
            let a = if format.has_alpha() { n(a.into(), 255) } else { 1.0 };
            [n(r.into(), 255), n(g.into(), 255), n(b.into(), 255), a]
        }
    }
}

/// Mesa's `float_to_ubyte` (`src/util/u_math.h`): 0 for NaN and below 0,
/// 255 from 1 up, else the low byte of `f * (255/256) + 32768` in f32.
#[inline]
fn float_to_ubyte(f: f32) -> u8 {
    if f.is_nan() || f <= 0.0 {
        0
    } else if f >= 1.0 {
        255
    } else {
        (f * (255.0 / 256.0) + 32768.0).to_bits() as u8
    }
}

/// `util_format`'s pack of a float channel to a `max`-valued unorm other
/// than 8 bits: clamped to `[0, 1]`, then `util_iround` (`(int)(f + 0.5f)`
/// on x86-64); NaN goes through the clamp and truncates to `0x80000000`.
#[inline]
fn float_to_unorm_iround(f: f32, max: u32) -> u32 {
    // NaN stays NaN through `clamp`, as through C's `CLAMP`.
    let f = f.clamp(0.0, 1.0);
    c_int(f * max as f32 + 0.5) as u32
}

/// C's `(int) f` on x86-64 (`cvttss2si`).
#[inline]
fn c_int(f: f32) -> i32 {
    if (-2_147_483_648.0..2_147_483_648.0).contains(&f) {
        f as i32
    } else {
        i32::MIN
    }
}

/// Mesa's pack of float RGBA into the stored pixel at the start of `bytes`
/// (`_mesa_pack_float_rgba_row`: 16-bit unorm by `util_iround`, floats as they are).
fn pack_float(format: ColorFormat, rgba: [f32; 4], bytes: &mut [u8]) {
    let v = if format.is_float() {
        // Halves as their clears and fragments store them; alpha 1 where none is stored.
        deep::from_float(format, rgba)
    } else {
        let mut v = rgba.map(|c| float_to_unorm_iround(c, 65535));
        if !format.has_alpha() {
            v[3] = 65535;
        }
        v
    };
    if format.is_deep() {
        for (c, v) in v.into_iter().enumerate() {
            deep::store_channel(format, bytes, c, v);
        }
    } else {
        pixel::store(format, bytes, pack_packed(format, rgba));
    }
}

/// [`pack_float`] for the formats of one packed value.
fn pack_packed(format: ColorFormat, [r, g, b, a]: [f32; 4]) -> u32 {
    match format {
        ColorFormat::Rgb565 => {
            (float_to_unorm_iround(r, 31) & 31) << 11
                | (float_to_unorm_iround(g, 63) & 63) << 5
                | (float_to_unorm_iround(b, 31) & 31)
        }
        _ => pixel::pack(format, [r, g, b, a].map(float_to_ubyte), None),
    }
}

/// The accumulation buffer's values, one RGBA16 snorm value a pixel, rows bottom-up.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AccumBuffer {
    width: u32,
    values: Vec<[i16; 4]>,
}

impl AccumBuffer {
    /// A zeroed buffer of `width` × `height`; `OutOfMemory` instead of an abort.
    pub(crate) fn new(width: u32, height: u32) -> GlResult<AccumBuffer> {
        let n = width as usize * height as usize;
        let mut values = Vec::new();
        values.try_reserve_exact(n).map_err(|_| GlError::OutOfMemory)?;
        values.resize(n, [0; 4]);
        Ok(AccumBuffer { width, values })
    }

    /// A stand-in of the same size holding no values (see `Framebuffer::hollow`).
    pub(crate) fn hollow(&self) -> AccumBuffer {
        AccumBuffer {
            width: self.width,
            values: Vec::new(),
        }
    }

    /// The value at `(x, y)`, if inside.
    pub fn get(&self, x: u32, y: u32) -> Option<[i16; 4]> {
        if x >= self.width {
            return None;
        }
        self.values.get(y as usize * self.width as usize + x as usize).copied()
    }

    /// Every value, rows bottom-up.
    pub fn values(&self) -> &[[i16; 4]] {
        &self.values
    }

    /// The values of row `y` from `x0` to `x1`.
    fn row_mut(&mut self, y: u32, x0: u32, x1: u32) -> &mut [[i16; 4]] {
        let start = y as usize * self.width as usize;
        &mut self.values[start + x0 as usize..start + x1 as usize]
    }

    /// `glClear(GL_ACCUM_BUFFER_BIT)` inside `rect` to `color` (in `[-1, 1]`).
    pub(crate) fn clear(&mut self, rect: Rect, color: [f32; 4]) {
        let v = color.map(float_to_short);
        for y in rect.y0..rect.y1 {
            self.row_mut(y, rect.x0, rect.x1).fill(v);
        }
    }

    /// `GL_ADD` (`bias`) or `GL_MULT` inside `rect`.
    fn scale_or_bias(&mut self, rect: Rect, value: f32, bias: bool) {
        let incr = c_short(value * 32767.0);
        for y in rect.y0..rect.y1 {
            for px in self.row_mut(y, rect.x0, rect.x1) {
                for c in px {
                    *c = if bias {
                        c.wrapping_add(incr)
                    } else {
                        c_short(f32::from(*c) * value)
                    };
                }
            }
        }
    }
}

/// Runs `op` with `value` over `rect` of `fb`'s colour and accumulation
/// buffers (which `fb` must have), as Mesa's `accum()` does; `mask` is the
/// colour mask `GL_RETURN` writes through.
pub(crate) fn apply(fb: &mut Framebuffer, op: AccumOp, value: f32, rect: Rect, mask: ColorMask) {
    if rect.is_empty() {
        return;
    }
    let format = fb.color_format();
    let bpp = format.bytes_per_pixel();
    match op {
        AccumOp::Add if value != 0.0 => fb
            .accum_mut_or_none()
            .map_or((), |a| a.scale_or_bias(rect, value, true)),
        AccumOp::Mult if value != 1.0 => fb
            .accum_mut_or_none()
            .map_or((), |a| a.scale_or_bias(rect, value, false)),
        AccumOp::Add | AccumOp::Mult => {}
        AccumOp::Accum if value == 0.0 => {}
        AccumOp::Accum | AccumOp::Load => {
            let scale = value * 32767.0;
            let load = op == AccumOp::Load;
            let (color, accum) = fb.color_and_accum_mut();
            let Some(accum) = accum else { return };
            for y in rect.y0..rect.y1 {
                let src = &color.bytes[color.offset(rect.x0, y)..];
                let row = accum.row_mut(y, rect.x0, rect.x1);
                for (px, bytes) in row.iter_mut().zip(src.chunks(bpp)) {
                    let rgba = unpack_float(format, bytes);
                    for (acc, c) in px.iter_mut().zip(rgba) {
                        let v = c_short(c * scale);
                        *acc = if load { v } else { acc.wrapping_add(v) };
                    }
                }
            }
        }
        AccumOp::Return => {
            let scale = value / 32767.0;
            let masking = !(mask.r && mask.g && mask.b && mask.a);
            let keep = [!mask.r, !mask.g, !mask.b, !mask.a];
            let (color, accum) = fb.color_and_accum_mut();
            let Some(accum) = accum else { return };
            for y in rect.y0..rect.y1 {
                let start = color.offset(rect.x0, y);
                let dst = &mut color.bytes[start..];
                let row = accum.row_mut(y, rect.x0, rect.x1);
                for (px, bytes) in row.iter().zip(dst.chunks_mut(bpp)) {
                    let mut rgba = px.map(|c| f32::from(c) * scale);
                    if masking {
                        let old = unpack_float(format, bytes);
                        for c in 0..4 {
                            if keep[c] {
                                rgba[c] = old[c];
                            }
                        }
                    }
                    pack_float(format, rgba, bytes);
                }
            }
        }
    }
}

/// The colour bytes of a framebuffer with their layout, lent to [`apply`].
pub(crate) struct ColorRows<'a> {
    pub bytes: &'a mut [u8],
    pub stride: usize,
    pub top_down: bool,
    pub height: u32,
    pub bpp: usize,
}

impl ColorRows<'_> {
    /// Byte offset of pixel `(x, y)`.
    fn offset(&self, x: u32, y: u32) -> usize {
        let row = if self.top_down { self.height - 1 - y } else { y };
        row as usize * self.stride + x as usize * self.bpp
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_are_mesas() {
        assert_eq!(float_to_short(0.0), 0);
        assert_eq!(float_to_short(1.0), 32767);
        assert_eq!(float_to_short(-1.0), -32768);
        assert_eq!(float_to_short(0.5), 16383);
        assert_eq!(float_to_short(-0.5), -16384);
        assert_eq!(c_short(40000.0), 40000u16 as i16);
        assert_eq!(c_short(-1.9), -1);
        assert_eq!(c_short(f32::NAN), 0);
        assert_eq!(c_short(3e9), 0);
        for v in 0..=255u8 {
            assert_eq!(float_to_ubyte(f32::from(v) * (1.0 / 255.0)), v);
        }
        assert_eq!(float_to_ubyte(0.5), 128);
        assert_eq!(float_to_unorm_iround(0.5, 31), 16);
    }
}
