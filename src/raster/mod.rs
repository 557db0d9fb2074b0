//! Rasterization following GL's rules as llvmpipe implements them: vertices
//! snapped to 8 sub-pixel bits (round half to even), samples at pixel centers,
//! edges on the left and at the bottom (y up) own the centers on them.
//! Primitives become [`FragmentSpan`]s handed to a [`SpanSink`]: at once
//! ([`Rasterize`]), or tile by tile when a [`scene::Scene`] they were binned
//! into is flushed.
//!
//! Measured facts about llvmpipe that these rules follow: `docs/llvmpipe-facts.md`.

pub mod background;
mod block;
mod edges;
mod line;
mod pixels;
mod point;
pub mod pool;
mod rows;
pub mod scene;
pub mod stipple;
pub(crate) mod triangle;

pub use block::{tile_coverage, TileMask, TILE};
pub use edges::{Edge, Edges};
pub use line::line;
pub use point::point;
pub use rows::row_coverage;
pub use triangle::{offset, triangle, triangle_box};

use crate::framebuffer::Rect;
use crate::geometry::varying::{VaryingLayout, Varyings};
use softgl_jit::shade::{slot, Planes};
use softgl_jit::{DepthFormat, FragmentSpan};

/// Sub-pixel bits of the fixed-point grid.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed-point units.
pub const ONE: i64 = 1 << SUBPIXEL_BITS;

/// A vertex after the viewport transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterVertex {
    /// Window x, y in pixels (y up); pixel `(i, j)` has its center at `(i + 0.5, j + 0.5)`.
    pub x: f32,
    pub y: f32,
    /// The same y in llvmpipe's top-down frame (`height - y`, computed by a
    /// flipped viewport transform), which attribute interpolation works in.
    pub y_down: f32,
    /// Window depth in `[0, 1]`.
    pub z: f64,
    /// `1 / w_clip`, for perspective-correct interpolation.
    pub inv_w: f32,
    /// The varyings of [`RasterParams::layout`] (colours in `[0, 1]`).
    pub v: Varyings,
}

/// Receives the spans a primitive covers, after its planes.
pub trait SpanSink {
    fn span(&mut self, span: &FragmentSpan);
    /// Where the planes of the spans that follow (until the next call) go,
    /// or `None` when the sink reads no planes. The storage may hold an
    /// earlier primitive's planes: the rasterizer writes only the slots of
    /// its varying layout, the only ones the fragment stage reads, so that
    /// a primitive costs the slots it uses (`Planes` has 42 of them, 2 KB),
    /// not a copy of all of them.
    fn planes_mut(&mut self) -> Option<&mut Planes> {
        None
    }
    /// The fragments `x0..=x1` of row `y`, all covered, with nothing but
    /// what the planes give (their colours and depths zero): as spans of at
    /// most 64 fragments, which a sink may make without a whole
    /// [`FragmentSpan`] (536 bytes zeroed a call, and copied) per row.
    fn row(&mut self, y: u32, x0: u32, x1: u32) {
        emit_row(self, &mut FragmentSpan::new(0, 0), y, x0, x1, None);
    }
}

/// Runs `fill` on the sink's planes for the next primitive (on scratch
/// planes when the sink takes none). Inlined: a call, its closure and the
/// sink's `planes_mut` were about 45 instructions a triangle of a flush.
#[inline(always)]
pub(crate) fn with_planes<S: SpanSink + ?Sized, R>(sink: &mut S, fill: impl FnOnce(&mut Planes) -> R) -> R {
    match sink.planes_mut() {
        Some(planes) => fill(planes),
        None => fill(&mut Planes::default()),
    }
}

impl<F: FnMut(&FragmentSpan)> SpanSink for F {
    fn span(&mut self, span: &FragmentSpan) {
        self(span)
    }
}

/// Receives a draw's primitives once clipped, projected and culled.
pub trait PrimSink {
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams);
    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams);
    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams);
    /// Starts the line stipple's counter again (a polygon drawn as lines;
    /// in feedback, each triangle of an unfilled polygon): only a
    /// [`stipple::LineStipple`] and feedback's recorder keep one.
    fn reset_stipple(&mut self) {}
}

/// Rasterizes what it is handed at once into a sink of a known type: its
/// triangles' rows reach [`SpanSink::row`] by a direct call the row loop
/// inlines, not through a `dyn` (a flush's fragment stage).
pub struct Rasterize<'s, S: SpanSink>(pub &'s mut S);

impl<S: SpanSink> PrimSink for Rasterize<'_, S> {
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) {
        triangle(v, flat, params, self.0)
    }

    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams) {
        line(a, b, width, flat, params, self.0)
    }

    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams) {
        point(v, size, params, self.0)
    }
}

/// The pixels within `bounds` that a primitive reaching `reach` pixels
/// around the points `p` may cover (a box, not exact); `None` when none or
/// when a coordinate is not finite (the rasterizer draws nothing then).
pub(crate) fn reach_box(p: &[(f32, f32)], reach: f32, bounds: Rect) -> Option<Rect> {
    let mut b = [f32::INFINITY, f32::INFINITY, f32::NEG_INFINITY, f32::NEG_INFINITY];
    for &(x, y) in p {
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    }
    let clamp = |v: f32, lo: u32, hi: u32| (v.max(lo as f32).min(hi as f32)) as u32;
    let r = Rect {
        x0: clamp((b[0] - reach).floor(), bounds.x0, bounds.x1),
        y0: clamp((b[1] - reach).floor(), bounds.y0, bounds.y1),
        x1: clamp((b[2] + reach).ceil() + 1.0, bounds.x0, bounds.x1),
        y1: clamp((b[3] + reach).ceil() + 1.0, bounds.y0, bounds.y1),
    };
    (!r.is_empty()).then_some(r)
}

/// What the rasterizer needs to know about the target and the state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterParams {
    /// Fragments are produced only inside this rectangle: the framebuffer
    /// intersected with the viewport for triangles.
    pub bounds: Rect,
    /// Depth format to produce `z` for; `None` when no stage reads depth.
    pub depth: Option<DepthFormat>,
    /// Framebuffer height in pixels.
    pub height: u32,
    /// The varyings the vertices carry; the colour is interpolated only
    /// when `layout.color` (some stage reads the fragment colour).
    pub layout: VaryingLayout,
    /// Polygon offset `(factor, units)` for this primitive, if enabled.
    pub offset: Option<(f32, f32)>,
}

/// Snaps a window coordinate to the fixed-point grid whose integer multiples of
/// [`ONE`] are pixel centers: `rint((x - 0.5) * 256)` in f32, as llvmpipe does.
/// Non-finite input snaps to 0; callers drop such primitives before.
///
/// Below 2^22 units (16384 pixels) in magnitude, adding 1.5·2^23 rounds the
/// value to an integer (ties to even: the addend is even), held in the low
/// mantissa bits of the sum, which subtracting the addend's bits yields:
/// two float operations and an integer one, where `rint`, the finiteness
/// test, the clamp and the saturating conversion took 33 instructions a
/// snap, now 9 (six snaps a triangle; callgrind, lit16). The result equals
/// the `rint` path's for every f32 (checked over all 2^32 once; the tests
/// sample it).
#[inline(always)]
pub fn snap(v: f32) -> i64 {
    const MAGIC: f32 = 12_582_912.0;
    let x = (v - 0.5) * ONE as f32;
    if x.abs() < 4_194_304.0 {
        return i64::from((x + MAGIC).to_bits() as i32 - MAGIC.to_bits() as i32);
    }
    let f = rint(x);
    if f.is_finite() {
        // Clipping bounds window coordinates to the view volume; this keeps
        // edge products inside i64 whatever arrives.
        f.clamp(-((1u64 << 40) as f32), (1u64 << 40) as f32) as i64
    } else {
        0
    }
}

/// `x.round_ties_even()` without the call to libm's `rintf` it compiles to
/// on baseline x86-64 (no SSE4.1 `roundss`): 3.8% of the lit16 frame went to
/// that call. Below 2^23, adding and subtracting 2^23 rounds to the nearest
/// integer, ties to even, in the default rounding mode; from 2^23 on every f32
/// is an integer already; NaN stays NaN, and the sign (of -0.0 too) is kept.
#[inline]
pub fn rint(x: f32) -> f32 {
    const TWO_23: f32 = 8_388_608.0;
    let a = x.abs();
    if a < TWO_23 {
        ((a + TWO_23) - TWO_23).copysign(x)
    } else {
        x
    }
}

/// Converts an interpolated color channel to a unorm byte: `rint(c * 255)`.
#[inline]
pub fn color_to_unorm8(c: f32) -> u8 {
    crate::framebuffer::float_to_unorm(c, 255) as u8
}

/// The planes of a point (or anything else constant): each varying of `v`
/// and depth `z` as a constant, 1/w as 1, so that the fragment stage's
/// perspective division leaves the values exact. Texture coordinates are
/// the values llvmpipe's fragment shader reads at a point: its planes hold
/// `a·(1/w)` and it multiplies by `1/(1/w)` (`point_persp_coeff`,
/// `lp_setup_point.c`; `lp_bld_interp.c`), so `inv_w` is the vertex's 1/w.
/// Only the slots of the layout are written into `p`.
pub fn constant_planes(p: &mut Planes, v: &Varyings, z: f32, inv_w: f32, params: &RasterParams) {
    p.constant(slot::INV_W, 1.0);
    let l = params.layout;
    for (at, to, n) in [
        (l.color(), slot::COLOR, 4),
        (l.secondary(), slot::SECONDARY, 3),
        (l.fog(), slot::FOG, 1),
    ] {
        if let Some(o) = at {
            for c in 0..n {
                p.constant(to + c, v[o + c]);
            }
        }
    }
    let w = 1.0 / inv_w;
    for (unit, o) in l.tex_units() {
        for c in 0..4 {
            p.constant(slot::tex(unit) + c, v[o + c] * inv_w * w);
        }
    }
    p.constant(slot::Z, z);
}

/// Converts window depth to buffer units (clamped to `[0, 1]`).
#[inline]
pub fn depth_value(z: f64, format: Option<DepthFormat>) -> u32 {
    match format {
        Some(f) => crate::framebuffer::depth_to_unorm(z, f),
        None => 0,
    }
}

/// `floor(a / b)` for `b > 0`.
#[inline]
pub(crate) fn floor_div(a: i64, b: i64) -> i64 {
    a.div_euclid(b)
}

/// `ceil(a / b)` for `b > 0`.
#[inline]
pub(crate) fn ceil_div(a: i64, b: i64) -> i64 {
    -((-a).div_euclid(b))
}

/// Fills slot `i` of a span with the fragment at `x` (what the planes do not give).
pub(crate) type FillSlot<'a> = dyn FnMut(u32, &mut FragmentSpan, usize) + 'a;

/// The indices of the set bits of `mask`, lowest first.
#[inline]
pub(crate) fn set_bits(mask: u64) -> impl Iterator<Item = usize> {
    let mut m = mask;
    std::iter::from_fn(move || {
        (m != 0).then(|| {
            let i = m.trailing_zeros() as usize;
            m &= m - 1;
            i
        })
    })
}

/// The spans of at most [`softgl_jit::SPAN_MAX`] fragments that cover
/// `x0..=x1` (inclusive), left to right: `(x, len, mask)`.
#[inline]
pub(crate) fn row_spans(x0: u32, x1: u32) -> impl Iterator<Item = (u32, u32, u64)> {
    let mut x = x0;
    std::iter::from_fn(move || {
        (x <= x1).then(|| {
            let n = (x1 - x + 1).min(softgl_jit::SPAN_MAX as u32);
            let at = x;
            x += n;
            (at, n, if n == 64 { u64::MAX } else { (1u64 << n) - 1 })
        })
    })
}

/// Emits a row `y` from `x0` to `x1` (inclusive) in spans of at most 64 fragments,
/// with `shade(x, slot)` filling each slot when given (the planes carry
/// everything else).
pub(crate) fn emit_row<S: SpanSink + ?Sized>(
    sink: &mut S,
    span: &mut FragmentSpan,
    y: u32,
    x0: u32,
    x1: u32,
    mut shade: Option<&mut FillSlot<'_>>,
) {
    for (x, n, mask) in row_spans(x0, x1) {
        (span.x, span.y, span.len, span.mask) = (x, y, n, mask);
        if let Some(shade) = shade.as_mut() {
            for i in 0..n {
                shade(x + i, span, i as usize);
            }
        }
        sink.span(span);
    }
}

#[cfg(test)]
mod rint_tests {
    use super::rint;
    use proptest::prelude::*;

    /// Bit-identical to `round_ties_even` (NaN payloads aside: NaN stays NaN).
    fn same(x: f32) -> bool {
        let (a, b) = (rint(x), x.round_ties_even());
        (a.is_nan() && b.is_nan()) || a.to_bits() == b.to_bits()
    }

    #[test]
    fn ties_signs_and_edges() {
        let edges = [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.49999997,
            4_194_303.5,
            4_194_304.5,
            8_388_607.5,
            -8_388_607.5,
            8_388_608.0,
            16_777_217.0,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            f32::MIN_POSITIVE,
            -f32::MIN_POSITIVE,
            1e-45,
        ];
        for x in edges {
            assert!(same(x), "{x}: {} vs {}", rint(x), x.round_ties_even());
        }
    }

    /// `snap` as it was before its fast path.
    fn snap_slow(v: f32) -> i64 {
        let f = rint((v - 0.5) * super::ONE as f32);
        if f.is_finite() {
            f.clamp(-((1u64 << 40) as f32), (1u64 << 40) as f32) as i64
        } else {
            0
        }
    }

    #[test]
    fn snap_at_the_fast_paths_bounds() {
        for units in [4_194_303.5f32, 4_194_304.0, 4_194_302.5, 0.5, 1.5, 2.5, -0.5, -1.5] {
            for v in [units / 256.0 + 0.5, -units / 256.0 + 0.5] {
                for v in [
                    v,
                    f32::from_bits(v.to_bits() + 1),
                    f32::from_bits(v.to_bits().saturating_sub(1)),
                ] {
                    assert_eq!(super::snap(v), snap_slow(v), "{v}");
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]
        #[test]
        fn snap_equals_rint(bits in any::<u32>(), units in -5_000_000i32..5_000_000, half in any::<bool>()) {
            let v = f32::from_bits(bits);
            prop_assert_eq!(super::snap(v), snap_slow(v), "{}", v);
            // Window coordinates on and near the sub-pixel grid and its ties.
            let v = (units as f32 + if half { 0.5 } else { 0.0 }) / 256.0 + 0.5;
            prop_assert_eq!(super::snap(v), snap_slow(v), "{}", v);
        }

        #[test]
        fn any_bits(bits in any::<u32>()) {
            let x = f32::from_bits(bits);
            prop_assert!(same(x), "{x}");
        }

        #[test]
        fn halves(n in -20_000_000i32..20_000_000) {
            let x = n as f32 * 0.5;
            prop_assert!(same(x), "{x}");
        }
    }
}
