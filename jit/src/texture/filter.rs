//! Filtering one mipmap level: llvmpipe's two paths (`docs/llvmpipe-facts.md` §16).
//!
//! - **AoS** (`lp_bld_sample_aos.c`), for unorm8 textures (`TexelFormat::Rgba8`)
//!   with REPEAT or CLAMP_TO_EDGE and no depth compare: coordinates scaled by
//!   `size·256` and rounded to 8.8 fixed point, texels lerped in 8 bits
//!   ([`lerp8`]), then converted to float.
//! - **SoA** (`lp_bld_sample_soa.c`), every other case: texels converted to
//!   float first (sRGB decoded per texel), f32 weights, lerps as fused
//!   multiply-adds, the border colour for texels outside CLAMP and
//!   CLAMP_TO_BORDER images.

use super::arith::{
    fract, fract_safe, ifloor, ifloor_fract, iround, itrunc, lerp, lerp8, maxps, minps, srgb8_to_linear,
    unorm16_to_float, unorm8_to_float,
};
use super::{DepthUnits, Filter, Image, TexelFormat, Wrap};
use crate::key::CompareFunc;

/// One level (one face) to sample, with what the coordinates need.
#[derive(Clone, Copy, Debug)]
pub struct Level<'a> {
    pub image: &'a Image<'a>,
    pub format: TexelFormat,
    /// Whether level 0 of the texture has power-of-two sizes (the REPEAT
    /// arithmetic differs: `pot_width` … of `lp_static_texture_state`).
    pub pot: [bool; 3],
}

impl Level<'_> {
    fn size(&self) -> [i32; 3] {
        [self.image.width, self.image.height, self.image.depth].map(|v| v.max(1) as i32)
    }

    fn index(&self, x: i32, y: i32, z: i32) -> Option<usize> {
        let [w, h, d] = self.size();
        if !(0..w).contains(&x) || !(0..h).contains(&y) || !(0..d).contains(&z) {
            return None;
        }
        Some(((z as usize * h as usize + y as usize) * w as usize) + x as usize)
    }

    /// The texel's four bytes (`Rgba8`, `Srgba8`); zeros where the image is short.
    fn bytes(&self, x: i32, y: i32, z: i32) -> [u8; 4] {
        let Some(i) = self.index(x, y, z) else { return [0; 4] };
        match self.image.texels.get(4 * i..4 * i + 4) {
            Some(b) => [b[0], b[1], b[2], b[3]],
            None => [0; 4],
        }
    }

    /// The texel as floats, converted as llvmpipe's SoA fetch does.
    fn float(&self, x: i32, y: i32, z: i32) -> [f32; 4] {
        match self.format {
            TexelFormat::Rgba8 => self.bytes(x, y, z).map(unorm8_to_float),
            TexelFormat::Srgba8 => {
                let b = self.bytes(x, y, z);
                [
                    srgb8_to_linear(b[0]),
                    srgb8_to_linear(b[1]),
                    srgb8_to_linear(b[2]),
                    unorm8_to_float(b[3]),
                ]
            }
            TexelFormat::Rgba16 => {
                let i = self.index(x, y, z).unwrap_or(usize::MAX);
                let b = self.image.texels.get(8 * i.min(usize::MAX / 8)..).unwrap_or(&[]);
                std::array::from_fn(|c| {
                    b.get(2 * c..2 * c + 2)
                        .map_or(0.0, |v| unorm16_to_float(u16::from_ne_bytes([v[0], v[1]])))
                })
            }
            TexelFormat::Depth32F => {
                let i = self.index(x, y, z).unwrap_or(usize::MAX);
                if let Some(u) = self.image.units {
                    let d = u.z.get(i).map_or(0.0, |&z| DepthUnits::texel(z, u.unorm24));
                    return [d, 0.0, 0.0, 1.0];
                }
                let d = self
                    .image
                    .texels
                    .get(4 * i.min(usize::MAX / 4)..)
                    .and_then(|b| b.get(..4))
                    .map_or(0.0, |v| f32::from_ne_bytes([v[0], v[1], v[2], v[3]]));
                [d, 0.0, 0.0, 1.0]
            }
        }
    }
}

/// Whether the AoS path samples with these wraps (`lp_is_simple_wrap_mode`).
pub fn simple_wrap(w: Wrap) -> bool {
    matches!(w, Wrap::Repeat | Wrap::ClampToEdge)
}

/// The (bi-, tri-)linear blend of the texels `t(i, j, k)` (i along s, j
/// along t, k along r) with weights `w`, in llvmpipe's order: along s within
/// each row, then t, then r (`lp_build_lerp_2d`, `lp_build_lerp_3d`).
fn blend<W: Copy, T: Copy>(
    dims: usize,
    w: [W; 3],
    t: impl Fn(usize, usize, usize) -> T,
    lerp: impl Fn(W, T, T) -> T,
) -> T {
    let slice = |k: usize| {
        let row0 = lerp(w[0], t(0, 0, k), t(1, 0, k));
        if dims == 1 {
            return row0;
        }
        let row1 = lerp(w[0], t(0, 1, k), t(1, 1, k));
        lerp(w[1], row0, row1)
    };
    if dims == 3 {
        lerp(w[2], slice(0), slice(1))
    } else {
        slice(0)
    }
}

// ---------------------------------------------------------------- AoS ----

/// The factor that takes a coordinate to texels along an axis of `len`
/// texels: `len` for normalized coordinates, 1 for a rectangle texture's
/// (llvmpipe skips the multiply when `normalized_coords` is off; `s · 1` is
/// `s`, bit for bit). Measured with callgrind (`osmesa/bench/shadow_fbo.c
/// 1|2 320x240 plane`, one thread, optimized tier), the shadow map sampled
/// through this reference: 1.3330 G instructions a frame against main's
/// 1.3145 G (+1.4%, all in `QuadSample::lane`); main's sampler code with
/// only the rectangle arms added measured +0.9%, and a const-generic
/// `normalized` +1.8%: code layout more than work. The native 2D path is
/// unchanged (`fill tex`: +107 instructions of 1.2518 G a frame).
fn scale(len: i32, normalized: bool) -> f32 {
    if normalized {
        len as f32
    } else {
        1.0
    }
}

/// Nearest texel along one axis (`lp_build_sample_wrap_nearest_int`);
/// `sc` is [`scale`] (REPEAT takes normalized coordinates only).
fn aos_nearest_axis(s: f32, len: i32, sc: f32, pot: bool, wrap: Wrap) -> i32 {
    let i = ifloor(s * sc);
    match wrap {
        Wrap::Repeat if pot => i & (len - 1),
        Wrap::Repeat => itrunc(fract_safe(s) * len as f32),
        _ => i.max(0).min(len - 1),
    }
}

/// The two texels and the 8-bit weight of the second along one axis
/// (`lp_build_sample_image_linear` and `lp_build_sample_wrap_linear_int`).
/// `sc` as in [`aos_nearest_axis`] (llvmpipe scales the size by 256, or
/// unnormalized coordinates by 256).
fn aos_linear_axis(s: f32, len: i32, sc: f32, pot: bool, wrap: Wrap) -> (i32, i32, u8) {
    let u = iround(s * (sc * 256.0)).wrapping_add(-128);
    let (i, w) = (u >> 8, (u & 255) as u8);
    match wrap {
        Wrap::Repeat => {
            let (x0, w) = if pot {
                (i & (len - 1), w)
            } else {
                // lp_build_coord_repeat_npot_linear_int: from the fraction of s.
                let v = iround(fract(s) * len as f32 * 256.0).wrapping_add(-128);
                let x0 = if v >> 8 < 0 { len - 1 } else { v >> 8 };
                (x0.min(len - 1), (v & 255) as u8)
            };
            (x0, if x0 != len - 1 { x0 + 1 } else { 0 }, w)
        }
        _ => {
            let inside = i >= 0 && i < len - 1;
            let x0 = if i >= 0 { i } else { 0 };
            let x0 = if i < len - 1 { x0 } else { len - 1 };
            (x0, x0 + i32::from(inside), w)
        }
    }
}

/// One level sampled on the AoS path, as unorm8 RGBA.
pub fn aos(level: &Level<'_>, filter: Filter, dims: usize, coord: [f32; 3], wrap: [Wrap; 3]) -> [u8; 4] {
    aos_at(level, filter, dims, coord, wrap, true)
}

/// [`aos`] with normalized or (rectangle textures) unnormalized coordinates.
pub fn aos_at(
    level: &Level<'_>,
    filter: Filter,
    dims: usize,
    coord: [f32; 3],
    wrap: [Wrap; 3],
    normalized: bool,
) -> [u8; 4] {
    let size = level.size();
    match filter {
        Filter::Nearest => {
            let mut p = [0i32; 3];
            for a in 0..dims {
                p[a] = aos_nearest_axis(coord[a], size[a], scale(size[a], normalized), level.pot[a], wrap[a]);
            }
            level.bytes(p[0], p[1], p[2])
        }
        Filter::Linear => {
            let mut x = [[0i32; 2]; 3];
            let mut w = [0u8; 3];
            for a in 0..dims {
                let (x0, x1, wa) =
                    aos_linear_axis(coord[a], size[a], scale(size[a], normalized), level.pot[a], wrap[a]);
                x[a] = [x0, x1];
                w[a] = wa;
            }
            let t = |i: usize, j: usize, k: usize| level.bytes(x[0][i], x[1][j], x[2][k]);
            blend(dims, w, t, |w, a, b| std::array::from_fn(|c| lerp8(w, a[c], b[c])))
        }
    }
}

/// The AoS lerp between two levels: weight `trunc(fpart·256)`, skipped at 0.
pub fn aos_mip(c0: [u8; 4], c1: [u8; 4], fpart: f32) -> [u8; 4] {
    let w = itrunc(fpart * 256.0);
    if w > 0 {
        std::array::from_fn(|c| lerp8(w as u8, c0[c], c1[c]))
    } else {
        c0
    }
}

// ---------------------------------------------------------------- SoA ----

/// GL_MIRRORED_REPEAT's fold (`lp_build_coord_mirror` with `posOnly`):
/// `|2·(s/2 − round(s/2))|`, NaN as 0.
fn mirror(s: f32) -> f32 {
    let c = s * 0.5;
    let f = c - c.round_ties_even();
    maxps((f + f).abs(), 0.0)
}

/// Whether a wrap mode reads the border colour with these filters
/// (`lp_sampler_wrap_mode_uses_border_color`).
pub fn uses_border(wrap: Wrap, min: Filter, mag: Filter) -> bool {
    match wrap {
        Wrap::Clamp => min == Filter::Linear || mag == Filter::Linear,
        Wrap::ClampToBorder => true,
        Wrap::Repeat | Wrap::ClampToEdge | Wrap::MirroredRepeat => false,
    }
}

/// Nearest texel along one axis (`lp_build_sample_wrap_nearest`); `sc` as
/// in [`aos_nearest_axis`].
fn soa_nearest_axis(s: f32, len: i32, sc: f32, pot: bool, wrap: Wrap) -> i32 {
    let lf = len as f32;
    match wrap {
        Wrap::Repeat if pot => ifloor(s * lf) & (len - 1),
        Wrap::Repeat => itrunc(fract_safe(s) * lf),
        Wrap::Clamp | Wrap::ClampToEdge => itrunc(s * sc).max(0).min(len - 1),
        Wrap::ClampToBorder => ifloor(s * sc),
        Wrap::MirroredRepeat => itrunc(mirror(s) * lf).min(len - 1),
    }
}

/// The two texels and the weight of the second along one axis
/// (`lp_build_sample_wrap_linear`).
pub fn soa_linear_axis(s: f32, len: i32, pot: bool, wrap: Wrap) -> (i32, i32, f32) {
    soa_linear_axis_at(s, len, len as f32, pot, wrap)
}

/// [`soa_linear_axis`] with `sc` as in [`aos_nearest_axis`].
fn soa_linear_axis_at(s: f32, len: i32, sc: f32, pot: bool, wrap: Wrap) -> (i32, i32, f32) {
    let lf = len as f32;
    match wrap {
        Wrap::Repeat if pot => {
            let (x0, w) = ifloor_fract(s * lf - 0.5);
            (x0 & (len - 1), x0.wrapping_add(1) & (len - 1), w)
        }
        Wrap::Repeat => {
            let u = fract(s) * lf - 0.5;
            let (x0, w) = ifloor_fract(u);
            let x0 = if u < 0.0 { len - 1 } else { x0 };
            (x0, if x0 != len - 1 { x0 + 1 } else { 0 }, w)
        }
        Wrap::Clamp => {
            let (x0, w) = ifloor_fract(minps(maxps(s * sc, 0.0), lf) - 0.5);
            (x0, x0.wrapping_add(1), w)
        }
        Wrap::ClampToEdge => {
            let (x0, w) = ifloor_fract(maxps(minps(s * sc, lf) - 0.5, 0.0));
            (x0, x0.wrapping_add(1).min(len - 1), w)
        }
        Wrap::ClampToBorder => {
            let (x0, w) = ifloor_fract(s * sc - 0.5);
            (x0, x0.wrapping_add(1), w)
        }
        Wrap::MirroredRepeat => {
            let (x0, w) = ifloor_fract(mirror(s) * lf - 0.5);
            (x0.max(0), x0.wrapping_add(1).min(len - 1), w)
        }
    }
}

/// What the SoA path needs beyond the level and coordinates.
#[derive(Clone, Copy, Debug)]
pub struct SoaState {
    pub wrap: [Wrap; 3],
    /// Per axis: whether texels outside the image are the border colour.
    pub border_axes: [bool; 3],
    /// The border colour as the texture's base format makes it, clamped to [0, 1].
    pub border: [f32; 4],
    /// Depth compare: function and reference (already clamped to [0, 1]).
    pub compare: Option<(CompareFunc, f32)>,
}

/// `p <func> d` with ordered comparisons except NOTEQUAL (`lp_build_sample_comparefunc`).
pub fn compare(func: CompareFunc, p: f32, d: f32) -> bool {
    func.test(p, d)
}

/// One level sampled on the SoA path. With a depth compare, every channel
/// holds the (filtered) comparison result.
pub fn soa(level: &Level<'_>, filter: Filter, dims: usize, coord: [f32; 3], st: &SoaState) -> [f32; 4] {
    soa_at(level, filter, dims, coord, st, true)
}

/// [`soa`] with normalized or (rectangle textures) unnormalized coordinates.
pub fn soa_at(
    level: &Level<'_>,
    filter: Filter,
    dims: usize,
    coord: [f32; 3],
    st: &SoaState,
    normalized: bool,
) -> [f32; 4] {
    let size = level.size();
    let texel = |x: i32, y: i32, z: i32| -> [f32; 4] {
        let p = [x, y, z];
        let outside = (0..dims).any(|a| st.border_axes[a] && !(0..size[a]).contains(&p[a]));
        if outside {
            st.border
        } else {
            level.float(x, y, z)
        }
    };
    match filter {
        Filter::Nearest => {
            let mut p = [0i32; 3];
            for a in 0..dims {
                p[a] = soa_nearest_axis(coord[a], size[a], scale(size[a], normalized), level.pot[a], st.wrap[a]);
            }
            let t = texel(p[0], p[1], p[2]);
            match st.compare {
                Some((func, r)) => [if compare(func, r, t[0]) { 1.0 } else { 0.0 }; 4],
                None => t,
            }
        }
        Filter::Linear => {
            let mut x = [[0i32; 2]; 3];
            let mut w = [0f32; 3];
            for a in 0..dims {
                let (x0, x1, wa) =
                    soa_linear_axis_at(coord[a], size[a], scale(size[a], normalized), level.pot[a], st.wrap[a]);
                x[a] = [x0, x1];
                w[a] = wa;
            }
            let t = |i: usize, j: usize, k: usize| texel(x[0][i], x[1][j], x[2][k]);
            if let Some((func, r)) = st.compare {
                // lp_build_masklerp(2d): weights where the comparison passes, summed.
                let pass = |i, j| compare(func, r, t(i, j, 0)[0]);
                let masklerp = |w: f32, m0: bool, m1: bool| {
                    let a = if m1 { w } else { 0.0 };
                    let b = if m0 { 1.0 - w } else { 0.0 };
                    a + b
                };
                let row0 = masklerp(w[0], pass(0, 0), pass(1, 0));
                if dims == 1 {
                    return [row0; 4];
                }
                let row1 = masklerp(w[0], pass(0, 1), pass(1, 1));
                return [lerp(w[1], row0, row1); 4];
            }
            blend(dims, w, t, |w, a, b| std::array::from_fn(|c| lerp(w, a[c], b[c])))
        }
    }
}

/// The SoA lerp between two levels, skipped unless the weight is positive.
pub fn soa_mip(c0: [f32; 4], c1: [f32; 4], fpart: f32) -> [f32; 4] {
    if fpart > 0.0 {
        std::array::from_fn(|c| lerp(fpart, c0[c], c1[c]))
    } else {
        c0
    }
}
