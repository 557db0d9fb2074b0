//! λ, the level of detail, and the mipmap levels it selects, as
//! `lp_build_rho`, `lp_build_lod_selector`, `lp_build_nearest_mip_level` and
//! `lp_build_linear_mip_levels` (`lp_bld_sample.c`) compute them with
//! GALLIVM_PERF unset: exact ρ² (no `rho_approx`), no brilinear, one λ per
//! 2×2 quad (`docs/llvmpipe-facts.md` §16).

use super::arith::{ifloor_fract, iround, maxps, minps};
use super::{Filter, MipFilter, SamplerKey, TextureRef};

/// Where sampling happens: whether the fragment is minified and which
/// level(s) it reads, with the weight of the second.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lod {
    /// λ > 0 (or ρ > 1 where llvmpipe skips λ): the minification filter.
    pub minified: bool,
    pub level0: u32,
    pub level1: u32,
    /// Weight of `level1` (`MipFilter::Linear`), 0 at the ends of the chain.
    pub weight: f32,
}

/// `lp_build_fast_log2`: the exponent minus one plus the mantissa in
/// `[1, 2)`, a piecewise-linear log2 exact at powers of two.
pub fn fast_log2(x: f32) -> f32 {
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 255) as i32 - 128;
    let mantissa = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    exponent as f32 + mantissa
}

/// `lp_build_extract_exponent(x, bias)`: the biased exponent field minus `127 − bias`.
fn exponent(x: f32, bias: i32) -> i32 {
    ((x.to_bits() >> 23) & 255) as i32 - (127 - bias)
}

/// `lp_build_ilog2_sqrt`: `round(log2(sqrt(x)))` from the exponent alone.
pub fn ilog2_sqrt(x: f32) -> i32 {
    exponent(x, 1) >> 1
}

/// `lp_build_ilog2`: `floor(log2(x·√2))`.
pub fn ilog2(x: f32) -> i32 {
    exponent(x * std::f64::consts::SQRT_2 as f32, 0)
}

/// ρ of a quad from the projected coordinates at its top-left, top-right
/// and bottom-left pixels (`lp_build_rho` without explicit derivatives):
/// with two or three dimensions the exact
/// `max(Σ(ds/dx·size)², Σ(ds/dy·size)²)` (ρ², `squared`), with one
/// `max(|ds/dx|, |ds/dy|)·width` (ρ).
pub fn rho_quad(dims: usize, size: [f32; 3], tl: [f32; 3], tr: [f32; 3], bl: [f32; 3]) -> (f32, bool) {
    if dims == 1 {
        let dx = (tr[0] - tl[0]).abs();
        let dy = (bl[0] - tl[0]).abs();
        return (maxps(dx, dy) * size[0], false);
    }
    let sq = |v: f32| v * v;
    let mut rx = sq((tr[0] - tl[0]) * size[0]) + sq((tr[1] - tl[1]) * size[1]);
    let mut ry = sq((bl[0] - tl[0]) * size[0]) + sq((bl[1] - tl[1]) * size[1]);
    if dims == 3 {
        rx += sq((tr[2] - tl[2]) * size[2]);
        ry += sq((bl[2] - tl[2]) * size[2]);
    }
    (maxps(rx, ry), true)
}

/// ρ² from per-pixel derivatives of two coordinates (the cube-map path of
/// `lp_build_rho`): `max(Σ(ddx·size)², Σ(ddy·size)²)`, infinite or NaN as 0.
pub fn rho_derivs(size: [f32; 2], ddx: [f32; 2], ddy: [f32; 2]) -> f32 {
    let sq = |v: f32| v * v;
    let rx = sq(size[0] * ddx[0]) + sq(size[1] * ddx[1]);
    let ry = sq(size[0] * ddy[0]) + sq(size[1] * ddy[1]);
    let rho = maxps(rx, ry);
    if rho.is_finite() {
        rho
    } else {
        0.0
    }
}

/// The sampler state llvmpipe derives from `pipe_sampler_state`
/// (`lp_sampler_static_sampler_state`): which λ adjustments are compiled in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodState {
    /// `max(GL_TEXTURE_MIN_LOD, 0)` (Mesa stores no negative minimum).
    pub min_lod: f32,
    pub max_lod: f32,
    pub bias: f32,
    pub min_max_equal: bool,
    pub apply_min: bool,
    pub apply_max: bool,
}

impl LodState {
    /// The state of `tex` sampled with `key`.
    pub fn new(key: &SamplerKey, tex: &TextureRef<'_>) -> LodState {
        let min_lod = tex.min_lod.max(0.0);
        let max_lod = tex.max_lod;
        let lod_used = key.mip != MipFilter::None || key.min != key.mag;
        let min_max_equal = lod_used && min_lod == max_lod;
        LodState {
            min_lod,
            max_lod,
            bias: tex.lod_bias,
            min_max_equal,
            apply_min: lod_used && !min_max_equal && min_lod > 0.0,
            // PIPE_MAX_TEXTURE_LEVELS − 1
            apply_max: lod_used && !min_max_equal && max_lod < 15.0,
        }
    }
}

/// λ's integer part (or the whole λ for `MipFilter::Linear`) and whether
/// it minifies, from ρ (`rho_squared`: ρ²), as `lp_build_lod_selector`.
/// Returns `(minified, ipart, fpart)`.
pub fn select(mip: MipFilter, s: &LodState, rho: f32, rho_squared: bool) -> (bool, i32, f32) {
    let lod = if s.min_max_equal {
        s.min_lod
    } else {
        if s.bias == 0.0 && !s.apply_min && !s.apply_max && mip != MipFilter::Linear {
            // No adjustment after log2: integer part from the exponent.
            let ipart = if rho_squared { ilog2_sqrt(rho) } else { ilog2(rho) };
            return (rho > 1.0, ipart, 0.0);
        }
        let rho2 = if rho_squared { rho } else { rho * rho };
        let mut lod = fast_log2(rho2) * 0.5;
        if s.bias != 0.0 {
            lod += s.bias;
        }
        if s.apply_max {
            lod = minps(lod, s.max_lod);
        }
        if s.apply_min {
            lod = maxps(lod, s.min_lod);
        }
        lod
    };
    let minified = lod > 0.0;
    match mip {
        MipFilter::Linear => {
            let (i, f) = ifloor_fract(lod);
            (minified, i, f)
        }
        MipFilter::None | MipFilter::Nearest => (minified, iround(lod), 0.0),
    }
}

/// The levels λ selects between `first` (`base_level`) and `last`
/// (`max_level`).
pub fn levels(mip: MipFilter, (minified, ipart, fpart): (bool, i32, f32), first: u32, last: u32) -> Lod {
    let (first_i, last_i) = (first as i32, last as i32);
    match mip {
        MipFilter::None => Lod {
            minified,
            level0: first,
            level1: first,
            weight: 0.0,
        },
        MipFilter::Nearest => {
            let l = ipart.wrapping_add(first_i).clamp(first_i, last_i.max(first_i)) as u32;
            Lod {
                minified,
                level0: l,
                level1: l,
                weight: 0.0,
            }
        }
        MipFilter::Linear => {
            let l0 = ipart.wrapping_add(first_i);
            if l0 < first_i {
                Lod {
                    minified,
                    level0: first,
                    level1: first,
                    weight: 0.0,
                }
            } else if l0 >= last_i {
                Lod {
                    minified,
                    level0: last,
                    level1: last,
                    weight: 0.0,
                }
            } else {
                Lod {
                    minified,
                    level0: l0 as u32,
                    level1: l0 as u32 + 1,
                    weight: fpart,
                }
            }
        }
    }
}

/// Whether a sampler computes λ at all: a mipmap filter, or different
/// minification and magnification filters.
pub fn needs_lod(key: &SamplerKey) -> bool {
    key.mip != MipFilter::None || key.min != key.mag
}

/// The filter a fragment uses at its level.
pub fn filter(key: &SamplerKey, minified: bool) -> (Filter, MipFilter) {
    if key.min == key.mag || minified {
        (key.min, key.mip)
    } else {
        (key.mag, MipFilter::None)
    }
}
