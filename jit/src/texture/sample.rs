//! The reference sampler: one fragment's texture colour as llvmpipe computes
//! it (`lp_build_sample_soa_code` in `lp_bld_sample_soa.c`;
//! `docs/llvmpipe-facts.md` §16).
//!
//! Per fragment: the coordinates are projected (`s·(1/q)`, Mesa's TXP
//! lowering), λ comes from the fragment's 2×2 quad (per pixel for cube maps
//! with mipmaps), the levels and the min/mag filter follow from λ, and one
//! of llvmpipe's two paths filters them ([`super::filter`]).

use super::arith::{maxps, minps};
use super::filter::{self, Level, SoaState};
use super::lod::{self, Lod, LodState};
use super::{
    BaseFormat, DepthMode, Image, MipFilter, SamplerKey, TexTarget, TexUnitKey, TexelFormat, TextureRef, Wrap,
};

/// The filtered RGBA of `tex` at texture coordinates `at` = (s, t, r, q) of
/// the fragment, with `quad` the coordinates at the top-left, top-right and
/// bottom-left pixels of its 2×2 quad (llvmpipe's frame: quads at even `px`
/// and even `row`), for λ. All coordinates are before projection: the
/// sampler divides s, t, r by q.
///
/// Exact for every target except cube maps whose λ llvmpipe takes per pixel
/// (a mipmap filter, or different min and mag filters): each pixel is then
/// differentiated along its own row and column, which needs the quad's
/// bottom-right pixel too; use [`sample_quad`] for those (here a fragment
/// that is not the bottom-right one extrapolates it as top-right +
/// bottom-left − top-left).
pub fn sample(unit: &TexUnitKey, tex: &TextureRef<'_>, at: [f32; 4], quad: [[f32; 4]; 3]) -> [f32; 4] {
    let [tl, tr, bl] = quad;
    match quad.iter().position(|&c| c == at) {
        Some(lane) => {
            let br = std::array::from_fn(|c| tr[c] + bl[c] - tl[c]);
            sample_quad(unit, tex, &[tl, tr, bl, br], lane)
        }
        None => sample_quad(unit, tex, &[tl, tr, bl, at], 3),
    }
}

/// [`sample`] from the coordinates (before projection) at all four pixels
/// of the quad (top-left, top-right, bottom-left, bottom-right) for the
/// pixel `lane` (0..4, same order). Exact for every target.
pub fn sample_quad(unit: &TexUnitKey, tex: &TextureRef<'_>, quad: &[[f32; 4]; 4], lane: usize) -> [f32; 4] {
    QuadSample::new(unit, tex, quad).lane(lane)
}

/// [`sample_quad`] split at the quad: what it derives once for the quad's
/// four pixels (the projected coordinates, λ and its levels unless λ is per
/// pixel, the filtering's facts about the texture), then
/// [`QuadSample::lane`] per pixel, the same bits as `sample_quad(.., lane)`
/// for each. The callout samples a group's lanes this way
/// (`crate::callout::texture_group`): per lane it projected the quad's four
/// pixels (four divisions) and set up λ and the filter again.
#[derive(Clone, Copy, Debug)]
pub struct QuadSample<'a> {
    unit: &'a TexUnitKey,
    tex: &'a TextureRef<'a>,
    /// The quad's coordinates times `1/q` (Mesa's TXP lowering).
    proj: [[f32; 4]; 4],
    state: LodState,
    /// λ's levels, unless λ is per pixel (cube maps with a mipmap filter or
    /// different min and mag filters, computed by [`QuadSample::lane`]).
    lod: Option<Lod>,
    /// Level 0's sizes are powers of two ([`pot`]).
    pot: [bool; 3],
}

impl<'a> QuadSample<'a> {
    /// The quad's shared part, from its coordinates before projection (as
    /// [`sample_quad`] takes them).
    pub fn new(unit: &'a TexUnitKey, tex: &'a TextureRef<'a>, quad: &[[f32; 4]; 4]) -> QuadSample<'a> {
        let key = &unit.sampler;
        // Mesa's TXP lowering: coordinates (and the shadow reference) times frcp(q).
        let proj = quad.map(|c| {
            let inv = 1.0 / c[3];
            [c[0] * inv, c[1] * inv, c[2] * inv, c[3] * inv]
        });
        let first = tex.base_level;
        let last = tex.max_level.max(first);
        let state = LodState::new(key, tex);
        let levels = |l: (bool, i32, f32)| lod::levels(key.mip, l, first, last);
        let no_lod = Lod {
            minified: false,
            level0: first,
            level1: first,
            weight: 0.0,
        };
        let lod = if key.target == TexTarget::Cube {
            let need = lod::needs_lod(key) && !state.min_max_equal;
            if need {
                None
            } else if lod::needs_lod(key) {
                Some(levels(lod::select(key.mip, &state, 0.0, true)))
            } else {
                Some(no_lod)
            }
        } else if lod::needs_lod(key) {
            let c = |p: usize| [proj[p][0], proj[p][1], proj[p][2]];
            let (rho, squared) = lod::rho_quad(dims(key.target), base_size(tex, key.target), c(0), c(1), c(2));
            Some(levels(lod::select(key.mip, &state, rho, squared)))
        } else {
            Some(no_lod)
        };
        QuadSample {
            unit,
            tex,
            proj,
            state,
            lod,
            pot: pot(tex, key.target),
        }
    }

    /// The filtered RGBA of the quad's pixel `lane` (0..4; larger is 3).
    pub fn lane(&self, lane: usize) -> [f32; 4] {
        let (unit, tex, proj) = (self.unit, self.tex, &self.proj);
        let key = &unit.sampler;
        let lane = lane.min(3);
        let reference = proj[lane][reference_component(key.target)];
        let dir = |p: usize| [proj[p][0], proj[p][1], proj[p][2]];
        let (face, coord, lod) = match (key.target, self.lod) {
            (TexTarget::Cube, Some(lod)) => {
                let (face, st) = super::cube::lookup(dir(lane));
                (face, [st[0], st[1], 0.0], lod)
            }
            (TexTarget::Cube, None) => {
                // Per pixel: derivatives along the pixel's own row and column.
                let at = |p: usize| {
                    let (row, col) = (p & 2, p & 1);
                    let ddx: [f32; 3] = std::array::from_fn(|c| dir(row + 1)[c] - dir(row)[c]);
                    let ddy: [f32; 3] = std::array::from_fn(|c| dir(col + 2)[c] - dir(col)[c]);
                    super::cube::lookup_derivs(dir(p), ddx, ddy)
                };
                let size = base_size(tex, key.target);
                let rho = |p: usize| {
                    let (_, _, dx, dy) = at(p);
                    lod::rho_derivs([size[0], size[1]], dx, dy)
                };
                // With a mipmap filter λ is per pixel; else per quad, the top-left pixel's.
                let rho = if key.mip != MipFilter::None { rho(lane) } else { rho(0) };
                let (face, st, _, _) = at(lane);
                let first = tex.base_level;
                let lod = lod::levels(
                    key.mip,
                    lod::select(key.mip, &self.state, rho, true),
                    first,
                    tex.max_level.max(first),
                );
                (face, [st[0], st[1], 0.0], lod)
            }
            (_, lod) => {
                let lod = lod.unwrap_or(Lod {
                    minified: false,
                    level0: tex.base_level,
                    level1: tex.base_level,
                    weight: 0.0,
                });
                (0, dir(lane), lod)
            }
        };
        let out = filter_levels(unit, tex, self.pot, (face, coord), &lod, reference);
        match key.format {
            TexelFormat::Depth32F => depth_swizzle(key.depth_mode, out[0]),
            _ => out,
        }
    }
}

/// Texture coordinates the target filters (cube maps: 2, the face's s and t).
fn dims(target: TexTarget) -> usize {
    match target {
        TexTarget::D1 => 1,
        TexTarget::D2 | TexTarget::Cube | TexTarget::Rect => 2,
        TexTarget::D3 => 3,
    }
}

/// Which coordinate is the depth reference: the one after the target's
/// coordinates (Mesa's fixed-function shader: t for 1D, r for 2D, q for cube).
fn reference_component(target: TexTarget) -> usize {
    match target {
        TexTarget::D1 => 1,
        TexTarget::D2 | TexTarget::D3 | TexTarget::Rect => 2,
        TexTarget::Cube => 3,
    }
}

/// The image of `level` (and `face`), if the texture has it.
fn image<'a>(tex: &'a TextureRef<'a>, target: TexTarget, level: u32, face: u32) -> Option<&'a Image<'a>> {
    let i = match target {
        TexTarget::Cube => level as usize * 6 + face as usize,
        _ => level as usize,
    };
    tex.images.get(i).filter(|im| !im.texels.is_empty())
}

/// The base level's size as floats (λ is measured in its texels). Rectangle
/// textures too: `lp_build_rho` scales the derivatives by the size whether
/// or not the coordinates are normalized, so their λ (with min ≠ mag) is
/// the size times a texel-unit ρ, as on llvmpipe.
fn base_size(tex: &TextureRef<'_>, target: TexTarget) -> [f32; 3] {
    image(tex, target, tex.base_level, 0)
        .map_or([1.0; 3], |im| [im.width, im.height, im.depth].map(|v| v.max(1) as f32))
}

/// Whether level 0's sizes are powers of two (the resource's `width0` …).
pub(crate) fn pot(tex: &TextureRef<'_>, target: TexTarget) -> [bool; 3] {
    let im = image(tex, target, 0, 0).or_else(|| image(tex, target, tex.base_level, 0));
    im.map_or([true; 3], |im| {
        [im.width, im.height, im.depth].map(|v| v.max(1).is_power_of_two())
    })
}

/// Whether llvmpipe takes the 8-bit AoS path for this sampler
/// (`use_aos` in `lp_build_sample_soa_code`).
pub fn uses_aos(key: &SamplerKey) -> bool {
    if key.format != TexelFormat::Rgba8 || key.compare.is_some() {
        return false;
    }
    if key.target == TexTarget::Cube {
        // Wraps are CLAMP_TO_EDGE; λ per pixel (mipmaps) excludes min ≠ mag.
        return key.mip == MipFilter::None || key.min == key.mag;
    }
    key.wrap[..dims(key.target)].iter().all(|&w| filter::simple_wrap(w))
}

/// Samples the level(s) `lod` selects with the filter it selects.
fn filter_levels(
    unit: &TexUnitKey,
    tex: &TextureRef<'_>,
    pot: [bool; 3],
    (face, coord): (u32, [f32; 3]),
    lod: &Lod,
    reference: f32,
) -> [f32; 4] {
    let key = &unit.sampler;
    let dims = dims(key.target);
    let (img_filter, mip) = lod::filter(key, lod.minified);
    let level = |l: u32| {
        image(tex, key.target, l, face).map(|im| Level {
            image: im,
            format: key.format,
            pot,
        })
    };
    let wrap = if key.target == TexTarget::Cube {
        [Wrap::ClampToEdge; 3]
    } else {
        key.wrap
    };
    let second = mip == MipFilter::Linear;
    if uses_aos(key) {
        let one = |l: u32| {
            level(l).map_or([0; 4], |lv| {
                filter::aos_at(&lv, img_filter, dims, coord, wrap, key.target.normalized())
            })
        };
        let mut c = one(lod.level0);
        if second {
            let w = lod.weight;
            if super::arith::itrunc(w * 256.0) > 0 {
                c = filter::aos_mip(c, one(lod.level1), w);
            }
        }
        return c.map(super::arith::unorm8_to_float);
    }
    let st = SoaState {
        wrap,
        border_axes: std::array::from_fn(|a| filter::uses_border(wrap[a], key.min, key.mag)),
        border: match tex.float_depth {
            true => [tex.border[0], 0.0, 0.0, 1.0],
            false => border(tex.border, unit.base, key.format),
        },
        compare: key.compare.map(|f| match tex.float_depth {
            true => (f, reference),
            false => (f, minps(maxps(reference, 0.0), 1.0)),
        }),
    };
    let one = |l: u32| {
        level(l).map_or([0.0; 4], |lv| {
            filter::soa_at(&lv, img_filter, dims, coord, &st, key.target.normalized())
        })
    };
    let c = one(lod.level0);
    if second && lod.weight > 0.0 {
        filter::soa_mip(c, one(lod.level1), lod.weight)
    } else {
        c
    }
}

/// The border colour as sampled: the GL border in the base format's
/// channels (`st_translate_color`: luminance r,r,r,1 …; llvmpipe replaces
/// only the channels its format stores, which comes to the same), for depth
/// textures the red, clamped to [0, 1] (`lp_build_clamp_border_color`, unorm
/// formats).
fn border(b: [f32; 4], base: BaseFormat, format: TexelFormat) -> [f32; 4] {
    let c = match (format, base) {
        (TexelFormat::Depth32F, _) => [b[0], 0.0, 0.0, 1.0],
        (_, BaseFormat::Alpha) => [0.0, 0.0, 0.0, b[3]],
        (_, BaseFormat::Luminance) => [b[0], b[0], b[0], 1.0],
        (_, BaseFormat::LuminanceAlpha) => [b[0], b[0], b[0], b[3]],
        (_, BaseFormat::Intensity) => [b[0]; 4],
        (_, BaseFormat::Rgb) => [b[0], b[1], b[2], 1.0],
        (_, BaseFormat::Rgba | BaseFormat::Depth) => b,
    };
    c.map(|v| minps(maxps(v, 0.0), 1.0))
}

/// `GL_DEPTH_TEXTURE_MODE` applied to the depth (or comparison) value `x`
/// (the sampler view swizzle of `compute_texture_format_swizzle`, `teximage.c`).
fn depth_swizzle(mode: DepthMode, x: f32) -> [f32; 4] {
    match mode {
        DepthMode::Luminance => [x, x, x, 1.0],
        DepthMode::Intensity => [x; 4],
        DepthMode::Alpha => [0.0, 0.0, 0.0, x],
    }
}
