//! A fused multiply-add of f32 values, `a·b + c` rounded once: the same bits
//! as [`f32::mul_add`], without its call.
//!
//! The crate is built for baseline x86-64, where `f32::mul_add` is a call
//! to the runtime's `fmaf` (which then dispatches to the FMA instruction
//! through a function pointer), and the registers live across it are saved
//! and reloaded around each call: the viewport transform makes four a
//! vertex. `#[target_feature(enable = "fma")]` would need `unsafe` at the
//! call, which the crate keeps to the JIT boundary and the C ABI. So the
//! sum is computed in f64 instead, inline: the product of two f32 values is
//! exact in f64, and the f64 sum, rounded once, rounds to the correctly
//! rounded f32 result unless it lands exactly on a midpoint between two
//! f32 values (double rounding could then go the wrong way; it does not
//! when the f64 sum was exact, which TwoSum tells) or the result is below
//! f32's normal range (where f32's rounding position moves); those rare
//! cases, and NaN, take `f32::mul_add`. Tested against `f32::mul_add` on
//! random bits, near-cancellations, midpoints and special values.
//! Measured on lit16 (callgrind): 32 instructions a vertex inside `fmaf`
//! alone before, plus the saves around the calls; inline about 16 a call,
//! and 5 more for TwoSum on the midpoints (59% of the calls there: `z·0.5 +
//! 0.5` and `y·512 + 512` often have one bit more than f32).

/// `a·b + c` with one rounding, bit for bit [`f32::mul_add`].
#[inline(always)]
pub fn fma(a: f32, b: f32, c: f32) -> f32 {
    fma_wide(a, f64::from(b), f64::from(c))
}

/// [`fma`] with `b` and `c` given as f64 (exactly: f32 values widened),
/// so that a draw's constants are widened once.
#[inline(always)]
pub fn fma_wide(a: f32, b: f64, c: f64) -> f32 {
    let xy = f64::from(a) * b;
    let r = xy + c;
    let bits = r.to_bits();
    let exp = (bits >> 52) & 0x7ff;
    // `r` rounds to the correctly rounded f32 of the exact sum when it is in
    // f32's normal range (897: the biased f64 exponent of 2^-126) and not on
    // an f32 midpoint, whose f64 bits end in a one and 28 zeros: every f32
    // value and midpoint there is an f64 value, so an exact sum on either
    // side of a midpoint rounds (in f64) to that side or onto it, never
    // across. On a midpoint it still does when the f64 sum was exact (then
    // f32's ties-to-even is the rounding of the exact sum): common in the
    // viewport transform, `x·512 + 512` having one bit more than f32 for a
    // quarter of the vertices; Knuth's TwoSum tells (its error term is
    // exact), computed only on a midpoint (computed always, branch-free:
    // 30 instructions a call instead of 14).
    let normal = (897..0x7ff).contains(&exp);
    if normal && (bits & 0x1fff_ffff != 0x1000_0000 || two_sum_error(xy, c, r) == 0.0) {
        r as f32
    } else {
        rare(a, b, c, r)
    }
}

/// [`fma`] for `b` a normal power of two (or its negative), with `b` and
/// `c` widened as [`fma_wide`] takes them: the product `a·b` only moves
/// `a`'s exponent, so when it comes out normal it is exact in f32 and one
/// f32 add rounds the sum once, as the fused operation does; otherwise
/// (an overflow, a product below the normal range, NaN) [`fma_wide`].
/// The viewport transform's scales are powers of two for a viewport of
/// 2^n pixels and the default depth range (`z·0.5 + 0.5`): measured on
/// lit16 (1024×1024), 73 instructions a vertex for its four fused
/// operations through [`fma_wide`], 13 here.
#[inline(always)]
pub fn fma_by_pow2(a: f32, b: f32, c: f32, wide: (f64, f64)) -> f32 {
    let p = a * b;
    if p.is_normal() {
        p + c
    } else {
        fma_wide(a, wide.0, wide.1)
    }
}

/// Whether `b` is a normal power of two or its negative (what
/// [`fma_by_pow2`] takes).
pub fn is_pow2(b: f32) -> bool {
    b.is_normal() && b.to_bits() & 0x007f_ffff == 0
}

/// [`fma_wide`] off its common path: an infinite sum (of infinite
/// operands) is exact; anything else (an inexact sum on a midpoint, a
/// result below f32's normal range, NaN) takes `f32::mul_add`.
#[cold]
#[inline(never)]
fn rare(a: f32, b: f64, c: f64, r: f64) -> f32 {
    if r.is_infinite() {
        r as f32
    } else {
        a.mul_add(b as f32, c as f32)
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
    fn by_a_power_of_two_equals_mul_add() {
        let mut r = Rng(777);
        let b_of = |r: &mut Rng| {
            let e = (r.next() % 254) as i32 - 126;
            let b = 2f32.powi(e);
            if r.next() & 1 == 0 {
                b
            } else {
                -b
            }
        };
        for _ in 0..2_000_000 {
            let (a, c) = (f32::from_bits(r.next()), f32::from_bits(r.next()));
            let b = b_of(&mut r);
            assert!(is_pow2(b));
            let want = a.mul_add(b, c);
            let got = fma_by_pow2(a, b, c, (b.into(), c.into()));
            assert!(
                want.to_bits() == got.to_bits() || (want.is_nan() && got.is_nan()),
                "{a:e} {b:e} {c:e}"
            );
            // The viewport's shape: a in [-1, 1], translate of the scale's size.
            let a = f32::from_bits(r.next() & 0x3f7f_ffff) * if r.next() & 1 == 0 { 1.0 } else { -1.0 };
            let b = [0.5f32, 512.0, -512.0, 8.0, 4096.0][(r.next() % 5) as usize];
            for c in [b.abs(), 0.5, 1000.0, b.abs() + 1.0] {
                let want = a.mul_add(b, c);
                assert_eq!(
                    want.to_bits(),
                    fma_by_pow2(a, b, c, (b.into(), c.into())).to_bits(),
                    "{a:e} {b:e} {c:e}"
                );
            }
        }
        assert!(!is_pow2(3.0) && !is_pow2(0.0) && !is_pow2(1e-40) && !is_pow2(f32::INFINITY));
    }

    #[test]
    fn equals_mul_add_on_random_bits() {
        let mut r = Rng(0x9e37_79b9_7f4a_7c15);
        for _ in 0..2_000_000 {
            check(
                f32::from_bits(r.next()),
                f32::from_bits(r.next()),
                f32::from_bits(r.next()),
            );
        }
    }

    #[test]
    fn equals_mul_add_near_cancellation_and_midpoints() {
        let mut r = Rng(12345);
        for _ in 0..2_000_000 {
            // Products of 12-bit significands near -c: exact sums with few
            // bits, midpoints and tiny results.
            let a = (r.next() & 0xfff) as f32 * 2f32.powi((r.next() % 40) as i32 - 20);
            let b = (r.next() & 0xfff) as f32 * 2f32.powi((r.next() % 40) as i32 - 20);
            let c = -(a * b) * (1.0 + ((r.next() % 9) as f32 - 4.0) * f32::EPSILON * 0.5);
            check(a, b, c);
            check(a, b, c + 2f32.powi(-((r.next() % 60) as i32)));
            // The viewport transform's shape: x·(1/w)·scale + translate.
            let x = f32::from_bits(0x3f00_0000 + (r.next() & 0x00ff_ffff));
            check(x, 512.0, 512.0);
            check(-x, 0.5, 0.5);
        }
        // Subnormal and tiny results, huge ones, specials.
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
