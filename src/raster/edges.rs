//! Triangle edge set-up: the snapped vertices made counter-clockwise, their
//! three edge functions with the top-left rule's bias, and the pixel bounding
//! box. The row rasterizer (`triangle::cover`, the coverage oracle) and the
//! block rasterizer ([`super::block`]) both start from this one value, so they
//! rasterize the very same edges.

use super::{snap, RasterVertex, ONE};

/// One edge of a counter-clockwise triangle, from `a` to `a + (dx, dy)`
/// (fixed point, y up). A pixel center `s` (fixed point) is on the inside when
/// `E(s) = dx·(s.y − a.y) − dy·(s.x − a.x) >= k`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Edge {
    pub a: (i64, i64),
    pub dx: i64,
    pub dy: i64,
    /// 0 when the edge owns the centers on it (a left edge, going down, or
    /// a bottom edge, horizontal going right), else 1.
    pub k: i64,
}

/// A non-degenerate triangle's edges and the pixels its bounding box spans.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Edges {
    pub edges: [Edge; 3],
    /// Inclusive pixel ranges `(first, last)` of the centers within the
    /// bounding box; unclipped.
    pub px: (i64, i64),
    pub py: (i64, i64),
}

impl Edges {
    /// The edges of the triangle of snapped bottom-up positions `p`, either
    /// winding; `None` when its area is zero (it covers nothing).
    pub fn new(p: [(i64, i64); 3]) -> Option<Edges> {
        let p = ccw(p, small(&p))?;
        let (min_x, max_x) = (p[0].0.min(p[1].0).min(p[2].0), p[0].0.max(p[1].0).max(p[2].0));
        let (min_y, max_y) = (p[0].1.min(p[1].1).min(p[2].1), p[0].1.max(p[1].1).max(p[2].1));
        Some(Edges {
            edges: edges_of(p),
            px: (ceil_one(min_x), floor_one(max_x)),
            py: (ceil_one(min_y), floor_one(max_y)),
        })
    }

    /// Whether every pixel centre of the box `x0..=x1` × `y0..=y1` is inside
    /// the triangle: all four corners are (an edge function is linear, so
    /// its least value over a rectangle is at a corner). In i128, exact for
    /// any snapped coordinates.
    pub fn contains_box(&self, (x0, x1): (i64, i64), (y0, y1): (i64, i64)) -> bool {
        self.edges.iter().all(|e| {
            [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].iter().all(|&(x, y)| {
                let w = |a: i64| i128::from(a);
                w(e.dx) * (w(y) * w(ONE) - w(e.a.1)) - w(e.dy) * (w(x) * w(ONE) - w(e.a.0)) >= w(e.k)
            })
        })
    }

    /// The edges of the triangle [`super::triangle`] rasterizes for `v` in a
    /// framebuffer `height` rows high: x snapped, and llvmpipe's top-down y
    /// snapped then reflected into GL rows (docs/llvmpipe-facts.md 2).
    pub fn window(v: [&RasterVertex; 3], height: u32) -> Option<Edges> {
        Edges::new(Edges::window_points(v, height))
    }

    /// The snapped bottom-up positions of `v`: llvmpipe snaps its top-down y,
    /// whose f32 value can round apart from the bottom-up one (to a tie, or
    /// across one); the snapped value is reflected exactly into GL rows.
    #[inline(always)]
    pub fn window_points(v: [&RasterVertex; 3], height: u32) -> [(i64, i64); 3] {
        let top = (i64::from(height) - 1) * ONE;
        let at = |v: &RasterVertex| (snap(v.x), top - snap(v.y_down));
        [at(v[0]), at(v[1]), at(v[2])]
    }
}

/// Below this (2^29 units, 2M pixels) a snapped coordinate is small: the
/// differences of two are below 2^30 and an area or an edge function at a
/// pixel centre within ±2^21 pixels fits in i64 (no i128).
pub(crate) const SMALL: i64 = 1 << 29;

/// Whether every coordinate of `p` is [`SMALL`].
#[inline(always)]
pub(crate) fn small(p: &[(i64, i64); 3]) -> bool {
    p.iter().all(|q| q.0.abs() < SMALL && q.1.abs() < SMALL)
}

/// `p` made counter-clockwise (the last two swapped when clockwise); `None`
/// when its area is zero. In i128 unless `small` ([`small`]): `snap` bounds
/// coordinates to ±2^40, so products reach 2^82.
#[inline(always)]
pub(crate) fn ccw(p: [(i64, i64); 3], small: bool) -> Option<[(i64, i64); 3]> {
    let negative = if small {
        let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
        if area == 0 {
            return None;
        }
        area < 0
    } else {
        let w = |a: i64| i128::from(a);
        let area = w(p[1].0 - p[0].0) * w(p[2].1 - p[0].1) - w(p[2].0 - p[0].0) * w(p[1].1 - p[0].1);
        if area == 0 {
            return None;
        }
        area < 0
    };
    Some(if negative { [p[0], p[2], p[1]] } else { p })
}

/// The edges of the counter-clockwise triangle `p`: edge i runs from p[i]
/// to p[i+1], the inside on its left. A center exactly on an edge is inside
/// when the edge is a left edge (going down) or a bottom edge (horizontal,
/// going right).
#[inline(always)]
pub(crate) fn edges_of(p: [(i64, i64); 3]) -> [Edge; 3] {
    let edge = |a: (i64, i64), b: (i64, i64)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let owns = dy < 0 || (dy == 0 && dx > 0);
        Edge {
            a,
            dx,
            dy,
            k: i64::from(!owns),
        }
    };
    [edge(p[0], p[1]), edge(p[1], p[2]), edge(p[2], p[0])]
}

/// `floor(a / ONE)`: an arithmetic shift.
#[inline(always)]
pub(crate) fn floor_one(a: i64) -> i64 {
    a >> super::SUBPIXEL_BITS
}

/// `ceil(a / ONE)`.
#[inline(always)]
pub(crate) fn ceil_one(a: i64) -> i64 {
    -((-a) >> super::SUBPIXEL_BITS)
}
