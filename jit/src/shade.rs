//! The shading stages that turn interpolated attributes into a fragment
//! colour, in llvmpipe's f32 arithmetic: colour sum and fog
//! (`docs/llvmpipe-facts.md` §14). These are the reference semantics; every
//! back end computes the same bits.

/// `GL_FOG_MODE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FogMode {
    Linear,
    Exp,
    Exp2,
}

/// The fog values a fragment reads, as f32 bit patterns so that uniforms stay
/// `Eq + Hash`: Mesa's `STATE_FOG_PARAMS_OPTIMIZED` (`prog_statevars.c`) and
/// the fog colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FogUniforms {
    /// `[-1/(end-start) (1 when end == start), end·(1/(end-start)),
    /// density·log2(e), density/sqrt(ln 2)]`.
    pub params: [u32; 4],
    /// Fog colour RGB (alpha is never fogged), clamped to `[0, 1]`.
    pub color: [u32; 3],
}

impl FogUniforms {
    /// The uniforms of `glFog` state `start`, `end`, `density` and `color`,
    /// computed as Mesa computes them (the products in f64, then rounded).
    pub fn new(start: f32, end: f32, density: f32, color: [f32; 3]) -> FogUniforms {
        let scale = if end == start { 1.0 } else { -1.0 / (end - start) };
        let params = [
            scale,
            end * -scale,
            (f64::from(density) * std::f64::consts::LOG2_E) as f32,
            (f64::from(density) * ONE_DIV_SQRT_LN2) as f32,
        ];
        FogUniforms {
            params: params.map(f32::to_bits),
            color: color.map(|c| c.clamp(0.0, 1.0).to_bits()),
        }
    }

    /// The parameters as floats.
    pub fn params(&self) -> [f32; 4] {
        self.params.map(f32::from_bits)
    }

    /// The fog colour as floats.
    pub fn color(&self) -> [f32; 3] {
        self.color.map(f32::from_bits)
    }
}

/// Mesa's `ONE_DIV_SQRT_LN2` (`src/mesa/main/macros.h`).
const ONE_DIV_SQRT_LN2: f64 = 1.201_122_408_786_449_8;

/// The coefficients of llvmpipe's `exp2` on `[0, 1)` (degree 5,
/// `lp_build_exp2_polynomial` in `lp_bld_arit.c`), as written there; it
/// builds f32 constants from them (see [`exp2_coeffs`]).
#[allow(clippy::excessive_precision)]
pub const EXP2_POLY: [f64; 6] = [
    1.0,
    0.693_153_073_200_168_932_794,
    0.240_153_617_044_375_388_211,
    0.055_826_318_053_295_666_477_5,
    0.008_989_340_090_494_663_911_01,
    0.001_877_576_675_191_479_126_99,
];

/// [`EXP2_POLY`] rounded to f32, as `lp_build_const_vec` rounds them.
pub fn exp2_coeffs() -> [f32; 6] {
    EXP2_POLY.map(|c| c as f32)
}

/// `2^x` as llvmpipe's `lp_build_exp2` computes it: `x` clamped to
/// `[-126.99999, 128]`, split into `floor(x)` and the fraction, the
/// fraction's power from [`EXP2_POLY`] evaluated with fused multiply-adds
/// (even and odd terms apart, `lp_build_polynomial`), times `2^floor(x)`
/// built in the exponent bits. NaN stays NaN.
pub fn exp2(x: f32) -> f32 {
    if x.is_nan() {
        return x;
    }
    let x = x.clamp(-126.99999, 128.0);
    let ipart = x.floor();
    let fpart = x - ipart;
    let expipart = f32::from_bits(((ipart as i32 + 127) as u32) << 23);
    let c = exp2_coeffs();
    let x2 = fpart * fpart;
    let odd = x2.mul_add(x2.mul_add(c[5], c[3]), c[1]);
    let even = x2.mul_add(x2.mul_add(c[4], c[2]), c[0]);
    expipart * odd.mul_add(fpart, even)
}

/// The fog factor `f` of fog coordinate `c` (GL 1.5 §3.10), as Mesa's
/// fixed-function fragment shader computes it (`emit_fog_instructions` in
/// `ff_fragment_shader.cpp`, multiply and add not fused) and clamped as
/// llvmpipe saturates (NaN becomes 0).
pub fn fog_factor(mode: FogMode, c: f32, u: &FogUniforms) -> f32 {
    let p = u.params();
    let f = match mode {
        FogMode::Linear => c * p[0] + p[1],
        FogMode::Exp => exp2(-(c * p[2])),
        FogMode::Exp2 => {
            let t = c * p[3];
            exp2(-(t * t))
        }
    };
    saturate(f)
}

/// `clamp(v, 0, 1)` with NaN as 0 (`lp_build_clamp_zero_one_nanzero`): its
/// `maxps` against 0 first, which gives +0 for -0 too (as the JIT's `fmax`;
/// a float colour buffer stores the difference).
#[inline]
pub fn saturate(v: f32) -> f32 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}

/// The fogged colour channel: `fog·(1 − f) + c·f`, two products and a sum.
#[inline]
pub fn fog_blend(c: f32, fog: f32, f: f32) -> f32 {
    fog * (1.0 - f) + c * f
}

/// A fragment's colour from its interpolated primary colour, secondary colour
/// (when the colour sum is on) and fog (mode, coordinate): the sum's RGB is
/// `primary + secondary` unclamped, alpha the primary's; fog blends RGB.
/// The result is clamped only when it becomes unorm8.
pub fn shade(primary: [f32; 4], secondary: Option<[f32; 3]>, fog: Option<(FogMode, f32, &FogUniforms)>) -> [f32; 4] {
    let mut c = primary;
    if let Some(s) = secondary {
        for k in 0..3 {
            c[k] += s[k];
        }
    }
    if let Some((mode, coord, u)) = fog {
        let f = fog_factor(mode, coord, u);
        let fc = u.color();
        for k in 0..3 {
            c[k] = fog_blend(c[k], fc[k], f);
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp2_is_exact_at_integers_and_close_between() {
        for i in -126..=127 {
            assert_eq!(exp2(i as f32), 2f32.powi(i), "2^{i}");
        }
        assert_eq!(exp2(-127.0), 0.0);
        assert_eq!(exp2(-1000.0), 0.0);
        assert_eq!(exp2(200.0), f32::INFINITY);
        // The degree-5 polynomial's relative error is below 2e-7 (3 ulp) on [0, 1).
        for k in 0..1000 {
            let x = -(k as f32) / 97.0;
            let want = 2f64.powf(f64::from(x));
            let got = f64::from(exp2(x));
            assert!((got - want).abs() <= want * 4e-7, "{x}: {got} vs {want}");
        }
    }
}

/// Plane slots of [`Planes`]: 1/w, the primary colour over w (RGBA), the
/// secondary colour over w (RGB), the fog coordinate over w, window depth,
/// and texture unit `u`'s s, t, r, q over w at `TEX0 + 4 * u ..`.
pub mod slot {
    pub const INV_W: usize = 0;
    pub const COLOR: usize = 1;
    pub const SECONDARY: usize = 5;
    pub const FOG: usize = 8;
    pub const Z: usize = 9;
    pub const TEX0: usize = 10;

    /// The first of texture unit `u`'s four slots (s, t, r, q over w).
    pub const fn tex(u: usize) -> usize {
        TEX0 + 4 * u
    }
}

/// Bit of `SpanPlanes::ones` (`compile`) beside [`Planes::ones`]'s: the
/// primary colour's planes are [`Planes::colour_bounded`].
pub const COLOUR_BOUNDED: u32 = 1 << 31;

/// Plane slots in a [`Planes`].
pub const PLANES: usize = slot::TEX0 + 4 * crate::texture::MAX_UNITS;

/// The attribute planes of one primitive in llvmpipe's frame (x right, y
/// down from the top row, pixel centres at integer coordinates): attribute
/// `k` at pixel `(px, row)` is `fma(dady, row, fma(dadx, px, a0))`
/// (`docs/llvmpipe-facts.md` §11). `#[repr(C)]`: compiled code reads it, each
/// coefficient stored four times so that one aligned vector load splats it.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planes {
    /// `[a0, dadx, dady]` of slot `k`, each repeated in four lanes.
    pub coeffs: [[[f32; 4]; 3]; PLANES],
}

impl Default for Planes {
    /// Every plane zero.
    fn default() -> Planes {
        Planes {
            coeffs: [[[0.0; 4]; 3]; PLANES],
        }
    }
}

impl Planes {
    /// Whether slot `k`'s plane is exactly 1 at every pixel: `a0` is 1.0 and
    /// `dadx`, `dady` are ±0 (then `fma(dady, row, fma(dadx, px, 1))` is 1
    /// for every finite `px` and `row`), compared as bits.
    #[inline]
    pub fn is_one(&self, k: usize) -> bool {
        let [a0, dadx, dady] = self.coeffs[k].map(|c| c[0].to_bits());
        a0 == 1.0f32.to_bits() && (dadx | dady) & 0x7fff_ffff == 0
    }

    /// What compiled code reads as `SpanPlanes::ones`: bit 0 the 1/w plane
    /// [`Self::is_one`] (colours and coordinates need no division by it),
    /// bit `1 + u` for each unit `u` of `units` (a bit mask) that and unit
    /// `u`'s q/w plane too (its s and t are its planes' values).
    pub fn ones(&self, units: u32) -> u32 {
        if !self.is_one(slot::INV_W) {
            return 0;
        }
        let mut bits = 1;
        let mut rest = units;
        while rest != 0 {
            let u = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            if u < crate::texture::MAX_UNITS && self.is_one(slot::tex(u) + 3) {
                bits |= 2 << u;
            }
        }
        bits
    }

    /// Whether the primary colour's four planes stay below about 2^22 in
    /// magnitude at every pixel `(px, row)` with both in `0..=extent`:
    /// `|a0| + (|dadx| + |dady|) · extent <= 2^22` in f32 (false for NaN
    /// or infinite coefficients; its three roundings and the planes' two
    /// leave the values below `2^22 · (1 + 2^-21)`). A value times 255 is
    /// then below 2^31 and converts to an integer without overflow: the
    /// compiled code leaves out the clamp to 255 before that conversion
    /// and lets its saturating narrowings clamp (`compile::shade`).
    pub fn colour_bounded(&self, extent: u32) -> bool {
        let e = extent as f32;
        let mut bounded = true;
        for c in 0..4 {
            let (a0, dadx, dady) = self.get(slot::COLOR + c);
            bounded &= a0.abs() + (dadx.abs() + dady.abs()) * e <= 4_194_304.0;
        }
        bounded
    }

    /// Sets slot `k`'s plane.
    #[inline]
    pub fn set(&mut self, k: usize, a0: f32, dadx: f32, dady: f32) {
        self.coeffs[k] = [[a0; 4], [dadx; 4], [dady; 4]];
    }

    /// Slot `k`'s plane as `(a0, dadx, dady)`.
    #[inline]
    pub fn get(&self, k: usize) -> (f32, f32, f32) {
        let [a0, dadx, dady] = self.coeffs[k];
        (a0[0], dadx[0], dady[0])
    }

    /// Attribute `k` at pixel `(px, row)`, with llvmpipe's fused multiply-adds.
    #[inline]
    pub fn at(&self, k: usize, px: f32, row: f32) -> f32 {
        let (a0, dadx, dady) = self.get(k);
        dady.mul_add(row, dadx.mul_add(px, a0))
    }

    /// Sets slot `k` to the constant `v` (points, flat colours).
    pub fn constant(&mut self, k: usize, v: f32) {
        self.set(k, v, 0.0, 0.0);
    }
}

/// Converts a colour channel to a unorm byte as llvmpipe does: clamped to
/// `[0, 1]` (NaN as 0), times 255, rounded half to even.
#[inline]
pub fn unorm8(c: f32) -> u8 {
    (saturate(c) * 255.0).round_ties_even() as u8
}

/// Converts window depth to a 16- or 24-bit depth value as llvmpipe does:
/// clamped to `[0, 1]` (NaN as 0), times the largest value, in f32, rounded
/// half to even.
#[inline]
pub fn unorm_depth(z: f32, max: u32) -> u32 {
    (saturate(z) * max as f32).round_ties_even() as u32
}

/// The colour and depth of the fragment at `(px, row)` of `planes`, as the
/// shading stage of `key` makes them (`None` for what the key leaves to the
/// span): the primary colour, the texture environment of the key's units
/// over it (sampling `textures`), then colour sum and fog, the order of
/// Mesa's fixed-function fragment shader (`emit_instructions`).
pub fn fragment(
    key: &crate::key::ShadeKey,
    planes: &Planes,
    (px, row): (f32, f32),
    fog_u: &FogUniforms,
    depth_format: Option<crate::key::DepthFormat>,
    textures: &crate::texture::TextureSet<'_>,
) -> (Option<[u8; 4]>, Option<u32>) {
    let (c, z) = fragment_f32(key, planes, (px, row), fog_u, depth_format, textures);
    (c.map(|c| c.map(unorm8)), z)
}

/// [`fragment`] with the colour left in f32, unclamped (the deep formats').
pub fn fragment_f32(
    key: &crate::key::ShadeKey,
    planes: &Planes,
    (px, row): (f32, f32),
    fog_u: &FogUniforms,
    depth_format: Option<crate::key::DepthFormat>,
    textures: &crate::texture::TextureSet<'_>,
) -> (Option<[f32; 4]>, Option<u32>) {
    let z = key
        .depth
        .then(|| depth_format.map_or(0, |f| f.from_window(planes.at(slot::Z, px, row))));
    if !key.color {
        return (None, z);
    }
    let w = 1.0 / planes.at(slot::INV_W, px, row);
    let colour = |k: usize| {
        let v = planes.at(k, px, row);
        if key.flat {
            v
        } else {
            v * w
        }
    };
    let mut primary = [0, 1, 2, 3].map(|c| colour(slot::COLOR + c));
    if key.textured() {
        primary = texture(key, planes, (px, row), textures, primary);
    }
    let secondary = key.color_sum.then(|| [0, 1, 2].map(|c| colour(slot::SECONDARY + c)));
    let fog = key.fog.map(|m| (m, planes.at(slot::FOG, px, row) * w, fog_u));
    (Some(shade(primary, secondary, fog)), z)
}

/// Unit `u`'s texture coordinates (s, t, r, q) at pixel `(px, row)`:
/// perspective-correct, each plane's value times w.
pub fn tex_coords(planes: &Planes, u: usize, (px, row): (f32, f32)) -> [f32; 4] {
    let w = 1.0 / planes.at(slot::INV_W, px, row);
    std::array::from_fn(|c| planes.at(slot::tex(u) + c, px, row) * w)
}

/// The top-left pixel of the 2×2 quad holding `(px, row)` in llvmpipe's
/// frame: quads start at even columns and even rows of the top-down frame.
#[inline]
pub fn quad_origin((px, row): (f32, f32)) -> (f32, f32) {
    (px - (px as u32 & 1) as f32, row - (row as u32 & 1) as f32)
}

/// The texture environment of `key`'s units over `primary` at `(px, row)`:
/// each enabled unit sampled at its coordinates at the four pixels of the
/// fragment's quad (λ and cube-map derivatives need them).
pub fn texture(
    key: &crate::key::ShadeKey,
    planes: &Planes,
    (px, row): (f32, f32),
    textures: &crate::texture::TextureSet<'_>,
    primary: [f32; 4],
) -> [f32; 4] {
    use crate::texture::MAX_UNITS;
    let mut samples = [[0.0; 4]; MAX_UNITS];
    for (u, unit) in key.tex.iter().enumerate() {
        let (Some(unit), Some(tex)) = (unit, &textures.units[u]) else {
            continue;
        };
        samples[u] = sample_unit(planes, (u, unit), tex, (px, row));
    }
    crate::texture::environment(&key.tex, &samples, primary, &textures.env_color)
}

/// Unit `u`'s sample of `tex` at `(px, row)`: its coordinates at the four
/// pixels of the fragment's quad (λ and cube-map derivatives need them).
pub fn sample_unit(
    planes: &Planes,
    (u, unit): (usize, &crate::texture::TexUnitKey),
    tex: &crate::texture::TextureRef<'_>,
    (px, row): (f32, f32),
) -> [f32; 4] {
    let (origin, lane) = quad_lane((px, row));
    crate::texture::sample_quad(unit, tex, &quad_coords(planes, u, origin), lane)
}

/// The origin of the quad holding `(px, row)` ([`quad_origin`]) and the
/// pixel's lane in it (0 top-left, 1 top-right, 2 and 3 below).
#[inline]
pub fn quad_lane((px, row): (f32, f32)) -> ((f32, f32), usize) {
    let (qx, qy) = quad_origin((px, row));
    ((qx, qy), usize::from(px != qx) + 2 * usize::from(row != qy))
}

/// Unit `u`'s coordinates ([`tex_coords`]) at the four pixels of the quad at `origin`.
#[inline]
pub fn quad_coords(planes: &Planes, u: usize, (qx, qy): (f32, f32)) -> [[f32; 4]; 4] {
    let pixels = [(qx, qy), (qx + 1.0, qy), (qx, qy + 1.0), (qx + 1.0, qy + 1.0)];
    pixels.map(|p| tex_coords(planes, u, p))
}
