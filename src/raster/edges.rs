//! Triangle edge set-up: the snapped vertices made counter-clockwise, their
//! three edge functions with the top-left rule's bias, and the pixel bounding
//! box. The row rasterizer (`triangle::cover`, the coverage oracle) and the
//! block rasterizer ([`super::block`]) both start from this one value, so they
//! rasterize the very same edges.

use super::{ceil_div, floor_div, snap, RasterVertex, ONE};

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
    pub fn new(mut p: [(i64, i64); 3]) -> Option<Edges> {
        // In i128: snap() bounds coordinates to ±2^40, so products reach 2^82.
        let w = |a: i64| i128::from(a);
        let area = w(p[1].0 - p[0].0) * w(p[2].1 - p[0].1) - w(p[2].0 - p[0].0) * w(p[1].1 - p[0].1);
        if area == 0 {
            return None;
        }
        if area < 0 {
            p.swap(1, 2);
        }
        // Edge i runs from p[i] to p[i+1]; with counter-clockwise order the inside
        // is on its left. A center exactly on an edge is inside when the edge is a
        // left edge (going down) or a bottom edge (horizontal, going right).
        let edges = [0, 1, 2].map(|i| {
            let (a, b) = (p[i], p[(i + 1) % 3]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let owns = dy < 0 || (dy == 0 && dx > 0);
            Edge {
                a,
                dx,
                dy,
                k: if owns { 0 } else { 1 },
            }
        });
        let xs = p.map(|q| q.0);
        let ys = p.map(|q| q.1);
        let (min_x, max_x) = (xs.into_iter().min().unwrap_or(0), xs.into_iter().max().unwrap_or(0));
        let (min_y, max_y) = (ys.into_iter().min().unwrap_or(0), ys.into_iter().max().unwrap_or(0));
        Some(Edges {
            edges,
            px: (ceil_div(min_x, ONE), floor_div(max_x, ONE)),
            py: (ceil_div(min_y, ONE), floor_div(max_y, ONE)),
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
    pub fn window_points(v: [&RasterVertex; 3], height: u32) -> [(i64, i64); 3] {
        let top = (i64::from(height) - 1) * ONE;
        v.map(|v| (snap(v.x), top - snap(v.y_down)))
    }
}
