//! The scalar meaning of the x86 instructions gallivm's sampling code
//! compiles to on this host (SSE4.1, AVX2, FMA): conversions that give
//! `i32::MIN` out of range, `minps`/`maxps` that return the second operand
//! when either is NaN, and the unorm conversions (`docs/llvmpipe-facts.md` §16).

/// `cvttps2dq` (`LLVMBuildFPToSI`, `lp_build_itrunc`): truncation toward
/// zero; NaN and values outside the i32 range give `i32::MIN`.
#[inline]
pub fn itrunc(x: f32) -> i32 {
    if x.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&x) {
        i32::MIN
    } else {
        x as i32
    }
}

/// `cvtps2dq` under the default rounding mode (`lp_build_iround`): round
/// half to even; NaN and out-of-range values give `i32::MIN`.
#[inline]
pub fn iround(x: f32) -> i32 {
    itrunc(x.round_ties_even())
}

/// `roundps` toward −∞ then `cvttps2dq` (`lp_build_ifloor` with SSE4.1).
#[inline]
pub fn ifloor(x: f32) -> i32 {
    itrunc(x.floor())
}

/// `lp_build_ifloor_fract`: `floor(x)` as an integer and `x − floor(x)`.
#[inline]
pub fn ifloor_fract(x: f32) -> (i32, f32) {
    let f = x.floor();
    (itrunc(f), x - f)
}

/// `minps(a, b)`: `a < b ? a : b` (the second operand when unordered).
#[inline]
pub fn minps(a: f32, b: f32) -> f32 {
    if a < b {
        a
    } else {
        b
    }
}

/// `maxps(a, b)`: `a > b ? a : b` (the second operand when unordered).
#[inline]
pub fn maxps(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else {
        b
    }
}

/// `lp_build_fract`: `x − floor(x)`.
#[inline]
pub fn fract(x: f32) -> f32 {
    x - x.floor()
}

/// `lp_build_fract_safe`: [`fract`] kept below 1 (NaN becomes the bound).
#[inline]
pub fn fract_safe(x: f32) -> f32 {
    let f = fract(x);
    let max = 1.0 - 1.0 / (1u32 << 24) as f32;
    if f < max {
        f
    } else {
        max
    }
}

/// `lp_build_unsigned_norm_to_float` for 8 bits: `v · f32(1/255)`.
#[inline]
pub fn unorm8_to_float(v: u8) -> f32 {
    f32::from(v) * (1.0f64 / 255.0) as f32
}

/// `lp_build_unsigned_norm_to_float` for 16 bits: `v · f32(1/65535)`.
#[inline]
pub fn unorm16_to_float(v: u16) -> f32 {
    f32::from(v) * (1.0f64 / 65535.0) as f32
}

/// `lp_build_srgb_to_linear` for an 8-bit channel: not the exact sRGB
/// curve but gallivm's approximation, `v / (12.6·255)` up to 15 and the
/// cubic `((0.3012·x + 0.6935)·x + 0.0030)·x + 0.0023` (coefficients
/// scaled by powers of 1/255 in f32, evaluated with fused multiply-adds as
/// `lp_build_polynomial` orders them) above.
///
/// Read from a table of the 256 values made on first use: the cubic's
/// three fused multiply-adds are libm `fmaf` calls on this build (baseline
/// x86-64), and the reference sampler decodes every channel of every texel
/// it filters. `osmesa/bench/shadow_lookup.c srgb` on the quick tier (both
/// units through the callout, 320×240 4×, callgrind, frames 3 minus 1):
/// 1362 → 1062 instructions a sample (the f32 lerps stay libm calls: the
/// same bits computed inline in f64, rounded to odd, took more instructions).
pub fn srgb8_to_linear(v: u8) -> f32 {
    static TABLE: std::sync::OnceLock<[f32; 256]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|v| srgb8_curve(v as u8)))[usize::from(v)]
}

/// [`srgb8_to_linear`] computed.
fn srgb8_curve(v: u8) -> f32 {
    let x = f32::from(v);
    if x <= 15.0 {
        return x * (1.0f32 / (12.6f32 * 255.0f32));
    }
    let c = [
        0.0023f32,
        0.0030f32 / 255.0f32,
        0.6935f32 / (255.0f32 * 255.0f32),
        0.3012f32 / (255.0f32 * 255.0f32 * 255.0f32),
    ];
    let x2 = x * x;
    let odd = x2.mul_add(c[3], c[1]);
    let even = x2.mul_add(c[2], c[0]);
    odd.mul_add(x, even)
}

/// The 8.8 fixed-point lerp of `lp_build_lerp` on unorm8 with prescaled
/// weights (`pmulhrsw` of the weight and `(b − a) << 7`, then a byte add):
/// `a + ((w·(b − a) + 128) >> 8)`, weight `w` in 0..=255.
#[inline]
pub fn lerp8(w: u8, a: u8, b: u8) -> u8 {
    let delta = i32::from(b) - i32::from(a);
    let step = (i32::from(w) * delta + 128) >> 8;
    (i32::from(a) + step) as u8
}

/// The float lerp of `lp_build_lerp`: `fma(w, b − a, a)` (`llvm.fmuladd`,
/// fused on this host).
#[inline]
pub fn lerp(w: f32, a: f32, b: f32) -> f32 {
    w.mul_add(b - a, a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_follow_the_x86_instructions() {
        assert_eq!(itrunc(-1.5), -1);
        assert_eq!(itrunc(f32::NAN), i32::MIN);
        assert_eq!(itrunc(3e9), i32::MIN);
        assert_eq!(itrunc(-3e9), i32::MIN);
        assert_eq!(iround(2.5), 2);
        assert_eq!(iround(3.5), 4);
        assert_eq!(iround(-0.5), 0);
        assert_eq!(ifloor(-0.25), -1);
        assert_eq!(ifloor_fract(-0.25), (-1, 0.75));
        assert_eq!(minps(f32::NAN, 1.0), 1.0);
        assert!(minps(1.0, f32::NAN).is_nan());
        assert_eq!(maxps(f32::NAN, 0.0), 0.0);
        assert_eq!(fract_safe(-1e-9), 0.99999994);
    }

    #[test]
    fn lerp8_rounds_half_up_in_steps_of_1_256() {
        // (w·(b−a) + 128) >> 8 computed by hand.
        assert_eq!(lerp8(0, 10, 250), 10);
        assert_eq!(lerp8(255, 0, 255), 254); // 65025 + 128 = 65153 >> 8 = 254
        assert_eq!(lerp8(128, 0, 255), 128); // 32640 + 128 = 32768 >> 8 = 128
        assert_eq!(lerp8(128, 0, 1), 1); // 128 + 128 = 256 >> 8 = 1
        assert_eq!(lerp8(127, 0, 1), 0);
        assert_eq!(lerp8(128, 1, 0), 1); // −128 + 128 = 0 >> 8 = 0
        assert_eq!(lerp8(129, 1, 0), 0); // −129 + 128 = −1 >> 8 = −1
        assert_eq!(lerp8(64, 200, 100), 175); // −6400 + 128 = −6272 >> 8 = −25
    }

    #[test]
    fn unorm_and_srgb_conversions() {
        assert_eq!(unorm8_to_float(255), 1.0);
        assert_eq!(unorm8_to_float(0), 0.0);
        assert_eq!(unorm16_to_float(65535), 1.0);
        // sRGB: exact curve 0.0 / 0.00455 / 0.2140 / 1.0; the approximation
        // stays within 0.35/255 of it above 15 and is 15/3213 at 15.
        assert_eq!(srgb8_to_linear(0), 0.0);
        assert_eq!(srgb8_to_linear(15), 15.0 * (1.0f32 / 3213.0f32));
        for v in 0..=255u8 {
            assert_eq!(srgb8_to_linear(v).to_bits(), srgb8_curve(v).to_bits());
        }
        for v in 16..=255u8 {
            let c = f64::from(v) / 255.0;
            let exact = ((c + 0.055) / 1.055).powf(2.4);
            let got = f64::from(srgb8_to_linear(v));
            assert!((got - exact).abs() < 0.36 / 255.0, "{v}: {got} vs {exact}");
        }
    }
}
