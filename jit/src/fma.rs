//! A fused multiply-add of f32 values, `a·b + c` rounded once: the same bits
//! as [`f32::mul_add`], without its call (the reference stages' copy of
//! `src/geometry/fma.rs`, which has the reasoning in full).
//!
//! The crate is built for baseline x86-64, where `f32::mul_add` is a call
//! to the runtime's `fmaf` (which dispatches to the FMA instruction through
//! a function pointer, `fmaf_with_fma`), and the registers live across it
//! are saved and reloaded around each call. `#[target_feature(enable =
//! "fma")]` would need `unsafe` at the call. So the sum is computed in f64,
//! inline: the product of two f32 values is exact in f64, and the f64 sum,
//! rounded once to f32, is the correctly rounded result unless it lands
//! exactly on a midpoint between two f32 values after an inexact f64 sum
//! (TwoSum tells) or below f32's normal range; those rare cases, and NaN,
//! take `f32::mul_add`. Tested against `f32::mul_add` on random bits,
//! near-cancellations, midpoints and special values.
//!
//! The reference sampler evaluates its coordinates' planes with it
//! (`crate::shade::Planes::at`: ten a pixel, forty a quad): in MuJoCo's
//! light passes (`perf`, 320×240, 1 thread) `fmaf` and `fmaf_with_fma` were
//! 3.7% of the frame, mostly from `crate::shade::tex_coords`.

/// `a·b + c` with one rounding, bit for bit [`f32::mul_add`].
#[inline(always)]
pub fn fma(a: f32, b: f32, c: f32) -> f32 {
    let xy = f64::from(a) * f64::from(b);
    let c = f64::from(c);
    let r = xy + c;
    let bits = r.to_bits();
    let exp = (bits >> 52) & 0x7ff;
    // In f32's normal range (897: the biased f64 exponent of 2^-126) and off
    // an f32 midpoint (f64 bits ending in a one and 28 zeros), or on one
    // with an exact f64 sum, `r` rounds as the exact sum does.
    let normal = (897..0x7ff).contains(&exp);
    if normal && (bits & 0x1fff_ffff != 0x1000_0000 || two_sum_error(xy, c, r) == 0.0) {
        r as f32
    } else {
        rare(a, b, c, r)
    }
}

/// [`fma`] off its common path: an infinite sum (of infinite operands) is
/// exact; anything else (an inexact sum on a midpoint, a result below f32's
/// normal range, NaN) takes `f32::mul_add`.
#[cold]
#[inline(never)]
fn rare(a: f32, b: f32, c: f64, r: f64) -> f32 {
    if r.is_infinite() {
        r as f32
    } else {
        a.mul_add(b, c as f32)
    }
}

/// Knuth's TwoSum: `(a + b) − r` exactly, `r` being `a + b` rounded (no overflow).
#[inline(always)]
fn two_sum_error(a: f64, b: f64, r: f64) -> f64 {
    let bb = r - a;
    (a - (r - bb)) + (b - bb)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(a: f32, b: f32, c: f32) {
        let want = a.mul_add(b, c);
        let got = fma(a, b, c);
        assert!(
            want.to_bits() == got.to_bits() || (want.is_nan() && got.is_nan()),
            "fma({a:e}, {b:e}, {c:e}) = {got:e}, want {want:e}"
        );
    }

    /// A small xorshift generator: the test needs no crate.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 16) as u32
        }
    }

    #[test]
    fn equals_mul_add_on_random_bits() {
        let mut r = Rng(0x9e37_79b9_7f4a_7c15);
        for _ in 0..1_000_000 {
            check(
                f32::from_bits(r.next()),
                f32::from_bits(r.next()),
                f32::from_bits(r.next()),
            );
        }
    }

    #[test]
    fn equals_mul_add_near_cancellation_midpoints_and_planes() {
        let mut r = Rng(12345);
        for _ in 0..1_000_000 {
            // Products of 12-bit significands near -c: exact sums with few
            // bits, midpoints and tiny results.
            let a = (r.next() & 0xfff) as f32 * 2f32.powi((r.next() % 40) as i32 - 20);
            let b = (r.next() & 0xfff) as f32 * 2f32.powi((r.next() % 40) as i32 - 20);
            let c = -(a * b) * (1.0 + ((r.next() % 9) as f32 - 4.0) * f32::EPSILON * 0.5);
            check(a, b, c);
            check(a, b, c + 2f32.powi(-((r.next() % 60) as i32)));
            // A plane at a pixel: `dadx·px + a0` with integer px.
            let d = f32::from_bits(0x3000_0000 + (r.next() & 0x0fff_ffff));
            let a0 = f32::from_bits(0x3e00_0000 + (r.next() & 0x03ff_ffff));
            check(d, (r.next() % 4096) as f32, a0);
            check(-d, (r.next() % 4096) as f32, a0);
        }
        let specials = [
            0.0,
            -0.0,
            1e-45,
            -1e-45,
            1.1754942e-38,
            1e-20,
            1.0,
            -1.0,
            3.4028235e38,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            1.0 + f32::EPSILON,
            0.5 + f32::EPSILON / 4.0,
        ];
        for a in specials {
            for b in specials {
                for c in specials {
                    check(a, b, c);
                }
            }
        }
        // 2^-127 + 2^-150 + 2^-180: the f64 sum rounds onto a subnormal midpoint.
        check(
            1.0 + 2f32.powi(-15),
            (1.0 + 2f32.powi(-15)) * 2f32.powi(-150),
            2f32.powi(-127),
        );
    }
}
