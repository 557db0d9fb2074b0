//! Pixel transfer between client memory and texel storage: where each pixel
//! is under the pixel-store state, and each component's conversion, taking
//! the route Mesa 22.3.6's `_mesa_format_convert` takes
//! (`main/format_utils.c`, `main/texstore.c`, `main/texgetimage.c`), so that
//! stored values equal llvmpipe's bit for bit.

use super::format::{
    float_to_unorm, snorm_to_float, unorm_to_float, unorm_to_unorm, PixelFormat, PixelType, Storage, TypeKind,
};
use super::jit::{BaseFormat, TexelFormat};
use super::object::TexImage;
use super::{PixelData, PixelStore};
use crate::pixel_transfer::PixelState;

/// Where an image's pixels are in client memory (GL 1.5 §3.6.4, Mesa
/// `main/image.c` `_mesa_image_address` and `_mesa_image_row_stride`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClientLayout {
    pub pixel_bytes: usize,
    pub row_stride: usize,
    pub image_stride: usize,
    /// Offset of pixel (0, 0, 0): the skips.
    pub start: usize,
    /// Bytes from the start of memory to the end of the last pixel.
    pub len: usize,
}

impl ClientLayout {
    /// The layout of a `size` image with `dims` dimensions (image height and
    /// skipped images count for 3D only); `None` when it overflows.
    pub fn new(format: PixelFormat, ty: PixelType, store: &PixelStore, dims: u32, size: [usize; 3]) -> Option<Self> {
        let pixel_bytes = format.pixel_bytes(ty);
        let row_pixels = if store.row_length > 0 {
            store.row_length as usize
        } else {
            size[0]
        };
        let align = store.alignment.max(1) as usize;
        let row_stride = row_pixels.checked_mul(pixel_bytes)?.checked_next_multiple_of(align)?;
        let rows = if dims == 3 && store.image_height > 0 {
            store.image_height as usize
        } else {
            size[1]
        };
        let image_stride = row_stride.checked_mul(rows)?;
        let skip_images = if dims == 3 {
            store.skip_images.max(0) as usize
        } else {
            0
        };
        let start = skip_images
            .checked_mul(image_stride)?
            .checked_add((store.skip_rows.max(0) as usize).checked_mul(row_stride)?)?
            .checked_add((store.skip_pixels.max(0) as usize).checked_mul(pixel_bytes)?)?;
        let len = if size.contains(&0) {
            0
        } else {
            let last = (size[2] - 1)
                .checked_mul(image_stride)?
                .checked_add((size[1] - 1).checked_mul(row_stride)?)?
                .checked_add(size[0].checked_mul(pixel_bytes)?)?;
            start.checked_add(last)?
        };
        (len <= isize::MAX as usize).then_some(ClientLayout {
            pixel_bytes,
            row_stride,
            image_stride,
            start,
            len,
        })
    }

    /// Offset of pixel `(x, y, z)`.
    pub fn at(&self, x: usize, y: usize, z: usize) -> usize {
        self.start + z * self.image_stride + y * self.row_stride + x * self.pixel_bytes
    }
}

/// One component as the client (or the texel storage) holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Raw {
    /// Unsigned normalized: value and bits.
    U(u32, u32),
    /// Signed normalized: value and bits.
    S(i32, u32),
    F(f32),
}

impl Raw {
    pub const ZERO: Raw = Raw::U(0, 1);
    pub const ONE: Raw = Raw::U(1, 1);

    /// To an unsigned normalized value of `bits` (Mesa's `_mesa_unorm_to_unorm`,
    /// `_mesa_snorm_to_unorm`, `_mesa_float_to_unorm`).
    pub fn to_unorm(self, bits: u32) -> u32 {
        match self {
            Raw::U(x, b) => unorm_to_unorm(x, b, bits),
            Raw::S(x, _) if x < 0 => 0,
            Raw::S(x, b) => unorm_to_unorm(x as u32, b - 1, bits),
            Raw::F(x) => float_to_unorm(x, bits),
        }
    }

    /// To a signed normalized value of `bits` (`_mesa_unorm_to_snorm`,
    /// `_mesa_snorm_to_snorm`, `_mesa_float_to_snorm`).
    pub fn to_snorm(self, bits: u32) -> i32 {
        let max = ((1i64 << (bits - 1)) - 1) as i32;
        match self {
            Raw::U(x, b) => unorm_to_unorm(x, b, bits - 1) as i32,
            Raw::S(x, b) if x < -(((1i64 << (b - 1)) - 1) as i32) => -max,
            Raw::S(x, b) if b < bits => {
                let (sb, db) = (b - 1, bits - 1);
                let rem = db % sb;
                let extra = if rem != 0 { x >> (sb - rem) } else { 0 };
                x.wrapping_mul((((1i64 << db) - 1) / ((1i64 << sb) - 1)) as i32)
                    .wrapping_add(extra)
            }
            Raw::S(x, b) => x >> (b - bits),
            Raw::F(x) if x < -1.0 => -max,
            Raw::F(x) if x > 1.0 => max,
            // `_mesa_lroundevenf` to long, then C's cast to int (1.0 → −2^31 for 32 bits, as Mesa).
            Raw::F(x) => (x * max as f32).round_ties_even() as i64 as i32,
        }
    }

    pub fn to_f32(self) -> f32 {
        match self {
            Raw::U(x, b) => unorm_to_float(x, b),
            Raw::S(x, b) => snorm_to_float(x, b),
            Raw::F(x) => x,
        }
    }
}

/// How `_mesa_format_convert` carries a component from source to destination.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// One conversion (array format to array format, or a direct pack from RGBA float/ubyte).
    Direct,
    /// Through an RGBA ubyte intermediate (destination of at most 8 unsigned bits).
    Ubyte,
    /// Through an RGBA float intermediate.
    Float,
}

/// A side of a conversion, as `_mesa_format_convert` classifies it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Side {
    /// Given to Mesa as an array format (a client format with a plain type);
    /// texture formats and packed client types are `mesa_format`s.
    pub encoded_array: bool,
    /// Has an array format (every channel a whole byte, short, int or float).
    pub array: bool,
    /// Exactly RGBA8 ubyte or RGBA float32 in memory order R, G, B, A (the
    /// direct pack and unpack cases).
    pub rgba_direct: bool,
    /// Signed or float (`is_signed` of a destination).
    pub signed: bool,
    /// Largest channel.
    pub max_bits: u32,
}

impl Side {
    /// The client's side of a transfer.
    pub fn client(format: PixelFormat, ty: PixelType) -> Side {
        let kind = ty.kind();
        let max_bits = match kind {
            TypeKind::Unsigned(b) | TypeKind::Signed(b) => b,
            TypeKind::Float => 32,
            TypeKind::Packed(_, f) => f.iter().map(|&(_, b)| b).max().unwrap_or(0),
        };
        let plain = !matches!(kind, TypeKind::Packed(..));
        Side {
            encoded_array: plain,
            array: plain,
            rgba_direct: format == PixelFormat::Rgba
                && matches!(
                    ty,
                    PixelType::UnsignedByte | PixelType::Float | PixelType::UnsignedInt8888Rev
                ),
            signed: matches!(kind, TypeKind::Signed(_) | TypeKind::Float),
            max_bits,
        }
    }

    /// The texture's side.
    pub fn texture(storage: &Storage) -> Side {
        Side {
            encoded_array: false,
            array: storage.is_array(),
            rgba_direct: storage.bits == [8, 8, 8, 8],
            signed: false,
            max_bits: storage.max_bits(),
        }
    }
}

/// The route from `src` to `dst` (`rebase`: a swizzle to the base format is
/// applied, which rules out the direct pack and unpack cases).
pub fn route(src: Side, dst: Side, rebase: bool) -> Route {
    let direct_unpack = !src.encoded_array && dst.rgba_direct;
    let direct_pack = !dst.encoded_array && src.rgba_direct;
    if (!rebase && (direct_unpack || direct_pack)) || (src.array && dst.array) {
        Route::Direct
    } else if dst.signed || dst.max_bits > 8 {
        Route::Float
    } else {
        Route::Ubyte
    }
}

/// A destination component's kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dst {
    /// A channel of an array format (Mesa converts floats with `_mesa_float_to_unorm`).
    Unorm(u32),
    /// A field of a packed format: floats go through util_format's pack
    /// functions, `util_iround(clamp(x) · max)` (`util/format/u_format_pack.py`).
    PackedUnorm(u32),
    Snorm(u32),
    Float,
}

/// `util_iround(CLAMP(x, 0, 1) * max)`: `(int)(v + 0.5)` in f32.
fn packed_float_to_unorm(x: f32, bits: u32) -> u32 {
    if x.is_nan() {
        return 0;
    }
    let max = ((1u64 << bits) - 1) as f32;
    (x.clamp(0.0, 1.0) * max + 0.5) as u32
}

/// `raw` converted to `dst` along `route`.
pub fn convert(raw: Raw, route: Route, dst: Dst) -> Raw {
    let mid = match route {
        Route::Direct => raw,
        Route::Ubyte => Raw::U(raw.to_unorm(8), 8),
        Route::Float => Raw::F(raw.to_f32()),
    };
    match dst {
        Dst::Unorm(b) => Raw::U(mid.to_unorm(b), b),
        Dst::PackedUnorm(b) => match mid {
            Raw::F(x) => Raw::U(packed_float_to_unorm(x, b), b),
            _ => Raw::U(mid.to_unorm(b), b),
        },
        Dst::Snorm(b) => Raw::S(mid.to_snorm(b), b),
        Dst::Float => Raw::F(mid.to_f32()),
    }
}

fn read_le(bytes: &[u8], n: usize, swap: bool) -> u32 {
    let mut b = [0u8; 4];
    b[..n].copy_from_slice(&bytes[..n]);
    if swap {
        b[..n].reverse();
    }
    // Client memory is in native order; softgl's targets are little-endian
    // like Mesa's x86 build (a big-endian host would swap here).
    u32::from_ne_bytes(b) & if n == 4 { u32::MAX } else { (1u32 << (8 * n)) - 1 }
}

fn write_ne(out: &mut [u8], v: u32, n: usize, swap: bool) {
    let mut b = v.to_ne_bytes();
    if swap {
        b[..n].reverse();
    }
    out[..n].copy_from_slice(&b[..n]);
}

/// The pixel at `at` as RGBA slots: components the format lacks are 0 for
/// colour and 1 for alpha; luminance fills R, G and B (GL 1.5 table 3.15).
pub fn fetch(bytes: &[u8], at: usize, format: PixelFormat, ty: PixelType, swap: bool) -> [Raw; 4] {
    let mut out = [Raw::ZERO, Raw::ZERO, Raw::ZERO, Raw::ONE];
    let comps = format.components();
    let mut put = |k: usize, v: Raw| {
        let slot = comps[k];
        if matches!(format, PixelFormat::Luminance | PixelFormat::LuminanceAlpha) && slot == 0 {
            out[..3].fill(v);
        } else {
            out[slot] = v;
        }
    };
    if ty == PixelType::Float32UnsignedInt248Rev {
        // The depth float, then the stencil in the next word's low byte.
        out[0] = Raw::F(f32::from_bits(read_le(&bytes[at..], 4, swap)));
        out[1] = Raw::U(read_le(&bytes[at + 4..], 4, swap) & 0xff, 8);
        return out;
    }
    match ty.kind() {
        TypeKind::Packed(n, fields) => {
            let v = read_le(&bytes[at..], n as usize, swap);
            for (k, &(shift, bits)) in fields.iter().enumerate().take(comps.len()) {
                put(k, Raw::U((v >> shift) & ((1u32 << bits) - 1), bits));
            }
        }
        kind => {
            let size = ty.element_bytes();
            for k in 0..comps.len() {
                let v = read_le(&bytes[at + k * size..], size, swap);
                put(
                    k,
                    match kind {
                        TypeKind::Unsigned(b) => Raw::U(v, b),
                        TypeKind::Signed(b) => Raw::S(((v << (32 - b)) as i32) >> (32 - b), b),
                        _ => Raw::F(f32::from_bits(v)),
                    },
                );
            }
        }
    }
    out
}

/// Writes RGBA slots `rgba` as one pixel of `format`/`ty` at `at`, along `route`.
pub fn store(out: &mut [u8], at: usize, format: PixelFormat, ty: PixelType, swap: bool, rgba: [Raw; 4], route: Route) {
    let comps = format.components();
    match ty.kind() {
        TypeKind::Packed(n, fields) => {
            let mut v = 0u32;
            for (k, &(shift, bits)) in fields.iter().enumerate() {
                let Raw::U(x, _) = convert(rgba[comps[k]], route, Dst::PackedUnorm(bits)) else {
                    unreachable!("Unorm gives U")
                };
                v |= x << shift;
            }
            write_ne(&mut out[at..], v, n as usize, swap);
        }
        kind => {
            let size = ty.element_bytes();
            for (k, &slot) in comps.iter().enumerate() {
                let dst = match kind {
                    TypeKind::Unsigned(b) => Dst::Unorm(b),
                    TypeKind::Signed(b) => Dst::Snorm(b),
                    _ => Dst::Float,
                };
                let bits = match convert(rgba[slot], route, dst) {
                    Raw::U(x, _) => x,
                    Raw::S(x, _) => x as u32,
                    Raw::F(x) => x.to_bits(),
                };
                write_ne(&mut out[at + k * size..], bits, size, swap);
            }
        }
    }
}

/// A depth value in [0, 1] as Mesa's `_mesa_unpack_depth_span` (`main/pack.c`) reads `raw`.
fn depth_float(raw: Raw) -> f32 {
    let f = match raw {
        Raw::U(x, 8) => x as f32 / 255.0,
        Raw::U(x, 16) => x as f32 * (1.0 / 65535.0),
        Raw::U(x, _) => (f64::from(x) * (1.0 / 4294967295.0)) as f32,
        // BYTE_TO_FLOATZ, SHORT_TO_FLOATZ, INT_TO_FLOAT: (2x + 1) / (2^b − 1), 0 kept.
        Raw::S(0, 8 | 16) => 0.0,
        Raw::S(x, 8) => (2.0 * x as f32 + 1.0) * (1.0 / 255.0),
        Raw::S(x, 16) => (2.0 * x as f32 + 1.0) * (1.0 / 65535.0),
        Raw::S(x, _) => ((2.0 * x as f32 + 1.0) as f64 * (1.0 / 4294967294.0)) as f32,
        Raw::F(x) => x,
    };
    f.clamp(0.0, 1.0)
}

/// The stored depth (an unsigned value of `bits`) for a client component.
pub fn depth_to_unorm(raw: Raw, bits: u32) -> u32 {
    match (raw, bits) {
        // A depth buffer's own value (copies): rescaled as an unsigned normalized value.
        (Raw::U(x, b), _) if !matches!(b, 8 | 16 | 32) => unorm_to_unorm(x, b, bits),
        // The special cases at the top of `_mesa_unpack_depth_span`.
        (Raw::U(x, 32), 16) => x >> 16,
        (Raw::U(x, 16), 32) => x | (x << 16),
        (_, 16) => (depth_float(raw) * 65535.0) as u16 as u32,
        (_, 24) => (depth_float(raw) * 16777215.0) as u32,
        _ => {
            let z = f64::from(depth_float(raw)) * 4294967295.0;
            if z >= 4294967295.0 {
                u32::MAX
            } else {
                z as u32
            }
        }
    }
}

/// A stored depth as llvmpipe's sampler reads it, what `Depth32F` texels
/// hold (`lp_build_unsigned_norm_to_float`, §16): up to 24 bits `z · f32(1/max)`,
/// 32 bits through the top 23 bits as a mantissa.
pub fn depth_sampled(z: u32, bits: u32) -> f32 {
    if bits == 32 {
        let m = f32::from_bits((z >> 9) | 0x3f80_0000) - 1.0;
        return m * (8_388_608.0f64 / 8_388_607.0) as f32;
    }
    z as f32 * (1.0 / ((1u64 << bits) - 1) as f64) as f32
}

/// The stored depth back from [`depth_sampled`] (for `glGetTexImage`): the
/// value nearest `f · max` among those the sampler reads as `f`. Exact for 16
/// bits; for 24 bits neighbours can share an f32, then one of them is
/// returned; 32 bits keep their top 23.
pub fn depth_unsampled(f: f32, bits: u32) -> u32 {
    let max = ((1u64 << bits) - 1) as f64;
    let guess = (f64::from(f) * max).round() as i64;
    let candidates = (guess - 3..=guess + 3).filter(|&z| (0..=max as i64).contains(&z));
    candidates
        .filter(|&z| depth_sampled(z as u32, bits) == f)
        .min_by_key(|&z| (z - guess).abs())
        .unwrap_or(guess.clamp(0, max as i64)) as u32
}

/// A stored depth as Mesa's `glGetTexImage` reads it (`util/format/u_format_zs.c`:
/// 16 bits in f32, 24 and 32 in f64).
fn depth_readback(z: u32, bits: u32) -> f32 {
    match bits {
        16 => z as f32 * (1.0 / 65535.0) as f32,
        24 => (f64::from(z) * (1.0 / 16777215.0)) as f32,
        _ => (f64::from(z) * (1.0 / 4294967295.0)) as f32,
    }
}

/// A depth value packed as `ty` (`main/pack.c` `_mesa_pack_depth_span`).
fn pack_depth(d: f32, ty: PixelType) -> (u32, usize) {
    match ty {
        PixelType::UnsignedByte => ((d * 255.0) as i32 as u8 as u32, 1),
        PixelType::Byte => (((((255.0 * d) as i32) - 1) / 2) as i8 as u8 as u32, 1),
        PixelType::UnsignedShort => ((d * 65535.0).round_ties_even() as u16 as u32, 2),
        PixelType::Short => (((((65535.0 * d) as i32) - 1) / 2) as i16 as u16 as u32, 2),
        PixelType::UnsignedInt => ((f64::from(d) * 4294967295.0) as u32, 4),
        PixelType::Int => ((2147483647.0 * f64::from(d)) as i32 as u32, 4),
        _ => (d.to_bits(), 4),
    }
}

/// The quantized value of each RGBA channel of a stored texel (`None` for a
/// channel the base format lacks), or the depth value.
pub fn texel_channels(img: &TexImage, x: usize, y: usize, z: usize) -> [Option<Raw>; 4] {
    let storage = img.internal.storage();
    let at = img.offset(x, y, z);
    let t = &img.texels[at..];
    let mut out = [None; 4];
    for (c, &bits) in storage.bits.iter().enumerate() {
        if bits == 0 {
            continue;
        }
        out[c] = Some(match storage.texel_format() {
            TexelFormat::Rgba8 | TexelFormat::Srgba8 => Raw::U(unorm_to_unorm(u32::from(t[c]), 8, bits), bits),
            TexelFormat::Rgba16 => {
                let v = u32::from(u16::from_ne_bytes([t[2 * c], t[2 * c + 1]]));
                Raw::U(unorm_to_unorm(v, 16, bits), bits)
            }
            TexelFormat::Depth32F => Raw::F(f32::from_ne_bytes([t[0], t[1], t[2], t[3]])),
        });
    }
    out
}

/// Writes quantized channels (`n` of `storage.bits`) as one stored texel.
pub(crate) fn put_texel(out: &mut [u8], storage: &Storage, n: [u32; 4]) {
    let base = storage.base;
    // Expand the base format's channels to RGBA (L → LLL1, A → 000A, I → IIII).
    let slot = |c: usize| -> Option<usize> {
        match base {
            BaseFormat::Luminance => (c < 3).then_some(0),
            BaseFormat::LuminanceAlpha => Some(if c < 3 { 0 } else { 3 }),
            BaseFormat::Intensity => Some(0),
            BaseFormat::Alpha => (c == 3).then_some(3),
            BaseFormat::Rgb => (c < 3).then_some(c),
            BaseFormat::Rgba | BaseFormat::Depth => Some(c),
        }
    };
    match storage.texel_format() {
        TexelFormat::Rgba8 | TexelFormat::Srgba8 => {
            for (c, o) in out[..4].iter_mut().enumerate() {
                *o = match slot(c) {
                    Some(s) => unorm_to_unorm(n[s], storage.bits[s], 8) as u8,
                    None if c == 3 => 255,
                    None => 0,
                };
            }
        }
        TexelFormat::Rgba16 => {
            for c in 0..4 {
                let v = match slot(c) {
                    Some(s) if storage.bits[s] == 16 => n[s],
                    Some(s) => float_to_unorm(unorm_to_float(n[s], storage.bits[s]), 16),
                    None if c == 3 => 65535,
                    None => 0,
                };
                out[2 * c..2 * c + 2].copy_from_slice(&(v as u16).to_ne_bytes());
            }
        }
        TexelFormat::Depth32F if storage.float => out[..4].copy_from_slice(&n[0].to_ne_bytes()),
        TexelFormat::Depth32F => {
            out[..4].copy_from_slice(&depth_sampled(n[0], storage.bits[0]).to_ne_bytes());
        }
    }
}

/// Stores `rgba` (client components as RGBA slots) into texel `(x, y, z)` of
/// `img`, converting along `route`.
pub fn store_texel(img: &mut TexImage, (x, y, z): (usize, usize, usize), rgba: [Raw; 4], route: Route) {
    let storage = img.internal.storage();
    let mut n = [0u32; 4];
    if storage.float {
        // `_mesa_unpack_depth_span` to float, clamped to [0, 1] (NaN as 0 here).
        let f = match rgba[0] {
            // A depth buffer's own value (copies).
            Raw::U(x, b) if !matches!(b, 8 | 16 | 32) => (f64::from(x) / ((1u64 << b) - 1) as f64) as f32,
            r => depth_float(r),
        };
        n[0] = softgl_jit::DepthFormat::D32F.from_window(f);
    } else if storage.base == BaseFormat::Depth {
        n[0] = depth_to_unorm(rgba[0], storage.bits[0]);
    } else {
        for c in 0..4 {
            if storage.bits[c] > 0 {
                let dst = if storage.is_array() {
                    Dst::Unorm(storage.bits[c])
                } else {
                    Dst::PackedUnorm(storage.bits[c])
                };
                let Raw::U(v, _) = convert(rgba[c], route, dst) else {
                    unreachable!("Unorm gives U")
                };
                n[c] = v;
            }
        }
    }
    let at = img.offset(x, y, z);
    put_texel(&mut img.texels_mut()[at..], &storage, n);
}

/// Client components `rgba` (fetched as `format`) after the pixel transfer
/// operations `t` (GL 1.5 §3.6.4, as Mesa's texture store applies them):
/// colours as floats through scale, bias and maps, clamped; depth through
/// depth scale and bias; stencil indices through shift, offset and map.
pub fn transfer(t: &PixelState, format: PixelFormat, rgba: [Raw; 4]) -> [Raw; 4] {
    match format {
        PixelFormat::DepthComponent => [Raw::F(t.depth(rgba[0].to_f32())), rgba[1], rgba[2], rgba[3]],
        PixelFormat::DepthStencil => {
            let s = match rgba[1] {
                Raw::U(s, _) => t.stencil(i64::from(s)) as u8,
                _ => 0,
            };
            [
                Raw::F(t.depth(rgba[0].to_f32())),
                Raw::U(u32::from(s), 8),
                rgba[2],
                rgba[3],
            ]
        }
        _ => t.cpu_colour(rgba.map(Raw::to_f32)).map(Raw::F),
    }
}

/// Converts `data`'s pixels into the `size` region of `img` at `offset`,
/// through the pixel transfer operations `transfer` when they are not the
/// identity. `data.bytes` must hold `layout` (checked by the caller).
pub fn upload(
    img: &mut TexImage,
    offset: [usize; 3],
    size: [usize; 3],
    data: &PixelData<'_>,
    layout: &ClientLayout,
    transfer: Option<&PixelState>,
) {
    let storage = img.internal.storage();
    if let Some(t) = transfer {
        return upload_transferred(img, offset, size, data, layout, t);
    }
    if data.ty == PixelType::UnsignedByte
        && storage.base != BaseFormat::Depth
        && storage.is_array()
        && storage.max_bits() == 8
    {
        return upload_bytes(img, &storage, offset, size, data, layout);
    }
    let route = route(Side::client(data.format, data.ty), Side::texture(&storage), false);
    let swap = data.store.swap_bytes;
    // Stencil goes to a depth-stencil image's stencil plane; depth-only
    // data keeps it (Mesa `_mesa_texstore_z24_s8`, `keepstencil`).
    let stencil = data.format == PixelFormat::DepthStencil && img.internal.stencil_bits() > 0;
    for z in 0..size[2] {
        for y in 0..size[1] {
            for x in 0..size[0] {
                let rgba = fetch(data.bytes, layout.at(x, y, z), data.format, data.ty, swap);
                let at = (offset[0] + x, offset[1] + y, offset[2] + z);
                store_texel(img, at, rgba, route);
                if stencil {
                    let Raw::U(s, _) = rgba[1] else { continue };
                    let so = img.stencil_offset(at.0, at.1, at.2);
                    img.texels_mut()[so] = s as u8;
                }
            }
        }
    }
}

/// [`upload`] through the transfer operations `t`: each pixel as floats
/// (Mesa's temporary float image, `_mesa_make_temp_float_image`), stored
/// as a float is stored.
fn upload_transferred(
    img: &mut TexImage,
    offset: [usize; 3],
    size: [usize; 3],
    data: &PixelData<'_>,
    layout: &ClientLayout,
    t: &PixelState,
) {
    let swap = data.store.swap_bytes;
    let stencil = data.format == PixelFormat::DepthStencil && img.internal.stencil_bits() > 0;
    for z in 0..size[2] {
        for y in 0..size[1] {
            for x in 0..size[0] {
                let raw = fetch(data.bytes, layout.at(x, y, z), data.format, data.ty, swap);
                let rgba = transfer(t, data.format, raw);
                let at = (offset[0] + x, offset[1] + y, offset[2] + z);
                store_texel(img, at, rgba, Route::Direct);
                if stencil {
                    let Raw::U(s, _) = rgba[1] else { continue };
                    let so = img.stencil_offset(at.0, at.1, at.2);
                    img.texels_mut()[so] = s as u8;
                }
            }
        }
    }
}

/// The common case: unsigned bytes into 8-bit channels, where every route
/// of [`upload`] is the identity on each channel (a 1024² RGBA upload: 204 →
/// 58 ms in release on a machine shared by six builds, so a rough figure).
fn upload_bytes(
    img: &mut TexImage,
    storage: &Storage,
    offset: [usize; 3],
    size: [usize; 3],
    data: &PixelData<'_>,
    layout: &ClientLayout,
) {
    let comps = data.format.components();
    let luminance = matches!(data.format, PixelFormat::Luminance | PixelFormat::LuminanceAlpha);
    let n = comps.len();
    let base = storage.base;
    for z in 0..size[2] {
        for y in 0..size[1] {
            let src = &data.bytes[layout.at(0, y, z)..][..size[0] * n];
            let at = img.offset(offset[0], offset[1] + y, offset[2] + z);
            let dst = &mut img.texels_mut()[at..][..size[0] * 4];
            if data.format == PixelFormat::Rgba && base == BaseFormat::Rgba {
                // Stored as given: the row is a copy.
                dst.copy_from_slice(src);
                continue;
            }
            for (px, out) in src.chunks_exact(n).zip(dst.chunks_exact_mut(4)) {
                let mut rgba = [0, 0, 0, 255];
                for (&slot, &v) in comps.iter().zip(px) {
                    if luminance && slot == 0 {
                        rgba[..3].fill(v);
                    } else {
                        rgba[slot] = v;
                    }
                }
                let [r, g, b, a] = rgba;
                out.copy_from_slice(&match base {
                    BaseFormat::Luminance => [r, r, r, 255],
                    BaseFormat::LuminanceAlpha => [r, r, r, a],
                    BaseFormat::Intensity => [r, r, r, r],
                    BaseFormat::Alpha => [0, 0, 0, a],
                    BaseFormat::Rgb => [r, g, b, 255],
                    BaseFormat::Rgba | BaseFormat::Depth => rgba,
                });
            }
        }
    }
}

/// Packs `img` into `out` as `format`/`ty` under `layout` (`glGetTexImage`,
/// Mesa `main/texgetimage.c`): luminance, intensity and alpha textures read
/// back as (L, 0, 0, 1), (I, 0, 0, 1), (0, 0, 0, A); luminance packed from
/// an RGB(A) texture is its red (not R + G + B as `glReadPixels` gives).
pub fn download(img: &TexImage, format: PixelFormat, ty: PixelType, swap: bool, layout: &ClientLayout, out: &mut [u8]) {
    let storage = img.internal.storage();
    let base = storage.base;
    let rebase = matches!(
        base,
        BaseFormat::Luminance | BaseFormat::LuminanceAlpha | BaseFormat::Intensity | BaseFormat::Alpha
    );
    // Luminance into a type without negative values is clamped: Mesa converts
    // to an RGBA float image first (`texgetimage.c`, `IMAGE_CLAMP_BIT`);
    // everything else takes `_mesa_format_convert`'s route.
    let clamped = !matches!(
        ty,
        PixelType::Byte | PixelType::Short | PixelType::Int | PixelType::Float
    );
    let route = if clamped && matches!(format, PixelFormat::Luminance | PixelFormat::LuminanceAlpha) {
        Route::Float
    } else {
        route(Side::texture(&storage), Side::client(format, ty), rebase)
    };
    for z in 0..img.depth as usize {
        for y in 0..img.height as usize {
            for x in 0..img.width as usize {
                let at = layout.at(x, y, z);
                let ch = texel_channels(img, x, y, z);
                if base == BaseFormat::Depth {
                    let Some(Raw::F(d)) = ch[0] else { continue };
                    let bits = storage.bits[0];
                    if format == PixelFormat::DepthStencil && ty == PixelType::Float32UnsignedInt248Rev {
                        // The float the sampler reads, then the stencil word (`z32f_x24s8`).
                        let s = img.texels[img.stencil_offset(x, y, z)];
                        write_ne(&mut out[at..], d.to_bits(), 4, swap);
                        write_ne(&mut out[at + 4..], u32::from(s), 4, swap);
                        continue;
                    }
                    if storage.float {
                        // Z32_FLOAT(_S8X24_UINT) read back: the floats (packed as `ty` says),
                        // with stencil `(uint32_t)(z · 0xffffff) << 8 | s` (u_format_zs.c).
                        if format == PixelFormat::DepthStencil {
                            let z24 = (f64::from(d) * 16_777_215.0) as u32 & 0xff_ffff;
                            let s = img.texels[img.stencil_offset(x, y, z)];
                            write_ne(&mut out[at..], (z24 << 8) | u32::from(s), 4, swap);
                        } else {
                            let (v, n) = pack_depth(d, ty);
                            write_ne(&mut out[at..], v, n, swap);
                        }
                        continue;
                    }
                    if format == PixelFormat::DepthStencil {
                        // `GL_UNSIGNED_INT_24_8` from Z24_UNORM_S8_UINT: the bits moved
                        // (`_mesa_unpack_uint_24_8_depth_stencil_row`).
                        let z24 = depth_unsampled(d, bits);
                        let s = img.texels[img.stencil_offset(x, y, z)];
                        write_ne(&mut out[at..], (z24 << 8) | u32::from(s), 4, swap);
                        continue;
                    }
                    let (v, n) = pack_depth(depth_readback(depth_unsampled(d, bits), bits), ty);
                    write_ne(&mut out[at..], v, n, swap);
                    continue;
                }
                let rgba = [
                    ch[0].unwrap_or(Raw::ZERO),
                    ch[1].unwrap_or(Raw::ZERO),
                    ch[2].unwrap_or(Raw::ZERO),
                    ch[3].unwrap_or(Raw::ONE),
                ];
                store(out, at, format, ty, swap, rgba, route);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn store_state(alignment: i32) -> PixelStore {
        PixelStore {
            alignment,
            ..PixelStore::default()
        }
    }

    #[test]
    fn rows_pad_to_the_alignment_and_skips_offset_the_start() {
        // RGB bytes, 3 wide: 9 bytes a row, padded to 12 with alignment 4.
        let l = ClientLayout::new(PixelFormat::Rgb, PixelType::UnsignedByte, &store_state(4), 2, [3, 2, 1]).unwrap();
        assert_eq!((l.row_stride, l.start, l.len), (12, 0, 21));
        let s = PixelStore {
            row_length: 5,
            skip_rows: 1,
            skip_pixels: 2,
            alignment: 8,
            ..PixelStore::default()
        };
        // 5 pixels × 3 bytes = 15 → 16; start = 16 + 2·3.
        let l = ClientLayout::new(PixelFormat::Rgb, PixelType::UnsignedByte, &s, 2, [3, 2, 1]).unwrap();
        assert_eq!((l.row_stride, l.start, l.len), (16, 22, 22 + 16 + 9));
        // Image height and skipped images count for 3D only.
        let s3 = PixelStore {
            image_height: 4,
            skip_images: 1,
            alignment: 1,
            ..PixelStore::default()
        };
        let l = ClientLayout::new(PixelFormat::Alpha, PixelType::UnsignedByte, &s3, 3, [2, 2, 2]).unwrap();
        assert_eq!((l.image_stride, l.start, l.len), (8, 8, 8 + 8 + 2 + 2));
        let l = ClientLayout::new(PixelFormat::Alpha, PixelType::UnsignedByte, &s3, 2, [2, 2, 1]).unwrap();
        assert_eq!((l.image_stride, l.start, l.len), (4, 0, 4));
    }

    #[test]
    fn packed_fields_and_swapped_bytes() {
        // 0xF800 in 5-6-5: red 31, green 0, blue 0.
        let px = fetch(
            &0xF800u16.to_ne_bytes(),
            0,
            PixelFormat::Rgb,
            PixelType::UnsignedShort565,
            false,
        );
        assert_eq!(px, [Raw::U(31, 5), Raw::U(0, 6), Raw::U(0, 5), Raw::ONE]);
        let px = fetch(
            &0x00F8u16.to_ne_bytes(),
            0,
            PixelFormat::Rgb,
            PixelType::UnsignedShort565,
            true,
        );
        assert_eq!(px[0], Raw::U(31, 5));
        let px = fetch(&[0x80], 0, PixelFormat::Luminance, PixelType::Byte, false);
        assert_eq!(px, [Raw::S(-128, 8), Raw::S(-128, 8), Raw::S(-128, 8), Raw::ONE]);
    }
}
