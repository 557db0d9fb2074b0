//! The deep colour formats ([`ColorFormat::Rgba16`], [`ColorFormat::Rgba32F`]),
//! as Mesa 22.3.6's llvmpipe renders OSMesa's `GL_UNSIGNED_SHORT` and
//! `GL_FLOAT` buffers (`docs/llvmpipe-facts.md`, "Deep colour buffers"):
//! the fragment colour stays f32 from the planes on; RGBA16 clamps it to
//! `[0, 1]` and converts it with llvmpipe's magic-number rounding, then
//! blends in 16-bit unorm integers (`lp_build_mul_norm`); RGBA32F keeps it
//! unclamped (GL's `GL_FIXED_ONLY` fragment clamping, unless the uniforms
//! say to clamp) and blends in f32. Logic op works on RGBA16's 16-bit
//! channels and does nothing on floats, as GL says.
//!
//! The JIT runs the same operations (`compile/deep.rs`), bit for bit
//! (`jit/tests/contract.rs`).

use crate::interp::{self, depth_stage, lanes, row_of, stencil_stage, BlendChannel};
use crate::key::{BlendEquation, BlendFactor, BlendKey, ColorFormat, FragmentKey, Stage};
use crate::shade::{self, saturate, Planes};
use crate::span::{FragmentSpan, SPAN_MAX};
use crate::target::Target;
use crate::texture::TextureSet;
use crate::uniforms::FragmentUniforms;

/// A float channel to 16-bit unorm as llvmpipe converts it
/// (`lp_build_clamped_float_to_unsigned_norm`, `lp_bld_conv.c`): clamped to
/// `[0, 1]` (NaN as 0), times `65535/65536`, plus `2^7`, whose f32 mantissa's
/// low 16 bits are then the value, rounded to nearest even.
#[inline]
pub fn unorm16(c: f32) -> u16 {
    const SCALE: f32 = (65535.0f64 / 65536.0) as f32;
    (saturate(c) * SCALE + 128.0).to_bits() as u16
}

/// A fragment colour channel clamped to `[0, 1]` as llvmpipe clamps it
/// (`lp_build_clamp_zero_one_nanzero`, `lp_bld_arit.c`): x86's `maxps(v, 0)`
/// then `minps(v, 1)`, so NaN and -0 become +0.
#[inline]
pub fn clamp_colour(v: f32) -> f32 {
    let v = if v > 0.0 { v } else { 0.0 };
    if v < 1.0 {
        v
    } else {
        1.0
    }
}

/// The NaN both back ends store for a float channel whatever NaN the
/// fragment's arithmetic made: x86's default NaN (`0xFFC00000`), what
/// llvmpipe stores for a NaN its own blend generates (`inf · 0`: checked
/// against llvmpipe, docs/llvmpipe-facts.md §43). NaN operands propagate
/// their sign and payload on x86 from whichever operand comes first, and the
/// two back ends (and LLVM, free to commute a product) order some operands
/// differently, so a NaN's bits are not kept; a clear stores its colour as given.
pub const CANONICAL_NAN: u32 = 0xFFC0_0000;

/// The bits a float channel stores: `v`'s, or [`CANONICAL_NAN`].
#[inline]
pub fn float_bits(v: f32) -> u32 {
    if v.is_nan() {
        CANONICAL_NAN
    } else {
        v.to_bits()
    }
}

/// The f32 bits of `v` converted to a half float as llvmpipe stores a
/// `GL_RGBA16F`/`GL_RGB16F` channel (`lp_build_float_to_half`,
/// `gallivm/lp_bld_conv.c`: `vcvtps2ph` with rounding mode 3, toward zero;
/// clears through `util_format`'s `_mesa_float_to_float16_rtz`, the same):
/// the mantissa cut to 10 bits, half denormals (below 2^-14) cut to
/// multiples of 2^-24 (llvmpipe keeps denormals on for half formats), finite
/// values past 65504 to ±65504 (round toward zero never overflows), ±inf kept,
/// NaN the canonical one (whose half is `0xFE00`, read back as the same f32).
#[inline]
pub fn half_bits(v: f32) -> u32 {
    const MIN_NORMAL: u32 = 0x3880_0000; // 2^-14
    const MAX_HALF: u32 = 0x477f_e000; // 65504
    let bits = float_bits(v);
    let abs = bits & 0x7fff_ffff;
    if abs < MIN_NORMAL {
        // `v · 2^24` and back are exact; the truncation keeps the sign (-0).
        ((v * 16_777_216.0).trunc() * (1.0 / 16_777_216.0)).to_bits()
    } else if abs > MAX_HALF && abs < 0x7f80_0000 {
        (bits & 0x8000_0000) | MAX_HALF
    } else {
        bits & 0xffff_e000
    }
}

/// A 16-bit unorm channel as a float (`v * (1 / 65535)`, `util_format`'s unpack).
#[inline]
pub fn unorm16_to_float(v: u16) -> f32 {
    f32::from(v) * (1.0 / 65535.0)
}

/// `a * b / 65535` as llvmpipe's `lp_build_mul_norm` computes it on 32-bit
/// lanes: `(t + (t >> 16) + 0x8000) >> 16` with `t = a * b`.
#[inline]
pub fn mul_unorm16(a: u16, b: u16) -> u16 {
    let t = u32::from(a) * u32::from(b);
    ((t + (t >> 16) + 0x8000) >> 16) as u16
}

/// The stored pixel at the start of `bytes` as RGBA channels: 16-bit values
/// widened, or f32 bits.
#[inline]
pub fn load(format: ColorFormat, bytes: &[u8]) -> [u32; 4] {
    if !format.is_deep() {
        return [0; 4];
    }
    if format.is_float() {
        std::array::from_fn(|c| {
            u32::from_ne_bytes([bytes[4 * c], bytes[4 * c + 1], bytes[4 * c + 2], bytes[4 * c + 3]])
        })
    } else {
        std::array::from_fn(|c| u32::from(u16::from_ne_bytes([bytes[2 * c], bytes[2 * c + 1]])))
    }
}

/// Stores channel `c` of a pixel (as [`load`] gives it) at the start of `bytes`.
#[inline]
pub fn store_channel(format: ColorFormat, bytes: &mut [u8], c: usize, v: u32) {
    if !format.is_deep() {
        return;
    }
    if format.is_float() {
        bytes[4 * c..4 * c + 4].copy_from_slice(&v.to_ne_bytes());
    } else {
        bytes[2 * c..2 * c + 2].copy_from_slice(&(v as u16).to_ne_bytes());
    }
}

/// The stored pixel as float RGBA.
#[inline]
pub fn to_float(format: ColorFormat, v: [u32; 4]) -> [f32; 4] {
    if format.is_float() {
        v.map(f32::from_bits)
    } else {
        v.map(|c| unorm16_to_float(c as u16))
    }
}

/// A float colour as the format stores it: [`unorm16`], the f32 bits
/// ([`float_bits`]: NaNs canonical) or a half's ([`half_bits`]); alpha 1
/// where the format stores none (what its fourth channel always holds).
#[inline]
pub fn from_float(format: ColorFormat, c: [f32; 4]) -> [u32; 4] {
    let mut v = c.map(|v| store_value(format, v));
    if !format.has_alpha() {
        v[3] = store_value(format, 1.0);
    }
    v
}

/// One channel of a fragment colour as the format stores it (see [`from_float`]).
#[inline]
pub fn store_value(format: ColorFormat, v: f32) -> u32 {
    if format.is_half() {
        half_bits(v)
    } else if format.is_float() {
        float_bits(v)
    } else {
        u32::from(unorm16(v))
    }
}

/// GL's blend in 16-bit unorm integers, llvmpipe's way for RGBA16: factors
/// in unorm16 ([`interp::factor`]), products by [`mul_unorm16`], sums and
/// differences saturated.
pub fn blend16(key: &BlendKey, src: [u16; 4], dst: [u16; 4], k: [u16; 4]) -> [u16; 4] {
    std::array::from_fn(|c| {
        let (sf, df, eq) = channel_blend(key, c);
        let s = mul_unorm16(src[c], interp::factor(sf, c, src, dst, k));
        let d = mul_unorm16(dst[c], interp::factor(df, c, src, dst, k));
        match eq {
            BlendEquation::Add => s.saturating_add(d),
            BlendEquation::Subtract => s.saturating_sub(d),
            BlendEquation::ReverseSubtract => d.saturating_sub(s),
            BlendEquation::Min => src[c].min(dst[c]),
            BlendEquation::Max => src[c].max(dst[c]),
        }
    })
}

/// GL's blend in f32, unclamped, llvmpipe's way for RGBA32F: `src · sf`
/// and `dst · df` rounded, then summed (`GL_ONE` multiplies by nothing:
/// `x · 1` is `x`); MIN and MAX as x86's `minps`/`maxps` of source and
/// destination (`lp_build_min`/`lp_build_max`, `lp_bld_blend.c`).
pub fn blend_f32(key: &BlendKey, src: [f32; 4], dst: [f32; 4], k: [f32; 4]) -> [f32; 4] {
    let term = |v: f32, f: BlendFactor, c: usize| match f {
        BlendFactor::One => v,
        _ => v * interp::factor(f, c, src, dst, k),
    };
    std::array::from_fn(|c| {
        let (sf, df, eq) = channel_blend(key, c);
        let (s, d) = (term(src[c], sf, c), term(dst[c], df, c));
        match eq {
            BlendEquation::Add => s + d,
            BlendEquation::Subtract => s - d,
            BlendEquation::ReverseSubtract => d - s,
            BlendEquation::Min => src[c].min_of(dst[c]),
            BlendEquation::Max => {
                if src[c] > dst[c] {
                    src[c]
                } else {
                    dst[c]
                }
            }
        }
    })
}

/// Channel `c`'s source and destination factors and equation (3 is alpha).
pub fn channel_blend(key: &BlendKey, c: usize) -> (BlendFactor, BlendFactor, BlendEquation) {
    if c < 3 {
        (key.src_rgb, key.dst_rgb, key.eq_rgb)
    } else {
        (key.src_alpha, key.dst_alpha, key.eq_alpha)
    }
}

/// The interpreter's run of `key`'s stages over one span into a deep-format
/// `t` (`interp::run_span` hands these formats here).
pub(crate) fn run_span(
    key: &FragmentKey,
    stages: &[Stage],
    (u, textures): (&FragmentUniforms, &TextureSet<'_>),
    (span, planes): (&FragmentSpan, &Planes),
    t: &mut Target<'_>,
) {
    let mut live = t.owned_mask(span);
    if live == 0 {
        return;
    }
    let format = key.color_format;
    let bpp = format.bytes_per_pixel();
    let (y, x0) = (span.y, span.x);
    // Unorm formats clamp fragment colours; floats only when asked (GL_FIXED_ONLY).
    let clamp = !format.is_float() || u.deep.clamp != 0;
    let clamped = |c: [f32; 4]| if clamp { c.map(clamp_colour) } else { c };
    let mut rgba = [[0f32; 4]; SPAN_MAX];
    for (i, c) in rgba.iter_mut().enumerate() {
        *c = [span.r[i], span.g[i], span.b[i], span.a[i]].map(|v| f32::from(v) * (1.0 / 255.0));
    }
    // The values to store, per channel (16-bit values or f32 bits), once packed.
    let mut out = [[0u32; 4]; SPAN_MAX];
    let mut blended = false;
    let mut z = span.z;
    let deep_u = &u.deep;
    let alpha_ref = f32::from_bits(deep_u.alpha_ref);
    let k = deep_u.blend_color.map(f32::from_bits);

    for stage in stages {
        match *stage {
            Stage::Shade(shade) => {
                let row = row_of(y, t.height());
                for i in lanes(live) {
                    let px = (x0 + i as u32) as f32;
                    let (c, d) = shade::fragment_f32(&shade, planes, (px, row), &u.fog, key.depth_format, textures);
                    if let Some(c) = c {
                        rgba[i] = c;
                    }
                    if let Some(d) = d {
                        z[i] = d;
                    }
                }
                for i in lanes(live) {
                    rgba[i] = clamped(rgba[i]);
                }
            }
            Stage::Scissor => {
                let [sx0, sy0, sx1, sy1] = u.scissor;
                let yi = i64::from(y);
                for i in lanes(live) {
                    let xi = i64::from(x0) + i as i64;
                    let inside =
                        xi >= i64::from(sx0) && xi < i64::from(sx1) && yi >= i64::from(sy0) && yi < i64::from(sy1);
                    if !inside {
                        live &= !(1 << i);
                    }
                }
            }
            Stage::AlphaTest(func) => {
                for i in lanes(live) {
                    if !func.test(rgba[i][3], alpha_ref) {
                        live &= !(1 << i);
                    }
                }
            }
            Stage::AlphaCoverage(c) => {
                for i in lanes(live) {
                    if let Some(q) = c.quarters {
                        if !crate::key::AlphaCoverage::keeps(rgba[i][3], q) {
                            live &= !(1 << i);
                        }
                    }
                    if c.to_one {
                        rgba[i][3] = 1.0;
                    }
                }
            }
            Stage::StencilTest { stencil, depth_on } => stencil_stage(stencil, depth_on, u, (x0, y), &mut live, t),
            Stage::DepthTest { depth, stencil } => depth_stage(depth, stencil, u, (x0, y, &z), &mut live, t),
            Stage::Count => t.add_samples_passed(u64::from(live.count_ones())),
            Stage::Blend(blend) => {
                let off0 = t.color_offset(x0, y);
                let color = t.color();
                for i in lanes(live) {
                    let dst = load(format, &color[off0 + i * bpp..]);
                    out[i] = if format.is_float() {
                        let v = blend_f32(&blend, rgba[i], dst.map(f32::from_bits), k);
                        v.map(|v| store_value(format, v))
                    } else {
                        let src = rgba[i].map(unorm16);
                        let k = k.map(unorm16);
                        blend16(&blend, src, dst.map(|v| v as u16), k).map(u32::from)
                    };
                }
                blended = true;
            }
            Stage::Pack { .. } => {
                if !blended {
                    for i in lanes(live) {
                        out[i] = from_float(format, rgba[i]);
                    }
                }
            }
            Stage::LogicOp(op) => {
                if !format.is_float() {
                    let off0 = t.color_offset(x0, y);
                    let color = t.color();
                    for i in lanes(live) {
                        let dst = load(format, &color[off0 + i * bpp..]);
                        for c in 0..4 {
                            out[i][c] = op.apply(out[i][c], dst[c]) & 0xffff;
                        }
                    }
                }
            }
            Stage::ColorWrite(mask) => {
                let keep = [mask.r, mask.g, mask.b, mask.a];
                let off0 = t.color_offset(x0, y);
                let color = t.color_mut();
                for i in lanes(live) {
                    let px = &mut color[off0 + i * bpp..];
                    for c in 0..4 {
                        if keep[c] {
                            store_channel(format, px, c, out[i][c]);
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm16_rounds_to_nearest_and_saturates() {
        assert_eq!(unorm16(0.0), 0);
        assert_eq!(unorm16(1.0), 65535);
        assert_eq!(unorm16(2.0), 65535);
        assert_eq!(unorm16(-1.0), 0);
        assert_eq!(unorm16(f32::NAN), 0);
        assert_eq!(unorm16(0.5), 32768);
        for v in (0..=65535u16).step_by(7) {
            assert_eq!(unorm16(unorm16_to_float(v)), v);
        }
        assert_eq!(mul_unorm16(65535, 65535), 65535);
        assert_eq!(mul_unorm16(65535, 1234), 1234);
        assert_eq!(mul_unorm16(0, 65535), 0);
    }

    /// `half_bits` against round toward zero onto the half grid, worked in
    /// f64: every half is kept, anything between two halves goes to the one
    /// nearer zero, past 65504 stays 65504, infinities stay, NaN is canonical.
    #[test]
    fn half_bits_truncates_onto_the_half_grid() {
        let reference = |x: f32| -> f32 {
            let (s, a) = (x.signum() as f64, f64::from(x.abs()));
            if a.is_infinite() {
                return x;
            }
            let e = a.log2().floor().max(-14.0);
            let ulp = (e - 10.0).exp2();
            let v = ((a / ulp).floor() * ulp).min(65504.0);
            (s * v) as f32
        };
        let mut bits = 0x1234_5678u32;
        let mut checked = 0;
        for i in 0..200_000u32 {
            bits = bits.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            // Half the draws near the half range (exponents 2^-26 .. 2^17).
            let x = if i % 2 == 0 {
                f32::from_bits(bits)
            } else {
                f32::from_bits((bits & 0x807f_ffff) | ((100 + (bits >> 23) % 44) << 23))
            };
            if x.is_nan() {
                assert_eq!(half_bits(x), CANONICAL_NAN);
                continue;
            }
            assert_eq!(half_bits(x), reference(x).to_bits(), "{x:e} ({:#x})", x.to_bits());
            checked += 1;
        }
        assert!(checked > 190_000);
        for (x, want) in [
            (0.3f32, 1228.0 / 4096.0),
            (0.6, 2456.0 / 4096.0),
            (0.9, 3686.0 / 4096.0),
            (65519.0, 65504.0),
            (1e9, 65504.0),
            (-70000.0, -65504.0),
            (f32::INFINITY, f32::INFINITY),
            (2.0e-8, 0.0),
            (6.0e-8, 5.9604645e-8),
            (-0.0, -0.0),
        ] {
            assert_eq!(f32::from_bits(half_bits(x)), want, "{x}");
        }
        assert_eq!(half_bits(-1e-9), 0x8000_0000);
    }
}
