//! The row rasterizer: a triangle's pixels row by row, each row's run
//! found by walking its edges. It rasterized every triangle until the
//! block rasterizer ([`super::block`]) took over; it is kept as that one's
//! oracle ([`row_coverage`]: the tests prove the two equal pixel for pixel)
//! and its benchmark's baseline (`benches/raster.rs`). [`Rows::classify`]
//! (a box against the edges at its corners) is what a triangle's set-up
//! (`triangle::Prepared`) classifies its box with.

use super::block::{TileMask, TILE};
use super::edges::{Edge, Edges, SMALL};
use super::{ceil_div, floor_div, ONE};
use crate::framebuffer::Rect;

/// The pixels of `tile` (at most 64×64) within `clip` that the triangle of
/// the snapped bottom-up positions `p` (either winding) covers, found row
/// by row: the block rasterizer's oracle.
pub fn row_coverage(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    let mut mask = TileMask::empty(tile.x0, tile.y0);
    let Some(e) = Edges::new(p) else { return mask };
    let lo = |a: u32, b: u32, c: i64| i64::from(a.max(b)).max(c);
    let hi = |a: u32, b: u32, c: i64| (i64::from(a.min(b)) - 1).min(c);
    let px = (lo(tile.x0, clip.x0, e.px.0), hi(tile.x1, clip.x1, e.px.1));
    let py = (lo(tile.y0, clip.y0, e.py.0), hi(tile.y1, clip.y1, e.py.1));
    if px.0 > px.1 || py.0 > py.1 || tile.x1 - tile.x0 > TILE || tile.y1 - tile.y0 > TILE {
        return mask;
    }
    if let Some(rows) = Rows::new(&e.edges, px, py) {
        rows.each(|y, x0, x1| {
            let bits = (u64::MAX >> (63 - (x1 - x0))) << (x0 - tile.x0);
            mask.rows[(y - tile.y0) as usize] |= bits;
        });
    }
    mask
}

/// The pixels of a triangle within a box, row by row, with no division per
/// row: each edge that is not horizontal bounds a row's pixels from one side
/// and is walked exactly from row to row ([`Walk`]); a horizontal edge bounds
/// the rows, found once. The row loop's three 64-bit divisions a row were
/// most of `cover`'s time.
pub(crate) struct Rows {
    /// The box's columns, and the rows the horizontal edges keep of its rows.
    px: (i64, i64),
    py: (i64, i64),
    /// Whether every pixel centre of the box is inside (a tile a large
    /// triangle covers: no edge is walked).
    inside: bool,
    /// The edges that bound a row's pixels from the left and from the right
    /// (a triangle has one or two of each; a missing one is the box's side).
    left: [Walk; 2],
    right: [Walk; 2],
    /// How many of `left` and `right` are edges.
    sides: (usize, usize),
}

impl Rows {
    /// Whether every pixel centre of the box is inside the triangle of
    /// `edges` (`Some(true)`), some may be (`Some(false)`), or none is
    /// (`None`): from each edge function at the box's corners (it is
    /// linear: its least and greatest values over the box are at corners).
    #[inline]
    pub(crate) fn classify(edges: &[Edge; 3], px: (i64, i64), py: (i64, i64)) -> Option<bool> {
        // Below 2^29 units (2M pixels) every product and sum fits in i64
        // (|dx|, |dy| < 2^30, |y·ONE − ay| < 2^30 + 2^29): the corners cost
        // i64 arithmetic, not i128.
        let small = edges.iter().all(|e| e.a.0.abs() < SMALL && e.a.1.abs() < SMALL)
            && px.0.abs().max(px.1.abs()).max(py.0.abs()).max(py.1.abs()) < SMALL / ONE;
        let mut inside = true;
        for edge in edges {
            let (lo, hi) = if small {
                let at = |x: i64, y: i64| edge.dx * (y * ONE - edge.a.1) - edge.dy * (x * ONE - edge.a.0) - edge.k;
                let c = [at(px.0, py.0), at(px.1, py.0), at(px.0, py.1), at(px.1, py.1)];
                (c[0].min(c[1]).min(c[2].min(c[3])), c[0].max(c[1]).max(c[2].max(c[3])))
            } else {
                // In i128, exact for any snapped coordinates (as
                // `Edges::contains_box`).
                let w = |a: i64| i128::from(a);
                let at = |x: i64, y: i64| {
                    w(edge.dx) * (w(y) * w(ONE) - w(edge.a.1)) - w(edge.dy) * (w(x) * w(ONE) - w(edge.a.0)) - w(edge.k)
                };
                let c = [at(px.0, py.0), at(px.1, py.0), at(px.0, py.1), at(px.1, py.1)];
                let (lo, hi) = (c[0].min(c[1]).min(c[2].min(c[3])), c[0].max(c[1]).max(c[2].max(c[3])));
                (lo.signum() as i64, hi.signum() as i64)
            };
            if hi < 0 {
                return None;
            }
            inside &= lo >= 0;
        }
        Some(inside)
    }

    /// `None` when no pixel centre of the box is inside the triangle of `edges`.
    pub(crate) fn new(edges: &[Edge; 3], px: (i64, i64), py: (i64, i64)) -> Option<Rows> {
        let inside = Rows::classify(edges, px, py)?;
        let mut rows = Rows {
            px,
            py,
            inside,
            left: [Walk::fixed(-px.0); 2],
            right: [Walk::fixed(px.1); 2],
            sides: (2, 2),
        };
        if inside {
            return Some(rows);
        }
        // Rows first: the walks start at the first row kept.
        for &Edge { a: (_, ay), dx, dy, k } in edges {
            if dy != 0 {
                continue;
            }
            // E = dx·(py·ONE − ay) − k at row py, >= 0 on the inside; it
            // changes by s ≠ 0 (dx ≠ 0: the triangle is not degenerate) a row.
            let n = dx * (py.0 * ONE - ay) - k;
            let s = dx * ONE;
            if s > 0 {
                if n < 0 {
                    rows.py.0 = rows.py.0.max(py.0 + ceil_div(-n, s));
                }
            } else if n < 0 {
                return None;
            } else {
                rows.py.1 = rows.py.1.min(py.0 + floor_div(n, -s));
            }
        }
        if rows.py.0 > rows.py.1 {
            return None;
        }
        let (mut l, mut r) = (0, 0);
        for edge in edges {
            if edge.dy < 0 {
                rows.left[l.min(1)] = Walk::new(edge, rows.py.0);
                l += 1;
            } else if edge.dy > 0 {
                rows.right[r.min(1)] = Walk::new(edge, rows.py.0);
                r += 1;
            }
        }
        rows.sides = (l.min(2), r.min(2));
        Some(rows)
    }

    /// Runs `row(py, first, last)` for each row of the box that has pixels
    /// inside, bottom to top.
    #[inline]
    pub(crate) fn each(self, mut row: impl FnMut(u32, u32, u32)) {
        let (px0, px1) = self.px;
        if self.inside {
            for py in self.py.0..=self.py.1 {
                row(py as u32, px0 as u32, px1 as u32);
            }
            return;
        }
        // One loop per count of left and right edges: no bound is walked
        // that is not an edge's (a third of the row steps).
        let (left, right) = (&self.left[..self.sides.0], &self.right[..self.sides.1]);
        match (left, right) {
            (&[l], &[r]) => self.walk([l], [r], &mut row),
            (&[l], &[r0, r1]) => self.walk([l], [r0, r1], &mut row),
            (&[l0, l1], &[r]) => self.walk([l0, l1], [r], &mut row),
            _ => self.walk(self.left, self.right, &mut row),
        }
    }

    #[inline]
    fn walk<const L: usize, const R: usize>(
        &self,
        mut left: [Walk; L],
        mut right: [Walk; R],
        row: &mut impl FnMut(u32, u32, u32),
    ) {
        let (px0, px1) = self.px;
        for py in self.py.0..=self.py.1 {
            let lo = left.iter_mut().fold(px0, |lo, w| lo.max(-w.step()));
            let hi = right.iter_mut().fold(px1, |hi, w| hi.min(w.step()));
            if lo <= hi {
                row(py as u32, lo as u32, hi as u32);
            }
        }
    }
}

/// One edge's bound on the pixels of a row, walked from row to row with no
/// division: `E(px) = dx·(sy − ay) − dy·(px·ONE − ax) >= k` bounds `px` by
/// `floor((c − k) / (dy·ONE))` from above when `dy > 0` (from below by the
/// negated floor of `(c − k) / (−dy·ONE)` when `dy < 0`), where
/// `c = dx·(sy − ay) + dy·ax` grows by `dx·ONE` a row: the quotient and its
/// remainder step exactly.
#[derive(Clone, Copy, Debug)]
struct Walk {
    /// The bound at this row: `floor(n / d)`, and `r = n − q·d` in `0..d`.
    q: i64,
    r: i64,
    d: i64,
    /// The step of `q` and `r` a row.
    sq: i64,
    sr: i64,
}

impl Walk {
    /// A bound `q` on every row.
    const fn fixed(q: i64) -> Walk {
        Walk {
            q,
            r: 0,
            d: 1,
            sq: 0,
            sr: 0,
        }
    }

    /// The walk of an edge with `dy ≠ 0`, at row `py`.
    fn new(&Edge { a: (ax, ay), dx, dy, k }: &Edge, py: i64) -> Walk {
        let n = dx * (py * ONE - ay) + dy * ax - k;
        let s = dx * ONE;
        let d = (dy * ONE).abs();
        Walk {
            q: floor_div(n, d),
            r: n.rem_euclid(d),
            d,
            sq: floor_div(s, d),
            sr: s.rem_euclid(d),
        }
    }

    /// This row's `q`; steps to the next row.
    #[inline]
    fn step(&mut self) -> i64 {
        let q = self.q;
        self.q += self.sq;
        self.r += self.sr;
        if self.r >= self.d {
            self.r -= self.d;
            self.q += 1;
        }
        q
    }
}
