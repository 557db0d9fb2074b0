//! Formats: the client's (`PixelFormat` × `PixelType`), the GL internal
//! formats, and how each internal format is stored — at the precision Mesa
//! 22.3.6 gives it on llvmpipe (`docs/llvmpipe-facts.md` §18), expanded to a
//! [`TexelFormat`] the sampler reads fast.

use super::jit::{BaseFormat, TexelFormat};

/// A client pixel format (`format` of `glTexImage`, `glGetTexImage`).
/// `GL_INTENSITY` is not one (GL 1.5 table 3.6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelFormat {
    Rgba,
    Rgb,
    Bgra,
    Bgr,
    Luminance,
    LuminanceAlpha,
    Alpha,
    Red,
    Green,
    Blue,
    DepthComponent,
    /// `GL_DEPTH_STENCIL` (EXT_packed_depth_stencil): depth in slot 0, stencil in slot 1.
    DepthStencil,
}

/// A client pixel type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelType {
    UnsignedByte,
    Byte,
    UnsignedShort,
    Short,
    UnsignedInt,
    Int,
    Float,
    UnsignedByte332,
    UnsignedByte233Rev,
    UnsignedShort565,
    UnsignedShort565Rev,
    UnsignedShort4444,
    UnsignedShort4444Rev,
    UnsignedShort5551,
    UnsignedShort1555Rev,
    UnsignedInt8888,
    UnsignedInt8888Rev,
    UnsignedInt1010102,
    UnsignedInt2101010Rev,
    /// `GL_UNSIGNED_INT_24_8`: depth in the top 24 bits, stencil in the low 8.
    UnsignedInt248,
    /// `GL_FLOAT_32_UNSIGNED_INT_24_8_REV` (ARB_depth_buffer_float): depth as
    /// an f32, then a word with stencil in its low 8 bits (two 4-byte elements).
    Float32UnsignedInt248Rev,
}

/// A GL internal format (`internalformat` of `glTexImage`, `glCopyTexImage`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InternalFormat {
    /// GL 1.0's component counts 1–4 (luminance, luminance-alpha, RGB, RGBA).
    One,
    Two,
    Three,
    Four,
    Alpha,
    Alpha4,
    Alpha8,
    Alpha12,
    Alpha16,
    Luminance,
    Luminance4,
    Luminance8,
    Luminance12,
    Luminance16,
    LuminanceAlpha,
    Luminance4Alpha4,
    Luminance6Alpha2,
    Luminance8Alpha8,
    Luminance12Alpha4,
    Luminance12Alpha12,
    Luminance16Alpha16,
    Intensity,
    Intensity4,
    Intensity8,
    Intensity12,
    Intensity16,
    Rgb,
    R3G3B2,
    Rgb4,
    Rgb5,
    Rgb8,
    Rgb10,
    Rgb12,
    Rgb16,
    Rgba,
    Rgba2,
    Rgba4,
    Rgb5A1,
    Rgba8,
    Rgb10A2,
    Rgba12,
    Rgba16,
    DepthComponent,
    DepthComponent16,
    DepthComponent24,
    DepthComponent32,
    /// EXT_packed_depth_stencil: depth and stencil, stored as llvmpipe's
    /// `Z24_UNORM_S8_UINT` (24 depth bits, 8 stencil bits).
    DepthStencil,
    Depth24Stencil8,
    /// ARB_depth_buffer_float: 32-bit float depth (llvmpipe's `Z32_FLOAT`),
    /// and with stencil (`Z32_FLOAT_S8X24_UINT`).
    DepthComponent32F,
    Depth32FStencil8,
    Srgb,
    Srgb8,
    SrgbAlpha,
    Srgb8Alpha8,
    Sluminance,
    Sluminance8,
    SluminanceAlpha,
    Sluminance8Alpha8,
    /// GL 1.3's generic compressed formats. llvmpipe compresses four of them
    /// (LATC/DXT); softgl stores them uncompressed at 8 bits (§18).
    CompressedAlpha,
    CompressedLuminance,
    CompressedLuminanceAlpha,
    CompressedIntensity,
    CompressedRgb,
    CompressedRgba,
}

/// How an internal format is stored: the bits per channel of the format Mesa
/// chooses on llvmpipe (GL_TEXTURE_*_SIZE), in RGBA order (luminance and
/// intensity in the red slot), or the depth bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Storage {
    pub base: BaseFormat,
    /// Bits of R, G, B, A (0 for a channel the base format lacks); depth formats: `[d, 0, 0, 0]`.
    pub bits: [u32; 4],
    pub srgb: bool,
    /// Float depth (`GL_DEPTH_COMPONENT32F`): the texels are the stored floats.
    pub float: bool,
}

impl Storage {
    /// Whether Mesa's format is an array format (every channel 8 or every
    /// channel 16 bits): conversions into it are per channel, never through
    /// a packed-format path (`main/format_utils.c` `_mesa_format_convert`).
    pub fn is_array(&self) -> bool {
        let bits = self.used_bits();
        bits.clone().all(|b| b == 8) || bits.clone().all(|b| b == 16)
    }

    fn used_bits(&self) -> impl Iterator<Item = u32> + Clone + '_ {
        self.bits.iter().copied().filter(|&b| b > 0)
    }

    /// The largest channel (`_mesa_get_format_max_bits`).
    pub fn max_bits(&self) -> u32 {
        self.used_bits().max().unwrap_or(0)
    }

    /// The layout texels take in memory.
    pub fn texel_format(&self) -> TexelFormat {
        if self.base == BaseFormat::Depth {
            TexelFormat::Depth32F
        } else if self.srgb {
            TexelFormat::Srgba8
        } else if self.max_bits() > 8 {
            TexelFormat::Rgba16
        } else {
            TexelFormat::Rgba8
        }
    }
}

impl InternalFormat {
    /// The GL base internal format.
    pub fn base(self) -> BaseFormat {
        self.storage().base
    }

    /// The internal format `GL_TEXTURE_INTERNAL_FORMAT` reports: the one
    /// asked for, except the generic compressed formats, which softgl stores
    /// uncompressed and reports as their base format.
    pub fn reported(self) -> InternalFormat {
        match self {
            InternalFormat::CompressedAlpha => InternalFormat::Alpha,
            InternalFormat::CompressedLuminance => InternalFormat::Luminance,
            InternalFormat::CompressedLuminanceAlpha => InternalFormat::LuminanceAlpha,
            InternalFormat::CompressedIntensity => InternalFormat::Intensity,
            InternalFormat::CompressedRgb => InternalFormat::Rgb,
            InternalFormat::CompressedRgba => InternalFormat::Rgba,
            f => f,
        }
    }

    /// The storage Mesa 22.3.6 chooses on llvmpipe, as `glGetTexLevelParameter`
    /// reports its sizes (probed, `docs/llvmpipe-facts.md` §18).
    pub fn storage(self) -> Storage {
        use BaseFormat as B;
        use InternalFormat as F;
        let (base, bits, srgb) = match self {
            F::Alpha | F::Alpha4 | F::Alpha8 | F::CompressedAlpha => (B::Alpha, [0, 0, 0, 8], false),
            F::Alpha12 | F::Alpha16 => (B::Alpha, [0, 0, 0, 16], false),
            F::One | F::Luminance | F::Luminance4 | F::Luminance8 | F::CompressedLuminance => {
                (B::Luminance, [8, 0, 0, 0], false)
            }
            F::Luminance12 | F::Luminance16 => (B::Luminance, [16, 0, 0, 0], false),
            F::Two | F::LuminanceAlpha | F::Luminance6Alpha2 | F::Luminance8Alpha8 | F::CompressedLuminanceAlpha => {
                (B::LuminanceAlpha, [8, 0, 0, 8], false)
            }
            F::Luminance4Alpha4 => (B::LuminanceAlpha, [4, 0, 0, 4], false),
            F::Luminance12Alpha4 | F::Luminance12Alpha12 | F::Luminance16Alpha16 => {
                (B::LuminanceAlpha, [16, 0, 0, 16], false)
            }
            F::Intensity | F::Intensity4 | F::Intensity8 | F::CompressedIntensity => {
                (B::Intensity, [8, 0, 0, 0], false)
            }
            F::Intensity12 | F::Intensity16 => (B::Intensity, [16, 0, 0, 0], false),
            F::Three | F::Rgb | F::Rgb8 | F::CompressedRgb => (B::Rgb, [8, 8, 8, 0], false),
            F::R3G3B2 => (B::Rgb, [3, 3, 2, 0], false),
            F::Rgb4 => (B::Rgb, [4, 4, 4, 0], false),
            F::Rgb5 => (B::Rgb, [5, 5, 5, 0], false),
            F::Rgb10 => (B::Rgb, [10, 10, 10, 0], false),
            F::Rgb12 | F::Rgb16 => (B::Rgb, [16, 16, 16, 0], false),
            F::Four | F::Rgba | F::Rgba8 | F::CompressedRgba => (B::Rgba, [8, 8, 8, 8], false),
            F::Rgba2 | F::Rgba4 => (B::Rgba, [4, 4, 4, 4], false),
            F::Rgb5A1 => (B::Rgba, [5, 5, 5, 1], false),
            F::Rgb10A2 => (B::Rgba, [10, 10, 10, 2], false),
            F::Rgba12 | F::Rgba16 => (B::Rgba, [16, 16, 16, 16], false),
            F::DepthComponent | F::DepthComponent24 | F::DepthStencil | F::Depth24Stencil8 => {
                (B::Depth, [24, 0, 0, 0], false)
            }
            F::DepthComponent16 => (B::Depth, [16, 0, 0, 0], false),
            F::DepthComponent32 => (B::Depth, [32, 0, 0, 0], false),
            F::DepthComponent32F | F::Depth32FStencil8 => {
                return Storage {
                    base: B::Depth,
                    bits: [32, 0, 0, 0],
                    srgb: false,
                    float: true,
                }
            }
            F::Srgb | F::Srgb8 => (B::Rgb, [8, 8, 8, 0], true),
            F::SrgbAlpha | F::Srgb8Alpha8 => (B::Rgba, [8, 8, 8, 8], true),
            F::Sluminance | F::Sluminance8 => (B::Luminance, [8, 0, 0, 0], true),
            F::SluminanceAlpha | F::Sluminance8Alpha8 => (B::LuminanceAlpha, [8, 0, 0, 8], true),
        };
        Storage {
            base,
            bits,
            srgb,
            float: false,
        }
    }

    /// The stencil bits of a packed depth-stencil format (0 for the others):
    /// kept in a plane of bytes after the depth texels ([`TexImage::stencil_offset`](super::TexImage::stencil_offset)).
    pub fn stencil_bits(self) -> u32 {
        match self {
            InternalFormat::DepthStencil | InternalFormat::Depth24Stencil8 | InternalFormat::Depth32FStencil8 => 8,
            _ => 0,
        }
    }
}

/// How a client type stores one component (or one packed pixel).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TypeKind {
    /// Unsigned normalized integers of this many bits.
    Unsigned(u32),
    /// Signed normalized integers of this many bits.
    Signed(u32),
    Float,
    /// One packed pixel of this many bytes; its fields (shift, bits) in component order.
    Packed(u32, &'static [(u32, u32)]),
}

impl PixelType {
    pub fn kind(self) -> TypeKind {
        use PixelType as T;
        use TypeKind::{Packed, Signed, Unsigned};
        // Fields listed in the order they go to the format's components: (shift, bits).
        match self {
            T::UnsignedByte => Unsigned(8),
            T::Byte => Signed(8),
            T::UnsignedShort => Unsigned(16),
            T::Short => Signed(16),
            T::UnsignedInt => Unsigned(32),
            T::Int => Signed(32),
            T::Float | T::Float32UnsignedInt248Rev => TypeKind::Float,
            T::UnsignedByte332 => Packed(1, &[(5, 3), (2, 3), (0, 2)]),
            T::UnsignedByte233Rev => Packed(1, &[(0, 3), (3, 3), (6, 2)]),
            T::UnsignedShort565 => Packed(2, &[(11, 5), (5, 6), (0, 5)]),
            T::UnsignedShort565Rev => Packed(2, &[(0, 5), (5, 6), (11, 5)]),
            T::UnsignedShort4444 => Packed(2, &[(12, 4), (8, 4), (4, 4), (0, 4)]),
            T::UnsignedShort4444Rev => Packed(2, &[(0, 4), (4, 4), (8, 4), (12, 4)]),
            T::UnsignedShort5551 => Packed(2, &[(11, 5), (6, 5), (1, 5), (0, 1)]),
            T::UnsignedShort1555Rev => Packed(2, &[(0, 5), (5, 5), (10, 5), (15, 1)]),
            T::UnsignedInt8888 => Packed(4, &[(24, 8), (16, 8), (8, 8), (0, 8)]),
            T::UnsignedInt8888Rev => Packed(4, &[(0, 8), (8, 8), (16, 8), (24, 8)]),
            T::UnsignedInt1010102 => Packed(4, &[(22, 10), (12, 10), (2, 10), (0, 2)]),
            T::UnsignedInt2101010Rev => Packed(4, &[(0, 10), (10, 10), (20, 10), (30, 2)]),
            T::UnsignedInt248 => Packed(4, &[(8, 24), (0, 8)]),
        }
    }

    /// Bytes of one element (a component, or a whole packed pixel).
    pub fn element_bytes(self) -> usize {
        match self.kind() {
            TypeKind::Unsigned(b) | TypeKind::Signed(b) => b as usize / 8,
            TypeKind::Float => 4,
            TypeKind::Packed(n, _) => n as usize,
        }
    }
}

impl PixelFormat {
    /// The format's components as RGBA slots (0–3), luminance as slot 0 and
    /// depth as slot 0.
    pub fn components(self) -> &'static [usize] {
        match self {
            PixelFormat::Rgba => &[0, 1, 2, 3],
            PixelFormat::Rgb => &[0, 1, 2],
            PixelFormat::Bgra => &[2, 1, 0, 3],
            PixelFormat::Bgr => &[2, 1, 0],
            PixelFormat::Luminance | PixelFormat::Red | PixelFormat::DepthComponent => &[0],
            PixelFormat::DepthStencil => &[0, 1],
            PixelFormat::LuminanceAlpha => &[0, 3],
            PixelFormat::Alpha => &[3],
            PixelFormat::Green => &[1],
            PixelFormat::Blue => &[2],
        }
    }

    /// `GL_INVALID_OPERATION` for a packed type this format cannot take
    /// (Mesa `main/glformats.c` `_mesa_error_check_format_and_type`).
    pub fn accepts(self, ty: PixelType) -> bool {
        use PixelType as T;
        match ty {
            T::UnsignedByte332 | T::UnsignedByte233Rev | T::UnsignedShort565 | T::UnsignedShort565Rev => {
                self == PixelFormat::Rgb
            }
            T::UnsignedShort4444
            | T::UnsignedShort4444Rev
            | T::UnsignedInt8888
            | T::UnsignedInt8888Rev
            | T::UnsignedShort5551
            | T::UnsignedShort1555Rev
            | T::UnsignedInt1010102
            | T::UnsignedInt2101010Rev => matches!(self, PixelFormat::Rgba | PixelFormat::Bgra),
            T::UnsignedInt248 | T::Float32UnsignedInt248Rev => self == PixelFormat::DepthStencil,
            _ => true,
        }
    }

    /// `GL_INVALID_ENUM` (checked before [`accepts`](Self::accepts)): GL 3.0
    /// §4.3.1, `GL_DEPTH_STENCIL` takes only `GL_UNSIGNED_INT_24_8` (Mesa
    /// `_mesa_error_check_format_and_type`).
    pub fn type_enum_ok(self, ty: PixelType) -> bool {
        self != PixelFormat::DepthStencil
            || matches!(ty, PixelType::UnsignedInt248 | PixelType::Float32UnsignedInt248Rev)
    }

    /// Depth or depth-stencil (they agree with the same internal formats:
    /// Mesa `texture_formats_agree`).
    pub fn is_depth(self) -> bool {
        matches!(self, PixelFormat::DepthComponent | PixelFormat::DepthStencil)
    }

    /// Bytes one pixel of this format and `ty` takes.
    pub fn pixel_bytes(self, ty: PixelType) -> usize {
        match ty.kind() {
            TypeKind::Packed(n, _) => n as usize,
            _ => self.components().len() * ty.element_bytes(),
        }
    }
}

/// Mesa's `_mesa_unorm_to_unorm` (`util/format/format_utils.h`): narrowing
/// rounds to nearest, widening replicates bits.
pub fn unorm_to_unorm(x: u32, src_bits: u32, dst_bits: u32) -> u32 {
    let max = |b: u32| ((1u64 << b) - 1) as u32;
    match src_bits.cmp(&dst_bits) {
        std::cmp::Ordering::Less => {
            let rem = dst_bits % src_bits;
            let extra = if rem != 0 { x >> (src_bits - rem) } else { 0 };
            x.wrapping_mul(max(dst_bits) / max(src_bits)).wrapping_add(extra)
        }
        std::cmp::Ordering::Greater => {
            let half = (1u64 << (src_bits - 1)) - 1;
            ((u64::from(x) * u64::from(max(dst_bits)) + half) / u64::from(max(src_bits))) as u32
        }
        std::cmp::Ordering::Equal => x,
    }
}

/// Mesa's `_mesa_float_to_unorm`: clamps, then rounds `x · (2^bits − 1)`
/// (in f32) to nearest even. NaN stores 0.
pub fn float_to_unorm(x: f32, bits: u32) -> u32 {
    let max = ((1u64 << bits) - 1) as u32;
    if x < 0.0 {
        0
    } else if x > 1.0 {
        max
    } else if x.is_nan() {
        0
    } else {
        // `_mesa_i64roundevenf`, then the C cast to unsigned.
        (x * max as f32).round_ties_even() as i64 as u32
    }
}

/// Mesa's `_mesa_unorm_to_float`: `x · (1 / (2^bits − 1))` in f32.
pub fn unorm_to_float(x: u32, bits: u32) -> f32 {
    x as f32 * (1.0 / ((1u64 << bits) - 1) as f32)
}

/// Mesa's `_mesa_snorm_to_float`.
pub fn snorm_to_float(x: i32, bits: u32) -> f32 {
    let max = ((1i64 << (bits - 1)) - 1) as i32;
    if x <= -max {
        -1.0
    } else {
        x as f32 * (1.0 / max as f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm_widening_replicates_and_narrowing_rounds() {
        assert_eq!(unorm_to_unorm(1, 5, 8), 8);
        assert_eq!(unorm_to_unorm(3, 5, 8), 24);
        assert_eq!(unorm_to_unorm(31, 5, 8), 255);
        assert_eq!(unorm_to_unorm(63, 6, 8), 255);
        assert_eq!(unorm_to_unorm(7, 3, 8), 255);
        assert_eq!(unorm_to_unorm(1, 1, 8), 255);
        assert_eq!(unorm_to_unorm(200, 8, 10), 803);
        assert_eq!(unorm_to_unorm(255, 8, 32), u32::MAX);
        assert_eq!(unorm_to_unorm(8, 8, 4), 0);
        assert_eq!(unorm_to_unorm(9, 8, 4), 1);
        assert_eq!(unorm_to_unorm(u32::MAX, 32, 8), 255);
        assert_eq!(unorm_to_unorm(803, 10, 16), 803 * 64 + (803 >> 4));
    }

    #[test]
    fn float_to_unorm_rounds_ties_to_even_and_clamps() {
        assert_eq!(float_to_unorm(0.5, 8), 128);
        assert_eq!(float_to_unorm(0.5, 4), 8);
        assert_eq!(float_to_unorm(-0.1, 8), 0);
        assert_eq!(float_to_unorm(7.0, 8), 255);
        assert_eq!(float_to_unorm(f32::NAN, 8), 0);
        assert_eq!(float_to_unorm(1.5 / 255.0, 8), 2);
    }
}
