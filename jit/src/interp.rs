//! The reference interpreter: runs the stages of a [`FragmentKey`] over spans.
//!
//! Written to be read, not to be fast: each stage is a loop over the live
//! fragments of a span, in GL order. Every back end must leave the buffers
//! exactly as this one does.

use crate::key::{
    AlphaCoverage, BlendEquation, BlendFactor, BlendKey, ColorMask, DepthKey, FragmentKey, KeyError, Stage, StencilKey,
    StencilOp,
};
use crate::pixel;
use crate::shade::{self, Planes};
use crate::span::{FragmentSpan, SPAN_MAX};
use crate::target::Target;
use crate::texture::TextureSet;
use crate::uniforms::FragmentUniforms;

/// Why a batch could not run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FragmentError {
    #[error("invalid fragment key: {0}")]
    Key(#[from] KeyError),
    #[error("the key's buffers do not match the target's")]
    TargetMismatch,
    #[error("a span names planes the batch does not have")]
    MissingPlanes,
}

/// Checks that `key` is valid and names exactly the buffers `target` has.
pub fn check_key(key: &FragmentKey, target: &Target<'_>) -> Result<(), FragmentError> {
    key.validate()?;
    if key.color_format != target.color_format()
        || key.depth_format != target.depth_format()
        || key.stencil_buffer != target.has_stencil()
    {
        return Err(FragmentError::TargetMismatch);
    }
    Ok(())
}

/// Runs `key`'s stages over `spans` into `target`. Fragments outside the target
/// fail GL's pixel ownership test and are dropped.
pub fn run(
    key: &FragmentKey,
    uniforms: &FragmentUniforms,
    spans: &[FragmentSpan],
    target: &mut Target<'_>,
) -> Result<(), FragmentError> {
    run_with_planes(key, uniforms, &TextureSet::default(), spans, &[], target)
}

/// [`run`] for keys with a shading stage: span `s` is of the primitive
/// whose planes are `planes[s.planes]`; textured units sample `textures`.
pub fn run_with_planes(
    key: &FragmentKey,
    uniforms: &FragmentUniforms,
    textures: &TextureSet<'_>,
    spans: &[FragmentSpan],
    planes: &[Planes],
    target: &mut Target<'_>,
) -> Result<(), FragmentError> {
    check_key(key, target)?;
    check_planes(key, spans, planes)?;
    let stages = key.stages();
    for span in spans {
        let p = planes.get(span.planes as usize).copied().unwrap_or_default();
        run_span(key, stages.as_slice(), (uniforms, textures), (span, &p), target);
    }
    Ok(())
}

/// Checks that every span of a key with a shading stage has its planes.
pub fn check_planes(key: &FragmentKey, spans: &[FragmentSpan], planes: &[Planes]) -> Result<(), FragmentError> {
    if key.shade.is_some() && spans.iter().any(|s| s.planes as usize >= planes.len()) {
        return Err(FragmentError::MissingPlanes);
    }
    Ok(())
}

/// The row of `y` in llvmpipe's top-down frame of a target `height` high.
#[inline]
pub fn row_of(y: u32, height: u32) -> f32 {
    height.saturating_sub(y + 1) as f32
}

fn run_span(
    key: &FragmentKey,
    stages: &[Stage],
    (u, textures): (&FragmentUniforms, &TextureSet<'_>),
    (span, planes): (&FragmentSpan, &Planes),
    t: &mut Target<'_>,
) {
    if key.color_format.is_deep() {
        return crate::deep::run_span(key, stages, (u, textures), (span, planes), t);
    }
    let mut live = t.owned_mask(span);
    if live == 0 {
        return;
    }
    let format = key.color_format;
    let bpp = format.bytes_per_pixel();
    let (y, x0) = (span.y, span.x);
    let mut rgba = [[0u8; 4]; SPAN_MAX];
    for (i, c) in rgba.iter_mut().enumerate() {
        *c = [span.r[i], span.g[i], span.b[i], span.a[i]];
    }
    let mut packed = [0u32; SPAN_MAX];
    let mut z = span.z;
    // The shaded alpha in f32, for alpha to coverage (a span's colour: its
    // byte times 1/255).
    let coverage = key.shade.is_some_and(|s| s.coverage.quarters.is_some());
    let mut alpha = [0.0f32; SPAN_MAX];
    if coverage {
        for (a, &b) in alpha.iter_mut().zip(&span.a) {
            *a = f32::from(b) * (1.0 / 255.0);
        }
    }

    for stage in stages {
        match *stage {
            Stage::Shade(shade) => {
                let row = row_of(y, t.height());
                for i in lanes(live) {
                    let px = (x0 + i as u32) as f32;
                    let (c, d) = if coverage {
                        let (c, d) = shade::fragment_f32(&shade, planes, (px, row), &u.fog, key.depth_format, textures);
                        if let Some(c) = c {
                            alpha[i] = c[3];
                        }
                        (c.map(|c| c.map(shade::unorm8)), d)
                    } else {
                        shade::fragment(&shade, planes, (px, row), &u.fog, key.depth_format, textures)
                    };
                    if let Some(c) = c {
                        rgba[i] = c;
                    }
                    if let Some(d) = d {
                        z[i] = d;
                    }
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
                    if !func.test(rgba[i][3], u.alpha_ref) {
                        live &= !(1 << i);
                    }
                }
            }
            Stage::AlphaCoverage(c) => {
                for i in lanes(live) {
                    if let Some(q) = c.quarters {
                        // `!(a > t)`: NaN fails.
                        if !AlphaCoverage::keeps(alpha[i], q) {
                            live &= !(1 << i);
                        }
                    }
                    if c.to_one {
                        rgba[i][3] = 255;
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
                    let off = off0 + i * bpp;
                    let dst = pixel::unpack(format, pixel::load(format, &color[off..]));
                    rgba[i] = blend_rgba(&blend, rgba[i], dst, u.blend_color);
                }
            }
            Stage::Pack { dither } => {
                for i in lanes(live) {
                    let bias = dither.then(|| pixel::dither_bias(x0 + i as u32, y));
                    packed[i] = pixel::pack(format, rgba[i], bias);
                }
            }
            Stage::LogicOp(op) => {
                let off0 = t.color_offset(x0, y);
                let color = t.color();
                for i in lanes(live) {
                    let dst = pixel::load(format, &color[off0 + i * bpp..]);
                    packed[i] = op.apply(packed[i], dst);
                }
            }
            Stage::ColorWrite(mask) => {
                let bits = pixel::mask_bits(format, mask);
                let all = pixel::mask_bits(format, ColorMask::ALL);
                let off0 = t.color_offset(x0, y);
                let color = t.color_mut();
                for i in lanes(live) {
                    let px = &mut color[off0 + i * bpp..];
                    let value = if bits == all {
                        packed[i]
                    } else {
                        (packed[i] & bits) | (pixel::load(format, px) & !bits)
                    };
                    pixel::store(format, px, value);
                }
            }
        }
    }
}

/// The stencil test of the fragments `live` of the span at `(x0, y)`, and
/// its `fail` op (with `zpass` too when the depth test is off).
pub(crate) fn stencil_stage(
    stencil: StencilKey,
    depth_on: bool,
    u: &FragmentUniforms,
    (x0, y): (u32, u32),
    live: &mut u64,
    t: &mut Target<'_>,
) {
    let idx0 = t.index(x0, y);
    let Some(buf) = t.stencil_mut() else { return };
    for i in lanes(*live) {
        let s = &mut buf[idx0 + i];
        let pass = stencil
            .func
            .test(u.stencil_ref & u.stencil_value_mask, *s & u.stencil_value_mask);
        if !pass {
            *s = stencil_write(stencil.fail, *s, u);
            *live &= !(1 << i);
        } else if !depth_on {
            *s = stencil_write(stencil.zpass, *s, u);
        }
    }
}

/// The depth test of the fragments `live` of the span at `(x0, y)` with
/// depths `z`, its write, and the stencil's `zfail`/`zpass` ops.
pub(crate) fn depth_stage(
    depth: DepthKey,
    stencil: Option<StencilKey>,
    u: &FragmentUniforms,
    (x0, y, z): (u32, u32, &[u32; SPAN_MAX]),
    live: &mut u64,
    t: &mut Target<'_>,
) {
    let idx0 = t.index(x0, y);
    let (_, depth_buf, stencil_buf) = t.parts_mut();
    let Some(dbuf) = depth_buf else { return };
    let max = dbuf.format().max_value();
    let mut stencil_buf = stencil_buf;
    for i in lanes(*live) {
        let z = z[i].min(max);
        let pass = depth.func.test(z, dbuf.get(idx0 + i));
        if pass && depth.write {
            dbuf.set(idx0 + i, z);
        }
        if let (Some(StencilKey { zfail, zpass, .. }), Some(sbuf)) = (stencil, stencil_buf.as_deref_mut()) {
            let s = &mut sbuf[idx0 + i];
            *s = stencil_write(if pass { zpass } else { zfail }, *s, u);
        }
        if !pass {
            *live &= !(1 << i);
        }
    }
}

/// The indices of the set bits of `mask`, lowest first.
pub(crate) fn lanes(mask: u64) -> impl Iterator<Item = usize> {
    let mut m = mask;
    std::iter::from_fn(move || {
        if m == 0 {
            return None;
        }
        let i = m.trailing_zeros() as usize;
        m &= m - 1;
        Some(i)
    })
}

/// The stencil value after `op`, through the write mask.
pub fn stencil_write(op: StencilOp, stored: u8, u: &FragmentUniforms) -> u8 {
    let new = op.apply(stored, u.stencil_ref);
    (new & u.stencil_write_mask) | (stored & !u.stencil_write_mask)
}

/// GL's blend of `src` over `dst` (unorm bytes RGBA) with constant color `k`.
pub fn blend_rgba(key: &BlendKey, src: [u8; 4], dst: [u8; 4], k: [u8; 4]) -> [u8; 4] {
    let mut out = [0u8; 4];
    for c in 0..4 {
        let (sf, df, eq) = if c < 3 {
            (key.src_rgb, key.dst_rgb, key.eq_rgb)
        } else {
            (key.src_alpha, key.dst_alpha, key.eq_alpha)
        };
        let s = pixel::mul_unorm8(src[c], factor(sf, c, src, dst, k));
        let d = pixel::mul_unorm8(dst[c], factor(df, c, src, dst, k));
        out[c] = equation(eq, src[c], dst[c], s, d);
    }
    out
}

/// A channel type GL blends in: unorm bytes (the 8-bit formats), 16-bit
/// unorm (`ColorFormat::Rgba16`) and f32 (`ColorFormat::Rgba32F`). Each
/// back end's factors are [`factor`] over one of these.
pub trait BlendChannel: Copy {
    /// The factor `GL_ONE`: 255, 65535 or 1.0.
    const ONE: Self;
    /// The factor `GL_ZERO`.
    const ZERO: Self;
    /// `ONE - self` (exact for the integer types, one f32 subtraction).
    fn one_minus(self) -> Self;
    /// `self < other ? self : other`: integer `min`, and for f32 the x86
    /// `minps(self, other)` llvmpipe's `lp_build_min` is (the second operand
    /// where either is NaN; docs/llvmpipe-facts.md §41).
    fn min_of(self, other: Self) -> Self;
}

impl BlendChannel for u8 {
    const ONE: u8 = u8::MAX;
    const ZERO: u8 = 0;
    fn one_minus(self) -> u8 {
        u8::MAX - self
    }
    fn min_of(self, other: u8) -> u8 {
        self.min(other)
    }
}

impl BlendChannel for u16 {
    const ONE: u16 = u16::MAX;
    const ZERO: u16 = 0;
    fn one_minus(self) -> u16 {
        u16::MAX - self
    }
    fn min_of(self, other: u16) -> u16 {
        self.min(other)
    }
}

impl BlendChannel for f32 {
    const ONE: f32 = 1.0;
    const ZERO: f32 = 0.0;
    fn one_minus(self) -> f32 {
        1.0 - self
    }
    fn min_of(self, other: f32) -> f32 {
        if self < other {
            self
        } else {
            other
        }
    }
}

/// The value of factor `f` for channel `c` (3 is alpha), in any channel type.
pub fn factor<T: BlendChannel>(f: BlendFactor, c: usize, src: [T; 4], dst: [T; 4], k: [T; 4]) -> T {
    match f {
        BlendFactor::Zero => T::ZERO,
        BlendFactor::One => T::ONE,
        BlendFactor::SrcColor => src[c],
        BlendFactor::OneMinusSrcColor => src[c].one_minus(),
        BlendFactor::DstColor => dst[c],
        BlendFactor::OneMinusDstColor => dst[c].one_minus(),
        BlendFactor::SrcAlpha => src[3],
        BlendFactor::OneMinusSrcAlpha => src[3].one_minus(),
        BlendFactor::DstAlpha => dst[3],
        BlendFactor::OneMinusDstAlpha => dst[3].one_minus(),
        BlendFactor::ConstantColor => k[c],
        BlendFactor::OneMinusConstantColor => k[c].one_minus(),
        BlendFactor::ConstantAlpha => k[3],
        BlendFactor::OneMinusConstantAlpha => k[3].one_minus(),
        BlendFactor::SrcAlphaSaturate => {
            if c == 3 {
                T::ONE
            } else {
                src[3].min_of(dst[3].one_minus())
            }
        }
    }
}

/// Equation `eq` on weighted terms `s`, `d` (MIN and MAX use the unweighted colors).
pub fn equation(eq: BlendEquation, src: u8, dst: u8, s: u8, d: u8) -> u8 {
    match eq {
        BlendEquation::Add => s.saturating_add(d),
        BlendEquation::Subtract => s.saturating_sub(d),
        BlendEquation::ReverseSubtract => d.saturating_sub(s),
        BlendEquation::Min => src.min(dst),
        BlendEquation::Max => src.max(dst),
    }
}
