//! Color arithmetic shared by every back end: GL's unsigned normalized (unorm)
//! rules on 8-bit channels, and conversion to and from each color format.
//! The deep formats (`ColorFormat::is_deep`) have no packed 32-bit pixel:
//! `load`, `pack`, `unpack` and `mask_bits` give 0 for them and `store`
//! writes nothing; `crate::deep` reads and writes them.

use crate::key::{ColorFormat, ColorMask};

/// `a * b / 255` for unorm bytes, rounded the way llvmpipe rounds it:
/// `(t + (t >> 8) + 128) >> 8` with `t = a * b`. This is `round(a * b / 255)`
/// except on 24 of the 65,536 pairs, whose exact quotient is `n + 0.50196`
/// and which give `n` (measured: docs/llvmpipe-facts.md §8, where this formula
/// matched llvmpipe on all 393,216 blends tried and exact rounding did not).
#[inline]
pub fn mul_unorm8(a: u8, b: u8) -> u8 {
    let t = u32::from(a) * u32::from(b);
    ((t + (t >> 8) + 128) >> 8) as u8
}

/// The 4x4 ordered-dither (Bayer) matrix, indexed `[y & 3][x & 3]`.
pub const BAYER4: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

/// The ordered-dither bias at `(x, y)` for [`dither`]: [`BAYER4`] spread over
/// `7..=247` (mean 127, which alone would round to nearest).
#[inline]
pub fn dither_bias(x: u32, y: u32) -> u32 {
    u32::from(BAYER4[(y & 3) as usize][(x & 3) as usize]) * 16 + 7
}

/// `floor((c * max + bias) / 255)`: a byte dithered to a `max`-valued channel
/// (the opt-in ordered dither; llvmpipe never dithers, see [`truncate`]).
#[inline]
pub fn dither(c: u8, max: u32, bias: u32) -> u32 {
    (u32::from(c) * max + bias) / 255
}

/// A byte reduced to its `bits` high bits, `c >> (8 - bits)`: how llvmpipe
/// stores unorm8 colour into a narrower channel (its `scale_bits` in
/// `lp_state_fs.c` shifts, "the wrong rounding"; docs/llvmpipe-facts.md §13).
#[inline]
pub fn truncate(c: u8, bits: u32) -> u32 {
    u32::from(c) >> (8 - bits)
}

/// Expands a 5-bit channel to 8 bits by bit replication (exact for 0 and 31).
#[inline]
pub fn expand5(v: u32) -> u8 {
    ((v << 3) | (v >> 2)) as u8
}

/// Expands a 6-bit channel to 8 bits by bit replication (exact for 0 and 63).
#[inline]
pub fn expand6(v: u32) -> u8 {
    ((v << 2) | (v >> 4)) as u8
}

/// Reads the pixel at the start of `bytes` as its packed little-endian value.
#[inline]
pub fn load(format: ColorFormat, bytes: &[u8]) -> u32 {
    match format {
        ColorFormat::Rgba8 | ColorFormat::Bgra8 => u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
        ColorFormat::Rgb8 => u32::from_le_bytes([bytes[0], bytes[1], bytes[2], 0]),
        ColorFormat::Rgb565 => u32::from(u16::from_le_bytes([bytes[0], bytes[1]])),
        // No packed value: `deep` reads these.
        ColorFormat::Rgba16
        | ColorFormat::Rgbx16
        | ColorFormat::Rgba16F
        | ColorFormat::Rgbx16F
        | ColorFormat::Rgba32F
        | ColorFormat::Rgbx32F => 0,
    }
}

/// Writes the packed value `v` to the start of `bytes` (nothing for the
/// deep formats, which `deep` writes).
#[inline]
pub fn store(format: ColorFormat, bytes: &mut [u8], v: u32) {
    let le = v.to_le_bytes();
    let n = format.bytes_per_pixel().min(4);
    if !format.is_deep() {
        bytes[..n].copy_from_slice(&le[..n]);
    }
}

/// Packs unorm bytes RGBA into `format`. Where bits are lost, `dither` is
/// `None` for llvmpipe's truncation or `Some(bias)` for the ordered dither.
#[inline]
pub fn pack(format: ColorFormat, [r, g, b, a]: [u8; 4], dither: Option<u32>) -> u32 {
    match format {
        ColorFormat::Rgba8 => u32::from_le_bytes([r, g, b, a]),
        ColorFormat::Bgra8 => u32::from_le_bytes([b, g, r, a]),
        ColorFormat::Rgb8 => u32::from_le_bytes([r, g, b, 0]),
        ColorFormat::Rgb565 => {
            let [r, g, b] = match dither {
                None => [truncate(r, 5), truncate(g, 6), truncate(b, 5)],
                Some(bias) => [
                    self::dither(r, 31, bias),
                    self::dither(g, 63, bias),
                    self::dither(b, 31, bias),
                ],
            };
            (r << 11) | (g << 5) | b
        }
        ColorFormat::Rgba16
        | ColorFormat::Rgbx16
        | ColorFormat::Rgba16F
        | ColorFormat::Rgbx16F
        | ColorFormat::Rgba32F
        | ColorFormat::Rgbx32F => 0,
    }
}

/// Unpacks a packed value to unorm bytes RGBA; formats without alpha read alpha 255.
#[inline]
pub fn unpack(format: ColorFormat, v: u32) -> [u8; 4] {
    let [c0, c1, c2, c3] = v.to_le_bytes();
    match format {
        ColorFormat::Rgba8 => [c0, c1, c2, c3],
        ColorFormat::Bgra8 => [c2, c1, c0, c3],
        ColorFormat::Rgb8 => [c0, c1, c2, 255],
        ColorFormat::Rgb565 => [expand5((v >> 11) & 31), expand6((v >> 5) & 63), expand5(v & 31), 255],
        ColorFormat::Rgba16
        | ColorFormat::Rgbx16
        | ColorFormat::Rgba16F
        | ColorFormat::Rgbx16F
        | ColorFormat::Rgba32F
        | ColorFormat::Rgbx32F => [0; 4],
    }
}

/// The bits of a packed pixel that `mask` lets through.
pub fn mask_bits(format: ColorFormat, mask: ColorMask) -> u32 {
    let m = |on: bool, bits: u32| if on { bits } else { 0 };
    match format {
        ColorFormat::Rgba8 => m(mask.r, 0xff) | m(mask.g, 0xff00) | m(mask.b, 0xff_0000) | m(mask.a, 0xff00_0000),
        ColorFormat::Bgra8 => m(mask.b, 0xff) | m(mask.g, 0xff00) | m(mask.r, 0xff_0000) | m(mask.a, 0xff00_0000),
        ColorFormat::Rgb8 => m(mask.r, 0xff) | m(mask.g, 0xff00) | m(mask.b, 0xff_0000),
        ColorFormat::Rgb565 => m(mask.r, 0xf800) | m(mask.g, 0x07e0) | m(mask.b, 0x001f),
        ColorFormat::Rgba16
        | ColorFormat::Rgbx16
        | ColorFormat::Rgba16F
        | ColorFormat::Rgbx16F
        | ColorFormat::Rgba32F
        | ColorFormat::Rgbx32F => 0,
    }
}
