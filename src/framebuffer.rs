//! The framebuffer: color, and only the depth and stencil buffers asked for.
//! Rows are stored bottom-up (row 0 is window y 0), as GL addresses them.

use crate::accum::{AccumBuffer, ColorRows};
use crate::error::{GlError, GlResult};
use softgl_jit::{deep, pixel, ColorFormat, ColorMask, DepthFormat, DepthTarget, Target};

/// Largest framebuffer side, in pixels (Mesa's `GL_MAX_VIEWPORT_DIMS`).
pub const MAX_FRAMEBUFFER_SIZE: u32 = 16384;

/// What a context's framebuffer holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FramebufferDesc {
    pub width: u32,
    pub height: u32,
    pub color: ColorFormat,
    /// 0 (no depth buffer), 16, 24 or 32 (unsigned normalized), or
    /// [`FramebufferDesc::FLOAT_DEPTH`] (32-bit float, `GL_DEPTH_COMPONENT32F`).
    pub depth_bits: u32,
    /// 0 (no stencil buffer) or 8.
    pub stencil_bits: u32,
}

impl FramebufferDesc {
    /// The `depth_bits` that asks for a 32-bit float depth buffer
    /// ([`DepthFormat::D32F`]): `GL_DEPTH_COMPONENT32F`'s enum value.
    pub const FLOAT_DEPTH: u32 = 0x8CAC;

    /// The `depth_bits` that asks for `format`.
    pub fn depth_bits_of(format: Option<DepthFormat>) -> u32 {
        match format {
            None => 0,
            Some(DepthFormat::D32F) => FramebufferDesc::FLOAT_DEPTH,
            Some(f) => f.bits(),
        }
    }

    /// RGBA8 color with a 24-bit depth and an 8-bit stencil buffer.
    pub fn rgba8_d24s8(width: u32, height: u32) -> FramebufferDesc {
        FramebufferDesc {
            width,
            height,
            color: ColorFormat::Rgba8,
            depth_bits: 24,
            stencil_bits: 8,
        }
    }

    /// The depth format `depth_bits` asks for; `InvalidValue` for an unsupported size.
    pub fn depth_format(&self) -> GlResult<Option<DepthFormat>> {
        match self.depth_bits {
            0 => Ok(None),
            16 => Ok(Some(DepthFormat::D16)),
            24 => Ok(Some(DepthFormat::D24)),
            32 => Ok(Some(DepthFormat::D32)),
            FramebufferDesc::FLOAT_DEPTH => Ok(Some(DepthFormat::D32F)),
            _ => Err(GlError::InvalidValue),
        }
    }

    fn validate(&self) -> GlResult {
        let side_ok = |s: u32| (1..=MAX_FRAMEBUFFER_SIZE).contains(&s);
        if !side_ok(self.width) || !side_ok(self.height) || !matches!(self.stencil_bits, 0 | 8) {
            return Err(GlError::InvalidValue);
        }
        self.depth_format().map(|_| ())
    }
}

/// Depth storage, one value per pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DepthBuffer {
    D16(Vec<u16>),
    D24(Vec<u32>),
    D32(Vec<u32>),
    /// `f32` bits (see [`DepthFormat::D32F`]).
    D32F(Vec<u32>),
}

impl DepthBuffer {
    pub fn format(&self) -> DepthFormat {
        match self {
            DepthBuffer::D16(_) => DepthFormat::D16,
            DepthBuffer::D24(_) => DepthFormat::D24,
            DepthBuffer::D32(_) => DepthFormat::D32,
            DepthBuffer::D32F(_) => DepthFormat::D32F,
        }
    }

    fn get(&self, i: usize) -> u32 {
        match self {
            DepthBuffer::D16(d) => u32::from(d[i]),
            DepthBuffer::D24(d) | DepthBuffer::D32(d) | DepthBuffer::D32F(d) => d[i],
        }
    }
}

/// A pixel rectangle, clipped to the framebuffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

impl Rect {
    pub fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    /// The pixels in both (empty when they do not meet).
    pub fn intersect(self, other: Rect) -> Rect {
        Rect {
            x0: self.x0.max(other.x0),
            y0: self.y0.max(other.y0),
            x1: self.x1.min(other.x1),
            y1: self.y1.min(other.y1),
        }
    }
}

/// A `glClear` resolved against a framebuffer: what each buffer is set to,
/// and through which mask, inside `rect`. Applied to any band of the
/// framebuffer's rows ([`Clear::apply`]), so that a deferred clear runs as part
/// of each tile's work.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Clear {
    pub rect: Rect,
    /// The packed colour, the bits of it the colour mask writes, and its bytes.
    color: Option<(u32, u32, [u8; 4])>,
    /// For the deep formats instead: the pixel's bytes and the channels written.
    deep: Option<([u8; 16], [bool; 4])>,
    depth: Option<u32>,
    /// Value and write mask.
    stencil: Option<(u8, u8)>,
}

impl Clear {
    /// Clears nothing yet, inside `rect` of `fb`.
    pub fn new(rect: Rect) -> Clear {
        Clear {
            rect,
            color: None,
            deep: None,
            depth: None,
            stencil: None,
        }
    }

    /// Also clears the color buffer to `rgba` through `mask`.
    pub fn color(mut self, fb: &Framebuffer, rgba: [f32; 4], mask: ColorMask) -> Clear {
        let format = fb.desc.color;
        if format.is_deep() {
            let keep = [mask.r, mask.g, mask.b, mask.a];
            if keep.contains(&true) {
                // A whole-buffer unmasked clear is llvmpipe's `pipe->clear`,
                // packed by `util_format_pack_rgba` (`util_iround(c * 65535)`,
                // half up in f32); a scissored or masked one draws a quad,
                // whose colour converts as a fragment's (`deep::unorm16`).
                let whole = self.rect == fb.bounds() && !keep.contains(&false);
                let mut values = deep::from_float(format, rgba);
                if format.is_float() {
                    // As given (`glClearColor` is not clamped): NaNs too, as
                    // llvmpipe's `util_pack_color` stores them.
                    for (v, c) in values.iter_mut().zip(rgba).take(if format.has_alpha() { 4 } else { 3 }) {
                        if c.is_nan() {
                            let bits = c.to_bits();
                            // A half keeps the sign and the top 10 payload bits, made quiet.
                            *v = if format.is_half() {
                                (bits & 0xffff_e000) | 0x0040_0000
                            } else {
                                bits
                            };
                        }
                    }
                }
                if whole && !format.is_float() {
                    // Alpha stays 1 where none is stored (`from_float`'s).
                    let packed = rgba.map(|c| (c.clamp(0.0, 1.0) * 65535.0 + 0.5) as u32);
                    values[..3].copy_from_slice(&packed[..3]);
                    if format.has_alpha() {
                        values[3] = packed[3];
                    }
                }
                let mut bytes = [0u8; 16];
                for (c, v) in values.into_iter().enumerate() {
                    deep::store_channel(format, &mut bytes, c, v);
                }
                self.deep = Some((bytes, keep));
            }
            return self;
        }
        let bits = pixel::mask_bits(format, mask);
        if bits == 0 || !fb.color_enabled {
            return self;
        }
        let rgb_written = mask.r && mask.g && mask.b;
        let value = if format == ColorFormat::Rgb565 && self.rect == fb.bounds() && rgb_written {
            // A whole-buffer clear is llvmpipe's `pipe->clear`, packed by
            // `util_format_pack_rgba`: `util_iround(c * max)`, half up in f32.
            // A scissored or masked clear draws a quad, whose colour goes the
            // fragments' way: unorm8, then truncated (docs/llvmpipe-facts.md §13).
            let q = |v: f32, max: f32| (v.clamp(0.0, 1.0) * max + 0.5) as u32;
            (q(rgba[0], 31.0) << 11) | (q(rgba[1], 63.0) << 5) | q(rgba[2], 31.0)
        } else {
            pixel::pack(format, rgba.map(|v| float_to_unorm(v, 255) as u8), None)
        };
        let mut bytes = [0u8; 4];
        pixel::store(format, &mut bytes, value);
        self.color = Some((value, bits, bytes));
        self
    }

    /// Also clears the depth buffer, if any, to window depth `depth`.
    pub fn depth(mut self, fb: &Framebuffer, depth: f64) -> Clear {
        self.depth = fb.depth_format().map(|f| depth_to_unorm(depth, f));
        self
    }

    /// Also clears the stencil buffer, if any, to `value` through `write_mask`.
    pub fn stencil(mut self, fb: &Framebuffer, value: u8, write_mask: u8) -> Clear {
        self.stencil = fb.has_stencil().then_some((value, write_mask));
        self
    }

    /// Whether it clears anything.
    pub fn is_empty(&self) -> bool {
        self.rect.is_empty()
            || (self.color.is_none() && self.deep.is_none() && self.depth.is_none() && self.stencil.is_none())
    }

    /// Clears the part of `rect` inside `within` and the rows `t` holds.
    pub fn apply(&self, t: &mut Target<'_>, within: Rect) {
        let rows = t.rows();
        let r = self.rect.intersect(within).intersect(Rect {
            x0: 0,
            y0: rows.start,
            x1: t.width(),
            y1: rows.end,
        });
        if r.is_empty() {
            return;
        }
        let (x0, x1) = (r.x0 as usize, r.x1 as usize);
        if let Some((value, bits, bytes)) = self.color {
            let format = t.color_format();
            let bpp = format.bytes_per_pixel();
            let all = bits == pixel::mask_bits(format, ColorMask::ALL);
            for y in r.y0..r.y1 {
                let start = t.color_offset(r.x0, y);
                let row = &mut t.color_mut()[start..][..(x1 - x0) * bpp];
                match (all, bpp) {
                    (true, 4) => fill_row::<4>(row, &bytes),
                    (true, 3) => fill_row::<3>(row, &bytes),
                    (true, _) => fill_row::<2>(row, &bytes),
                    (false, 4) => mask_row::<4>(row, value, bits),
                    (false, 3) => mask_row::<3>(row, value, bits),
                    (false, _) => mask_row::<2>(row, value, bits),
                }
            }
        }
        if let Some(deep) = &self.deep {
            clear_deep(t, r, deep);
        }
        if let Some(v) = self.depth {
            for y in r.y0..r.y1 {
                let i = t.index(r.x0, y);
                match t.depth_mut() {
                    Some(DepthTarget::D16(d)) => d[i..i + x1 - x0].fill(v as u16),
                    Some(DepthTarget::D24(d) | DepthTarget::D32(d) | DepthTarget::D32F(d)) => d[i..i + x1 - x0].fill(v),
                    None => {}
                }
            }
        }
        if let Some((value, mask)) = self.stencil {
            for y in r.y0..r.y1 {
                let i = t.index(r.x0, y);
                if let Some(s) = t.stencil_mut() {
                    let row = &mut s[i..i + x1 - x0];
                    if mask == 0xff {
                        row.fill(value);
                    } else {
                        for s in row {
                            *s = (value & mask) | (*s & !mask);
                        }
                    }
                }
            }
        }
    }
}

/// Clears `r` of a deep-format target to the pixel `bytes` through the
/// channels `keep`: a function apart, so that [`Clear::apply`]'s loops for
/// the byte formats stay as they were.
#[inline(never)]
fn clear_deep(t: &mut Target<'_>, r: Rect, (bytes, keep): &([u8; 16], [bool; 4])) {
    let format = t.color_format();
    let bpp = format.bytes_per_pixel();
    let size = bpp / 4;
    let n = (r.x1 - r.x0) as usize;
    for y in r.y0..r.y1 {
        let start = t.color_offset(r.x0, y);
        let row = &mut t.color_mut()[start..][..n * bpp];
        for px in row.chunks_exact_mut(bpp) {
            for c in (0..4).filter(|&c| keep[c]) {
                px[c * size..][..size].copy_from_slice(&bytes[c * size..][..size]);
            }
        }
    }
}

/// Formats `read_pixels` can return.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ReadFormat {
    Rgba8,
    Rgb8,
    Bgra8,
}

impl ReadFormat {
    fn bytes_per_pixel(self) -> usize {
        match self {
            ReadFormat::Rgba8 | ReadFormat::Bgra8 => 4,
            ReadFormat::Rgb8 => 3,
        }
    }
}

/// Rounds a non-negative finite f32 to the nearest integer, ties to even,
/// without a libm call: adding 2^23 leaves no fraction bits, and the FPU's
/// default rounding is to nearest even. Values from 2^23 up are integers already.
#[inline]
pub fn rint_nonnegative(v: f32) -> f32 {
    const TWO_23: f32 = 8_388_608.0;
    if v < TWO_23 {
        (v + TWO_23) - TWO_23
    } else {
        v
    }
}

/// Writes the first `N` bytes of `bytes` to each `N`-byte pixel of `row`:
/// [`PATTERN`] bytes at a time (whole vector stores), where a copy per
/// pixel cost about 2 instructions a pixel (the full clears of `thrash`,
/// callgrind).
fn fill_row<const N: usize>(row: &mut [u8], bytes: &[u8; 4]) {
    let pattern: [u8; PATTERN] = std::array::from_fn(|i| bytes[i % N]);
    let mut chunks = row.chunks_exact_mut(PATTERN);
    for c in &mut chunks {
        c.copy_from_slice(&pattern);
    }
    let tail = chunks.into_remainder();
    tail.copy_from_slice(&pattern[..tail.len()]);
}

/// Writes the bits `bits` of the packed value `value` into each `N`-byte
/// pixel of `row`, keeping the others: byte by byte, which is the same as
/// pixel by pixel (`pixel::load`/`store` are little-endian, a byte's bits
/// are its own), on a pattern of [`PATTERN`] bytes (16 pixels of 3 bytes,
/// 12 of 4, 24 of 2) that the compiler runs on whole vector registers. A
/// colour-masked clear at 1024²: 35 M instructions in `pixel::load` alone
/// over two `ops` frames before (callgrind), the row loop now.
fn mask_row<const N: usize>(row: &mut [u8], value: u32, bits: u32) {
    let (v, m) = (value.to_le_bytes(), bits.to_le_bytes());
    let val: [u8; PATTERN] = std::array::from_fn(|i| v[i % N] & m[i % N]);
    let keep: [u8; PATTERN] = std::array::from_fn(|i| !m[i % N]);
    let mut chunks = row.chunks_exact_mut(PATTERN);
    for c in &mut chunks {
        for ((b, &v), &k) in c.iter_mut().zip(&val).zip(&keep) {
            *b = v | (*b & k);
        }
    }
    // The pattern starts on a pixel, so the tail's bytes line up with it too.
    for ((b, &v), &k) in chunks.into_remainder().iter_mut().zip(&val).zip(&keep) {
        *b = v | (*b & k);
    }
}

/// Bytes of [`mask_row`]'s and [`fill_row`]'s patterns: a whole number of
/// 2-, 3- and 4-byte pixels.
const PATTERN: usize = 48;

/// Converts a float in `[0, 1]` (clamped; NaN reads as 0) to a unorm value of
/// `max`, rounding half to even as llvmpipe does.
#[inline]
pub fn float_to_unorm(v: f32, max: u32) -> u32 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    if max < 1 << 24 {
        rint_nonnegative(v * max as f32) as u32
    } else {
        (v * max as f32).round_ties_even() as u32
    }
}

/// Converts a window depth in `[0, 1]` to depth-buffer units: computed in f32
/// for 16 and 24 bits, as llvmpipe does (`rint(float(z * 0xffffff))`), in f64
/// for 32 bits, where f32 cannot hold the range; a float format stores the
/// f32 clamped to `[0, 1]` (`DepthFormat::from_window`).
#[inline]
pub fn depth_to_unorm(z: f64, format: DepthFormat) -> u32 {
    let z = if z.is_nan() { 0.0 } else { z.clamp(0.0, 1.0) };
    match format {
        DepthFormat::D32F => format.from_window(z as f32),
        DepthFormat::D16 | DepthFormat::D24 => rint_nonnegative((z as f32) * format.max_value() as f32) as u32,
        DepthFormat::D32 => (z * f64::from(u32::MAX)).round_ties_even() as u32,
    }
}

/// Color memory lent to a framebuffer by its owner (the OSMesa C ABI hands
/// softgl the caller's buffer this way, so that it renders into it directly).
/// Both methods return the same bytes, of the same length, every time: the
/// framebuffer checks the length once, when the memory is lent.
pub trait ColorMemory: Send {
    fn bytes(&self) -> &[u8];
    fn bytes_mut(&mut self) -> &mut [u8];
}

/// Where the color buffer lives.
enum ColorStore {
    Owned(Vec<u8>),
    Lent(Box<dyn ColorMemory>),
}

impl ColorStore {
    fn bytes(&self) -> &[u8] {
        match self {
            ColorStore::Owned(v) => v,
            ColorStore::Lent(m) => m.bytes(),
        }
    }

    fn bytes_mut(&mut self) -> &mut [u8] {
        match self {
            ColorStore::Owned(v) => v,
            ColorStore::Lent(m) => m.bytes_mut(),
        }
    }
}

/// A clone owns a copy of the colour bytes, lent or not (a snapshot).
impl Clone for ColorStore {
    fn clone(&self) -> ColorStore {
        ColorStore::Owned(self.bytes().to_vec())
    }
}

impl std::fmt::Debug for ColorStore {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ColorStore::Owned(v) => write!(f, "Owned({} bytes)", v.len()),
            ColorStore::Lent(m) => write!(f, "Lent({} bytes)", m.bytes().len()),
        }
    }
}

/// Color, depth and stencil storage of a context. Depth and stencil rows are
/// always bottom-up and `width` values long; color rows are `color_stride`
/// bytes apart, top-down when `color_top_down`. A clone owns its colour bytes.
#[derive(Clone, Debug)]
pub struct Framebuffer {
    desc: FramebufferDesc,
    color: ColorStore,
    color_stride: usize,
    color_top_down: bool,
    depth: Option<DepthBuffer>,
    stencil: Option<Vec<u8>>,
    /// Whether draws and clears write the colour buffer: false for a
    /// framebuffer object whose draw buffer is `GL_NONE` or that has no
    /// colour attachment (its colour bytes are then a scratch buffer no one
    /// reads, `src/fbo.rs`).
    color_enabled: bool,
    /// Only when asked for ([`Framebuffer::with_accum_buffer`]).
    accum: Option<AccumBuffer>,
    /// Samples 1.. of a multisampled framebuffer, each a single-sampled
    /// framebuffer of the same size and formats; this one holds sample 0
    /// (`framebuffer/multisample.rs`). Empty when single-sampled.
    pub(crate) samples: Vec<Framebuffer>,
    /// Whether the sample pattern is mirrored in y, as in a window's
    /// multisampled buffer on llvmpipe (`multisample.rs`,
    /// [`Framebuffer::new_multisample_window`]).
    pub(crate) window_samples: bool,
}

impl Framebuffer {
    /// Allocates the buffers `desc` asks for, cleared to zero color, depth 1.0 and stencil 0.
    pub fn new(desc: FramebufferDesc) -> GlResult<Framebuffer> {
        desc.validate()?;
        let n = desc.width as usize * desc.height as usize;
        let color = alloc(n * desc.color.bytes_per_pixel(), 0u8)?;
        let stride = desc.width as usize * desc.color.bytes_per_pixel();
        Framebuffer::with_color(desc, ColorStore::Owned(color), stride, false)
    }

    /// A framebuffer whose color buffer is `memory`, laid out in rows of
    /// `stride` bytes (top row first when `top_down`); depth and stencil are
    /// allocated as [`Framebuffer::new`] does. The color memory is not cleared.
    /// `InvalidValue` when `memory` is too small for `desc`.
    pub fn with_color_memory(
        desc: FramebufferDesc,
        memory: Box<dyn ColorMemory>,
        stride: usize,
        top_down: bool,
    ) -> GlResult<Framebuffer> {
        desc.validate()?;
        check_color_memory(&desc, memory.bytes().len(), stride)?;
        Framebuffer::with_color(desc, ColorStore::Lent(memory), stride, top_down)
    }

    /// Allocates depth and stencil around a validated color store.
    fn with_color(desc: FramebufferDesc, color: ColorStore, stride: usize, top_down: bool) -> GlResult<Framebuffer> {
        let n = desc.width as usize * desc.height as usize;
        let depth = match desc.depth_format()? {
            None => None,
            Some(DepthFormat::D16) => Some(DepthBuffer::D16(alloc(n, u16::MAX)?)),
            Some(f @ DepthFormat::D24) => Some(DepthBuffer::D24(alloc(n, f.max_value())?)),
            Some(f @ DepthFormat::D32) => Some(DepthBuffer::D32(alloc(n, f.max_value())?)),
            Some(f @ DepthFormat::D32F) => Some(DepthBuffer::D32F(alloc(n, f.max_value())?)),
        };
        let stencil = if desc.stencil_bits == 8 {
            Some(alloc(n, 0u8)?)
        } else {
            None
        };
        Ok(Framebuffer {
            desc,
            color,
            color_stride: stride,
            color_top_down: top_down,
            depth,
            stencil,
            color_enabled: true,
            accum: None,
            samples: Vec::new(),
            window_samples: false,
        })
    }

    /// A framebuffer over buffers made elsewhere (a framebuffer object's
    /// attachments, `src/fbo.rs`): colour rows bottom-up and tightly packed.
    /// `InvalidValue` when a buffer's length does not fit `desc`.
    pub fn from_parts(
        desc: FramebufferDesc,
        color: Vec<u8>,
        depth: Option<DepthBuffer>,
        stencil: Option<Vec<u8>>,
    ) -> GlResult<Framebuffer> {
        desc.validate()?;
        let n = desc.width as usize * desc.height as usize;
        let depth_len = depth.as_ref().map(|d| match d {
            DepthBuffer::D16(v) => v.len(),
            DepthBuffer::D24(v) | DepthBuffer::D32(v) | DepthBuffer::D32F(v) => v.len(),
        });
        let ok = color.len() == n * desc.color.bytes_per_pixel()
            && depth.as_ref().map(DepthBuffer::format) == desc.depth_format()?
            && depth_len.is_none_or(|l| l == n)
            && stencil.as_ref().map(Vec::len) == (desc.stencil_bits == 8).then_some(n);
        if !ok {
            return Err(GlError::InvalidValue);
        }
        Ok(Framebuffer {
            desc,
            color_stride: desc.width as usize * desc.color.bytes_per_pixel(),
            color: ColorStore::Owned(color),
            color_top_down: false,
            depth,
            stencil,
            color_enabled: true,
            accum: None,
            samples: Vec::new(),
            window_samples: false,
        })
    }

    /// The buffers back (lent colour memory is copied), as [`Framebuffer::from_parts`] takes them.
    pub fn into_parts(self) -> (Vec<u8>, Option<DepthBuffer>, Option<Vec<u8>>) {
        let color = match self.color {
            ColorStore::Owned(v) => v,
            ColorStore::Lent(m) => m.bytes().to_vec(),
        };
        (color, self.depth, self.stencil)
    }

    /// Whether draws and clears write the colour buffer.
    pub fn color_enabled(&self) -> bool {
        self.color_enabled
    }

    /// Turns colour writes on or off (a framebuffer object's `GL_NONE` draw buffer).
    pub fn set_color_enabled(&mut self, on: bool) {
        self.color_enabled = on;
    }

    /// This framebuffer with an accumulation buffer (RGBA, 16 bits a
    /// channel, as Mesa's OSMesa gives for any accumulation bits asked for),
    /// cleared to zero. `OutOfMemory` when it cannot be allocated.
    pub fn with_accum_buffer(mut self) -> GlResult<Framebuffer> {
        if self.accum.is_none() {
            self.accum = Some(AccumBuffer::new(self.desc.width, self.desc.height)?);
        }
        Ok(self)
    }

    /// Whether it has an accumulation buffer.
    pub fn has_accum(&self) -> bool {
        self.accum.is_some()
    }

    /// The accumulation buffer, if any.
    pub fn accum_buffer(&self) -> Option<&AccumBuffer> {
        self.accum.as_ref()
    }

    pub(crate) fn accum_mut_or_none(&mut self) -> Option<&mut AccumBuffer> {
        self.accum.as_mut()
    }

    /// The colour rows and the accumulation buffer, both writable.
    pub(crate) fn color_and_accum_mut(&mut self) -> (ColorRows<'_>, Option<&mut AccumBuffer>) {
        let rows = ColorRows {
            bytes: self.color.bytes_mut(),
            stride: self.color_stride,
            top_down: self.color_top_down,
            height: self.desc.height,
            bpp: self.desc.color.bytes_per_pixel(),
        };
        (rows, self.accum.as_mut())
    }

    /// A framebuffer of the same size, layout and formats that holds no
    /// pixels: it stands in for this one while its buffers are with a flush
    /// on another thread (`raster/background.rs`), answering for the sizes
    /// and formats a draw is recorded with. Nothing reads or writes its
    /// pixels: every path that does waits for the flush and gets the real
    /// buffers back first.
    pub(crate) fn hollow(&self) -> Framebuffer {
        Framebuffer {
            desc: self.desc,
            color: ColorStore::Owned(Vec::new()),
            color_stride: self.color_stride,
            color_top_down: self.color_top_down,
            depth: self.depth.as_ref().map(|d| match d {
                DepthBuffer::D16(_) => DepthBuffer::D16(Vec::new()),
                DepthBuffer::D24(_) => DepthBuffer::D24(Vec::new()),
                DepthBuffer::D32(_) => DepthBuffer::D32(Vec::new()),
                DepthBuffer::D32F(_) => DepthBuffer::D32F(Vec::new()),
            }),
            stencil: self.stencil.as_ref().map(|_| Vec::new()),
            color_enabled: self.color_enabled,
            accum: self.accum.as_ref().map(AccumBuffer::hollow),
            samples: self.samples.iter().map(Framebuffer::hollow).collect(),
            window_samples: self.window_samples,
        }
    }

    /// Replaces the color buffer with `memory` (same size and format), rows
    /// `stride` bytes apart, top row first when `top_down`. Depth and stencil
    /// are kept. `InvalidValue` (and no change) when `memory` is too small.
    pub fn set_color_memory(&mut self, memory: Box<dyn ColorMemory>, stride: usize, top_down: bool) -> GlResult {
        check_color_memory(&self.desc, memory.bytes().len(), stride)?;
        self.color = ColorStore::Lent(memory);
        self.color_stride = stride;
        self.color_top_down = top_down;
        Ok(())
    }

    /// Bytes from one color row to the next.
    pub fn color_stride(&self) -> usize {
        self.color_stride
    }

    /// Whether color row 0 is the top of the image.
    pub fn color_top_down(&self) -> bool {
        self.color_top_down
    }

    /// Byte offset of pixel `(x, y)` (window coordinates) in the color bytes.
    pub(crate) fn color_offset(&self, x: u32, y: u32) -> usize {
        let row = if self.color_top_down {
            self.desc.height - 1 - y
        } else {
            y
        };
        row as usize * self.color_stride + x as usize * self.desc.color.bytes_per_pixel()
    }

    pub fn desc(&self) -> &FramebufferDesc {
        &self.desc
    }

    pub fn width(&self) -> u32 {
        self.desc.width
    }

    pub fn height(&self) -> u32 {
        self.desc.height
    }

    pub fn color_format(&self) -> ColorFormat {
        self.desc.color
    }

    pub fn depth_format(&self) -> Option<DepthFormat> {
        self.depth.as_ref().map(DepthBuffer::format)
    }

    pub fn has_stencil(&self) -> bool {
        self.stencil.is_some()
    }

    /// The color bytes: rows bottom-up and tightly packed unless the memory
    /// was lent with another layout ([`Framebuffer::color_stride`], [`Framebuffer::color_top_down`]).
    pub fn color_bytes(&self) -> &[u8] {
        self.color.bytes()
    }

    pub fn depth_buffer(&self) -> Option<&DepthBuffer> {
        self.depth.as_ref()
    }

    /// The depth storage, for callers that hand it out (`OSMesaGetDepthBuffer`).
    pub fn depth_buffer_mut(&mut self) -> Option<&mut DepthBuffer> {
        self.depth.as_mut()
    }

    pub fn stencil_buffer(&self) -> Option<&[u8]> {
        self.stencil.as_deref()
    }

    /// Clears as `clear` says, now.
    pub fn apply_clear(&mut self, clear: &Clear) {
        clear.apply(&mut self.target(), clear.rect);
    }

    /// A checked view for the fragment stages.
    pub fn target(&mut self) -> Target<'_> {
        let (w, h, format) = (self.desc.width, self.desc.height, self.desc.color);
        let depth = self.depth.as_mut().map(|d| match d {
            DepthBuffer::D16(v) => DepthTarget::D16(v),
            DepthBuffer::D24(v) => DepthTarget::D24(v),
            DepthBuffer::D32(v) => DepthTarget::D32(v),
            DepthBuffer::D32F(v) => DepthTarget::D32F(v),
        });
        Target::new(
            w,
            h,
            format,
            self.color.bytes_mut(),
            self.color_stride,
            depth,
            self.stencil.as_deref_mut(),
        )
        .expect("a framebuffer's buffers are allocated for its size")
        .with_top_down(self.color_top_down)
    }

    /// The whole framebuffer as a rectangle.
    pub fn bounds(&self) -> Rect {
        Rect {
            x0: 0,
            y0: 0,
            x1: self.desc.width,
            y1: self.desc.height,
        }
    }

    /// The intersection of the framebuffer with the window rectangle `x, y, w, h`.
    pub fn clip_rect(&self, x: i64, y: i64, w: i64, h: i64) -> Rect {
        let clamp_x = |v: i64| v.clamp(0, i64::from(self.desc.width)) as u32;
        let clamp_y = |v: i64| v.clamp(0, i64::from(self.desc.height)) as u32;
        Rect {
            x0: clamp_x(x),
            y0: clamp_y(y),
            x1: clamp_x(x.saturating_add(w)),
            y1: clamp_y(y.saturating_add(h)),
        }
    }

    /// The color at `(x, y)` as unorm RGBA (alpha 255 for formats without
    /// alpha; the deep formats' channels rounded to 8 bits from their float
    /// values, clamped).
    pub fn pixel(&self, x: u32, y: u32) -> Option<[u8; 4]> {
        if x >= self.desc.width || y >= self.desc.height {
            return None;
        }
        let format = self.desc.color;
        let off = self.color_offset(x, y);
        let bytes = &self.color.bytes()[off..];
        if format.is_deep() {
            let c = deep::to_float(format, deep::load(format, bytes));
            return Some(c.map(|v| float_to_unorm(v, 255) as u8));
        }
        Some(pixel::unpack(format, pixel::load(format, bytes)))
    }

    /// The colour bytes of pixels `x0..x1` of row `y`, in the colour
    /// format (`None` when they are not all inside): what a fast
    /// `glReadPixels` copies from.
    pub fn color_span(&self, x0: u32, x1: u32, y: u32) -> Option<&[u8]> {
        if x0 > x1 || x1 > self.desc.width || y >= self.desc.height {
            return None;
        }
        let bpp = self.desc.color.bytes_per_pixel();
        let off = self.color_offset(x0, y);
        self.color.bytes().get(off..off + (x1 - x0) as usize * bpp)
    }

    /// The color at `(x, y)` as float RGBA: unorm channels over their
    /// maximum (8-bit ones `v / 255`), floats as stored.
    pub fn pixel_f32(&self, x: u32, y: u32) -> Option<[f32; 4]> {
        let format = self.desc.color;
        if !format.is_deep() {
            return self.pixel(x, y).map(|p| p.map(|c| f32::from(c) / 255.0));
        }
        if x >= self.desc.width || y >= self.desc.height {
            return None;
        }
        let off = self.color_offset(x, y);
        Some(deep::to_float(format, deep::load(format, &self.color.bytes()[off..])))
    }

    /// The stored depth at `(x, y)`, in buffer units.
    pub fn depth_at(&self, x: u32, y: u32) -> Option<u32> {
        if x >= self.desc.width || y >= self.desc.height {
            return None;
        }
        let i = y as usize * self.desc.width as usize + x as usize;
        self.depth.as_ref().map(|d| d.get(i))
    }

    /// The stored stencil value at `(x, y)`.
    pub fn stencil_at(&self, x: u32, y: u32) -> Option<u8> {
        if x >= self.desc.width || y >= self.desc.height {
            return None;
        }
        let i = y as usize * self.desc.width as usize + x as usize;
        self.stencil.as_ref().map(|s| s[i])
    }

    /// `glReadPixels` into bytes: rows bottom-up, tightly packed. Pixels of the
    /// rectangle outside the framebuffer read as zero.
    pub fn read_pixels(&self, x: i32, y: i32, w: i32, h: i32, format: ReadFormat) -> GlResult<Vec<u8>> {
        if w < 0 || h < 0 {
            return Err(GlError::InvalidValue);
        }
        let bpp = format.bytes_per_pixel();
        let mut out = alloc(w as usize * h as usize * bpp, 0u8)?;
        for j in 0..h {
            for i in 0..w {
                let (px, py) = (i64::from(x) + i64::from(i), i64::from(y) + i64::from(j));
                let (Ok(px), Ok(py)) = (u32::try_from(px), u32::try_from(py)) else {
                    continue;
                };
                let Some([r, g, b, a]) = self.pixel(px, py) else {
                    continue;
                };
                let o = (j as usize * w as usize + i as usize) * bpp;
                let dst = &mut out[o..o + bpp];
                match format {
                    ReadFormat::Rgba8 => dst.copy_from_slice(&[r, g, b, a]),
                    ReadFormat::Rgb8 => dst.copy_from_slice(&[r, g, b]),
                    ReadFormat::Bgra8 => dst.copy_from_slice(&[b, g, r, a]),
                }
            }
        }
        Ok(out)
    }

    /// `glReadPixels` with `GL_FLOAT`: RGBA in `[0, 1]` (a float buffer's
    /// values as stored), rows bottom-up.
    pub fn read_pixels_f32(&self, x: i32, y: i32, w: i32, h: i32) -> GlResult<Vec<[f32; 4]>> {
        if self.desc.color.is_deep() {
            if w < 0 || h < 0 {
                return Err(GlError::InvalidValue);
            }
            let mut out = alloc(w as usize * h as usize, [0.0f32; 4])?;
            for j in 0..h {
                for i in 0..w {
                    let (px, py) = (i64::from(x) + i64::from(i), i64::from(y) + i64::from(j));
                    let (Ok(px), Ok(py)) = (u32::try_from(px), u32::try_from(py)) else {
                        continue;
                    };
                    if let Some(c) = self.pixel_f32(px, py) {
                        out[j as usize * w as usize + i as usize] = c;
                    }
                }
            }
            return Ok(out);
        }
        let bytes = self.read_pixels(x, y, w, h, ReadFormat::Rgba8)?;
        Ok(bytes
            .chunks_exact(4)
            .map(|p| [0, 1, 2, 3].map(|c| f32::from(p[c]) / 255.0))
            .collect())
    }

    /// The color buffer as an image, top row first.
    pub fn to_rgba_image(&self) -> image::RgbaImage {
        let (w, h) = (self.desc.width, self.desc.height);
        image::RgbaImage::from_fn(w, h, |x, y| image::Rgba(self.pixel(x, h - 1 - y).unwrap_or([0; 4])))
    }
}

/// `InvalidValue` unless `len` bytes hold `desc`'s color rows `stride` bytes apart.
fn check_color_memory(desc: &FramebufferDesc, len: usize, stride: usize) -> GlResult {
    let row = desc.width as usize * desc.color.bytes_per_pixel();
    let rows = (desc.height as usize).saturating_sub(1);
    let needed = stride.checked_mul(rows).and_then(|v| v.checked_add(row));
    if stride < row || needed.is_none_or(|n| len < n) {
        return Err(GlError::InvalidValue);
    }
    Ok(())
}

/// A zero-initialised vector, or `OutOfMemory` instead of an abort.
fn alloc<T: Clone>(n: usize, value: T) -> GlResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| GlError::OutOfMemory)?;
    v.resize(n, value);
    Ok(v)
}

#[cfg(test)]
mod mask_row_tests {
    use super::*;

    /// The pixel-by-pixel masked write `mask_row` replaces.
    fn by_pixel(format: ColorFormat, row: &mut [u8], value: u32, bits: u32) {
        for px in row.chunks_exact_mut(format.bytes_per_pixel()) {
            let old = pixel::load(format, px);
            pixel::store(format, px, (value & bits) | (old & !bits));
        }
    }

    #[test]
    fn masked_and_filled_rows_are_the_bytes_of_pixel_by_pixel() {
        let formats = [
            ColorFormat::Rgba8,
            ColorFormat::Bgra8,
            ColorFormat::Rgb8,
            ColorFormat::Rgb565,
        ];
        let mut seed = 0x1234_5678u32;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        for format in formats {
            let bpp = format.bytes_per_pixel();
            for width in [0, 1, 2, 5, 11, 12, 16, 17, 24, 25, 63, 64, 100] {
                for m in 0..16u8 {
                    let mask = ColorMask::from_bits(m.into());
                    let bits = pixel::mask_bits(format, mask);
                    let value = next() & if bpp == 2 { 0xffff } else { u32::MAX };
                    let old: Vec<u8> = (0..width * bpp).map(|_| next() as u8).collect();
                    let (mut a, mut b) = (old.clone(), old);
                    by_pixel(format, &mut a, value, bits);
                    match bpp {
                        4 => mask_row::<4>(&mut b, value, bits),
                        3 => mask_row::<3>(&mut b, value, bits),
                        _ => mask_row::<2>(&mut b, value, bits),
                    }
                    assert_eq!(a, b, "{format:?} width {width} mask {m}");
                }
                // A clear through every channel.
                let value = next() & if bpp == 2 { 0xffff } else { u32::MAX };
                let all = pixel::mask_bits(format, ColorMask::ALL);
                let old: Vec<u8> = (0..width * bpp).map(|_| next() as u8).collect();
                let (mut a, mut b) = (old.clone(), old);
                by_pixel(format, &mut a, value, all);
                let bytes = value.to_le_bytes();
                match bpp {
                    4 => fill_row::<4>(&mut b, &bytes),
                    3 => fill_row::<3>(&mut b, &bytes),
                    _ => fill_row::<2>(&mut b, &bytes),
                }
                assert_eq!(a, b, "{format:?} width {width} filled");
            }
        }
    }
}
