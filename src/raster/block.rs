//! The block rasterizer: a triangle's coverage of one 64×64 tile as row
//! masks, found hierarchically from the same [`Edges`] the row rasterizer
//! (`rows::row_coverage`, the oracle) walks, with the same exact test per
//! pixel. It is what a flush's tiles find their triangles' pixels with
//! (`triangle::Prepared::cover`, for a triangle whose pixels were not all
//! decided when it was set up); each covered row becomes one span with its
//! mask for the specialist (a triangle's pixels in a row are one run).
//!
//! The tile is classified against each edge at its corners first: a tile
//! no pixel of which is inside costs nothing more, one wholly inside sets
//! its rows. Otherwise its 16×16 blocks are classified against each edge
//! that does not accept the whole tile, from the edge function at a corner
//! and its extreme over the block: rejected blocks cost nothing more, fully
//! covered ones set their bits without a per-pixel test, and partial ones
//! are split into 4×4 blocks, classified the same way against the edges
//! that do not accept the whole 16×16 block; only partial 4×4 blocks are
//! evaluated per pixel.
//!
//! Exactness: an edge's value at the tile's origin is computed in i128
//! (snapped coordinates are within ±2^40, so it can reach 2^82). An edge
//! kept for the tile has both signs over it, so its values there are small.
//! Edges shorter than 2^24 units (every edge within the largest viewport)
//! are tested in i32 with the sub-pixel bits divided out ([`Narrow`]),
//! sixteen values at once in four `wide::i32x4` lanes; longer ones in i64
//! (`wide`, the exact general form, tested at the snap limits).
//!
//! Speed: the hierarchy pays where blocks are whole; where a tile is crossed
//! by edges, finding a row's run by walking each edge (the row rasterizer:
//! about 12 instructions a row) is cheaper than testing blocks. Against the
//! row rasterizer, callgrind, one thread, instructions a frame of
//! `osmesa/bench/fill.c`: tris 626 M → 654 M, thrash 78.6 M → 82.6 M, lit16
//! 2285 M → 2280 M; in time, medians of 5 interleaved runs (2 shared
//! cores), one thread and two: tris 1.13x and 1.11x, ops 1.11x and 1.00x,
//! tex 1.05x and 1.01x, thrash 1.06x and 0.96x. On the way there: the i64
//! form with scalar lanes cost 722 M on tris; sixteen values a test in i32
//! lanes, 660 M; the splats of an array of corner values went through
//! memory and stalled on store forwarding (a quarter of this function's
//! time: 1.20x → 1.13x on tris). Evaluating a partial 16×16 block's rows
//! sixteen pixels at a time instead of its 4×4 blocks cost more (tris 1.25x
//! and, without the 4×4 level, 1.30x), and so did testing a partial block
//! against all the tile's live edges rather than those it splits.

use super::edges::{Edge, Edges};
use super::ONE;
use crate::framebuffer::Rect;
use wide::i32x4;

/// Side of a tile in pixels.
pub const TILE: u32 = 64;

/// A tile's coverage: bit `i` of `rows[j]` is pixel `(x0 + i, y0 + j)`
/// (window coordinates, y up).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileMask {
    pub x0: u32,
    pub y0: u32,
    pub rows: [u64; TILE as usize],
}

impl TileMask {
    /// No pixel of the tile whose lower-left pixel is `(x0, y0)`.
    pub fn empty(x0: u32, y0: u32) -> TileMask {
        TileMask {
            x0,
            y0,
            rows: [0; TILE as usize],
        }
    }

    /// Number of covered pixels.
    pub fn count(&self) -> u32 {
        self.rows.iter().map(|r| r.count_ones()).sum()
    }

    /// Whether pixel `(x, y)` (window coordinates) is covered.
    pub fn covers(&self, x: u32, y: u32) -> bool {
        let (i, j) = (x.wrapping_sub(self.x0), y.wrapping_sub(self.y0));
        i < TILE && j < TILE && self.rows[j as usize] >> i & 1 == 1
    }
}

/// One edge's stepping over a tile, its value less `k` so that a pixel is
/// inside when it is `>= 0`.
#[derive(Clone, Copy, Debug, Default)]
struct Step {
    /// `E − k` at the tile's lower-left pixel.
    c0: i64,
    /// Change of `E` per pixel right and per row up.
    sx: i64,
    sy: i64,
    /// Least and greatest change of `E` from a block's lower-left pixel over
    /// a 16×16 block (`[0]`) and a 4×4 block (`[1]`).
    lo: [i64; 2],
    hi: [i64; 2],
}

impl Step {
    fn new(c0: i64, sx: i64, sy: i64) -> Step {
        let span = |n: i64| {
            let (a, b) = (n * sx, n * sy);
            (a.min(0) + b.min(0), a.max(0) + b.max(0))
        };
        let ((lo16, hi16), (lo4, hi4)) = (span(15), span(3));
        Step {
            c0,
            sx,
            sy,
            lo: [lo16, lo4],
            hi: [hi16, hi4],
        }
    }

    /// `E − k` at pixel `(i, j)` of the tile.
    #[inline]
    fn at(&self, i: u32, j: u32) -> i64 {
        self.c0 + i64::from(i) * self.sx + i64::from(j) * self.sy
    }
}

/// The edges still undecided in a block, bit `e` for edge `e` (the others
/// accept all of it).
type Live = u8;

/// Bit `l` set for the cells `(l % 4, l / 4)` of a 4×4 grid within the
/// inclusive ranges `i` and `j`.
#[inline(always)]
fn grid_mask(i: (u32, u32), j: (u32, u32)) -> u32 {
    let row = (0xf >> (3 - (i.1 - i.0))) << i.0;
    // The row repeated in rows j.0..=j.1 (a product of nibbles: no carry).
    row * ((0x1111 >> (4 * (3 - (j.1 - j.0)))) << (4 * j.0))
}

/// The pixels of the tile `tile` (at most 64×64) that the triangle of `edges`
/// covers, within `clip` (the tile is usually intersected with the raster
/// bounds): exactly the pixels the row rasterizer finds
/// ([`super::row_coverage`]).
pub fn tile_coverage(edges: &Edges, tile: Rect, clip: Rect) -> TileMask {
    debug_assert!(
        tile.x1 - tile.x0 <= TILE && tile.y1 - tile.y0 <= TILE,
        "a tile is at most 64x64"
    );
    let mut mask = TileMask::empty(tile.x0, tile.y0);
    let (ox, oy) = (i64::from(tile.x0), i64::from(tile.y0));
    // The pixels to decide, relative to the tile, half-open: tile, clip and
    // bounding box intersected.
    let lo_x = ox.max(i64::from(clip.x0)).max(edges.px.0) - ox;
    let hi_x = i64::from(tile.x1.min(clip.x1)).min(edges.px.1.saturating_add(1)) - ox;
    let lo_y = oy.max(i64::from(clip.y0)).max(edges.py.0) - oy;
    let hi_y = i64::from(tile.y1.min(clip.y1)).min(edges.py.1.saturating_add(1)) - oy;
    if lo_x >= hi_x || lo_y >= hi_y {
        return mask;
    }
    let area = Area::new((lo_x as u32, hi_x as u32), (lo_y as u32, hi_y as u32));
    cover(&edges.edges, (ox, oy), &area, &mut mask.rows);
    // (`cover` may set bits in rows outside the area.)
    for (j, r) in mask.rows.iter_mut().enumerate() {
        if !(area.y.0..area.y.1).contains(&(j as u32)) {
            *r = 0;
        }
    }
    mask
}

/// The pixels to decide, relative to a tile: columns `x.0..x.1` (as the
/// mask `cols`) of rows `y.0..y.1`. Blocks may reach past it; no bit
/// outside its columns is set (rows outside it are not read).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Area {
    cols: u64,
    x: (u32, u32),
    y: (u32, u32),
}

impl Area {
    /// The half-open, non-empty ranges `x` and `y` within `0..TILE`.
    #[inline]
    pub(crate) fn new(x: (u32, u32), y: (u32, u32)) -> Area {
        debug_assert!(x.0 < x.1 && x.1 <= TILE && y.0 < y.1 && y.1 <= TILE);
        Area {
            cols: (u64::MAX >> (64 - (x.1 - x.0))) << x.0,
            x,
            y,
        }
    }
}

/// Sets the bits (in `rows`, as [`TileMask::rows`]) of the pixels of `area`
/// of the tile whose lower-left pixel is `origin` that the counter-clockwise
/// triangle of `edges` covers. Bits of the area's columns in rows outside
/// it may be set too (a 4×4 block's four rows are written together): only
/// the area's rows are to be read. `false` when no pixel of the area may be
/// inside (nothing set).
#[inline]
pub(crate) fn cover(edges: &[Edge; 3], (ox, oy): (i64, i64), area: &Area, rows: &mut [u64; 64]) -> bool {
    let (cx0, cx1, cy0, cy1) = (area.x.0, area.x.1, area.y.0, area.y.1);
    let mut origin = [0i128; 3];
    let mut live: Live = 0;
    // The narrow form holds while every live edge's |dx| + |dy| is below this.
    let mut narrow = true;
    for (n, e) in edges.iter().enumerate() {
        let (sx, sy) = (-e.dy * ONE, e.dx * ONE);
        let w = i128::from;
        let c0 = w(e.dx) * w(oy * ONE - e.a.1) - w(e.dy) * w(ox * ONE - e.a.0) - w(e.k);
        // Extremes of E − k over the pixels to decide.
        let (ax, bx) = (i64::from(cx0) * sx, i64::from(cx1 - 1) * sx);
        let (ay, by) = (i64::from(cy0) * sy, i64::from(cy1 - 1) * sy);
        let least = c0 + w(ax.min(bx) + ay.min(by));
        let most = c0 + w(ax.max(bx) + ay.max(by));
        if most < 0 {
            return false;
        }
        if least < 0 {
            origin[n] = c0;
            live |= 1 << n;
            narrow &= e.dx.abs() + e.dy.abs() < NARROW;
        }
    }
    if live == 0 {
        // Every edge accepts the whole area.
        fill(rows, area, cy0, cy1 - cy0, u64::MAX);
    } else if narrow {
        Narrow::new(edges, origin, live).cover(area, rows);
    } else {
        let mut steps = [Step::default(); 3];
        for (n, e) in edges.iter().enumerate().filter(|&(n, _)| live >> n & 1 == 1) {
            // Both signs occur over the area, so c0 is small (module docs).
            steps[n] = Step::new(origin[n] as i64, -e.dy * ONE, e.dx * ONE);
        }
        wide(&steps, live, area, rows);
    }
    true
}

/// Below this `|dx| + |dy|` (2^24 units, 65536 pixels: every edge of a
/// triangle within the largest viewport, 16384 pixels) a live edge's
/// values over a tile fit in i32 ([`Narrow`]).
const NARROW: i64 = 1 << 24;

/// The live edges of a tile in i32. A pixel centre is inside an edge when
/// `E − k >= 0`; at pixel `(i, j)` of the tile `E − k = c0 + ONE·(i·a + j·b)`
/// with `a = −dy`, `b = dx`, so it is inside exactly when
/// `floor(c0 / ONE) + i·a + j·b >= 0`: the sub-pixel bits drop out of the
/// steps. A live edge has both signs over the tile, so that value is within
/// `±126·(|a| + |b|)` everywhere in it: below 2^31 when `|a| + |b| < 2^24`.
/// Sixteen values (a 4×4 grid of pixels or of blocks) are tested at once,
/// four lanes a vector, their signs gathered into a mask ([`grid_bits`]).
struct Narrow {
    live: Live,
    /// `floor(c0 / ONE)` at the tile's lower-left pixel, and the steps.
    q: [i32; 3],
    a: [i32; 3],
    b: [i32; 3],
    /// A 4×4 grid's offsets from its first cell, for cells of a pixel and
    /// of 4×4 pixels: lane `l` is `(l % 4)·a·w + (l / 4)·b·w`.
    px: [Grid; 3],
    b4: [Grid; 3],
    /// The least and greatest offset from a 4×4 (`[0]`) and a 16×16 (`[1]`)
    /// block's lower-left pixel over its pixels.
    lo: [[i32; 3]; 2],
    hi: [[i32; 3]; 2],
}

/// Sixteen lanes: a 4×4 grid, row by row.
type Grid = [i32x4; 4];

/// Bits `4·f .. 4·f + 4` set for each bit `f` of a nibble: a strip's full
/// 4×4 blocks as the columns of its rows.
const NIBBLE_COLUMNS: [u64; 16] = {
    let mut t = [0; 16];
    let mut n = 0;
    while n < 16 {
        let mut f = 0;
        while f < 4 {
            if n >> f & 1 == 1 {
                t[n] |= 0xf << (4 * f);
            }
            f += 1;
        }
        n += 1;
    }
    t
};

impl Narrow {
    #[inline(always)]
    fn new(edges: &[Edge; 3], origin: [i128; 3], live: Live) -> Narrow {
        let zero = [i32x4::ZERO; 4];
        let mut n = Narrow {
            live,
            q: [0; 3],
            a: [0; 3],
            b: [0; 3],
            px: [zero; 3],
            b4: [zero; 3],
            lo: [[0; 3]; 2],
            hi: [[0; 3]; 2],
        };
        for (e, edge) in edges.iter().enumerate().filter(|&(e, _)| live >> e & 1 == 1) {
            // Both in i32: |dx| + |dy| < NARROW.
            let (a, b) = (-edge.dy as i32, edge.dx as i32);
            (n.q[e], n.a[e], n.b[e]) = ((origin[e] >> super::SUBPIXEL_BITS) as i32, a, b);
            let row = i32x4::new([0, a, 2 * a, 3 * a]);
            let px: Grid = [0, 1, 2, 3].map(|j| row + i32x4::splat(j * b));
            n.px[e] = px;
            n.b4[e] = px.map(|v| v << 2);
            for (s, w) in [(0, 3), (1, 15)] {
                n.lo[s][e] = (w * a).min(0) + (w * b).min(0);
                n.hi[s][e] = (w * a).max(0) + (w * b).max(0);
            }
        }
        n
    }

    /// The tile's 16×16 blocks, each edge on its own: the blocks an edge
    /// rejects cost nothing more, those every edge accepts set their bits,
    /// and the rest are split ([`Narrow::block16`]) with only the edges
    /// that do not accept all of them.
    #[inline]
    fn cover(&self, area: &Area, rows: &mut [u64; 64]) {
        let mut any = grid_mask(
            (area.x.0 / 16, (area.x.1 - 1) / 16),
            (area.y.0 / 16, (area.y.1 - 1) / 16),
        );
        let mut full = [0xffff; 3];
        for e in (0..3).filter(|&e| self.live >> e & 1 == 1) {
            let b16 = self.b4[e].map(|v| v << 2);
            any &= grid_bits([self.q[e] + self.hi[1][e]], [&b16]);
            full[e] = grid_bits([self.q[e] + self.lo[1][e]], [&b16]);
        }
        let mut f = any & full[0] & full[1] & full[2];
        let mut p = any & !f;
        while f != 0 {
            let l = f.trailing_zeros();
            f &= f - 1;
            fill(rows, area, l / 4 * 16, 16, 0xffff << (l % 4 * 16));
        }
        while p != 0 {
            let l = p.trailing_zeros();
            p &= p - 1;
            let (i, j) = (l % 4 * 16, l / 4 * 16);
            // The edges that do not accept the whole block.
            let split = (0..3).fold(0, |s, e| s | (!full[e] >> l & 1) << e);
            match split {
                1 => self.block16([0], area, rows, i, j),
                2 => self.block16([1], area, rows, i, j),
                4 => self.block16([2], area, rows, i, j),
                3 => self.block16([0, 1], area, rows, i, j),
                5 => self.block16([0, 2], area, rows, i, j),
                6 => self.block16([1, 2], area, rows, i, j),
                _ => self.block16([0, 1, 2], area, rows, i, j),
            }
        }
    }

    /// A partial 16×16 block at `(i, j)` of the tile, tested against the
    /// edges `es`: its 4×4 blocks classified together (the full ones set a
    /// strip at a time), then the partial ones evaluated per pixel.
    #[inline(always)]
    fn block16<const N: usize>(&self, es: [usize; N], area: &Area, rows: &mut [u64; 64], i: u32, j: u32) {
        let c = es.map(|e| self.q[e] + i as i32 * self.a[e] + j as i32 * self.b[e]);
        let b4 = es.map(|e| &self.b4[e]);
        // The 4x4 blocks that meet the area.
        let (si0, si1) = ((i.max(area.x.0) - i) / 4, ((i + 16).min(area.x.1) - 1 - i) / 4);
        let (sj0, sj1) = ((j.max(area.y.0) - j) / 4, ((j + 16).min(area.y.1) - 1 - j) / 4);
        let meet = grid_mask((si0, si1), (sj0, sj1));
        let any = grid_bits(add(c, es.map(|e| self.hi[0][e])), b4) & meet;
        let full = grid_bits(add(c, es.map(|e| self.lo[0][e])), b4) & any;
        for s in sj0..=sj1 {
            let f = full >> (4 * s) & 0xf;
            if f != 0 {
                fill(rows, area, j + 4 * s, 4, NIBBLE_COLUMNS[f as usize] << i);
            }
        }
        let mut p = any & !full;
        if p == 0 {
            return;
        }
        let px = es.map(|e| &self.px[e]);
        let (a4, b4) = (es.map(|e| 4 * self.a[e]), es.map(|e| 4 * self.b[e]));
        while p != 0 {
            let l = p.trailing_zeros() as usize;
            p &= p - 1;
            // The block's first pixel's values, in registers (read back
            // from a lane in memory, a splat stalled on store forwarding).
            let (u, v) = ((l % 4) as i32, (l / 4) as i32);
            let mut corner = c;
            for k in 0..N {
                corner[k] += u * a4[k] + v * b4[k];
            }
            let bits = u64::from(grid_bits(corner, px));
            // All four rows: those outside the area are not read (`cover`).
            let (i, j) = (i as usize + l % 4 * 4, (j as usize + l / 4 * 4) & 60);
            let cols = area.cols >> i;
            for (r, row) in rows[j..j + 4].iter_mut().enumerate() {
                *row |= (bits >> (4 * r) & 0xf & cols) << i;
            }
        }
    }
}

#[inline(always)]
fn add<const N: usize>(a: [i32; N], b: [i32; N]) -> [i32; N] {
    let mut s = a;
    for (s, b) in s.iter_mut().zip(b) {
        *s += b;
    }
    s
}

/// Bit `l` set when every edge's `c[e] + off[e]`'s lane `l` is `>= 0` (no
/// sign bit in their or).
#[inline(always)]
fn grid_bits<const N: usize>(c: [i32; N], off: [&Grid; N]) -> u32 {
    // One edge's four vectors at a time, their splat made in a register (an
    // array of splats went through memory and stalled on store forwarding).
    let mut v = [i32x4::ZERO; 4];
    for e in 0..N {
        let s = i32x4::splat(c[e]);
        for (v, o) in v.iter_mut().zip(off[e]) {
            *v |= s + *o;
        }
    }
    !(v[0].to_bitmask() | v[1].to_bitmask() << 4 | v[2].to_bitmask() << 8 | v[3].to_bitmask() << 12) & 0xffff
}

/// The general form, in i64, for live edges too long for [`Narrow`]: the
/// tile's 16×16 blocks classified together as the 4×4 blocks of a 16×16 one
/// are ([`block16`]).
fn wide(steps: &[Step; 3], live: Live, area: &Area, rows: &mut [u64; 64]) {
    let (cx0, cx1, cy0, cy1) = (area.x.0, area.x.1, area.y.0, area.y.1);
    let meet = grid_mask((cx0 / 16, (cx1 - 1) / 16), (cy0 / 16, (cy1 - 1) / 16));
    let (mut any, mut full) = (meet, meet);
    for (e, s) in steps.iter().enumerate() {
        if live >> e & 1 == 1 {
            any &= inside(s.c0 + s.hi[0], 16 * s.sx, 16 * s.sy);
            full &= inside(s.c0 + s.lo[0], 16 * s.sx, 16 * s.sy);
        }
    }
    let mut f = full;
    while f != 0 {
        let l = f.trailing_zeros();
        f &= f - 1;
        fill(rows, area, l / 4 * 16, 16, 0xffff << (l % 4 * 16));
    }
    let mut p = any & !full;
    while p != 0 {
        let l = p.trailing_zeros();
        p &= p - 1;
        block16(steps, live, rows, area, l % 4 * 16, l / 4 * 16);
    }
}

/// Sets `bits` (within the area) in `n` rows from row `j`.
#[inline]
fn fill(rows: &mut [u64; 64], area: &Area, j: u32, n: u32, bits: u64) {
    let (j0, j1) = (j.max(area.y.0), (j + n).min(area.y.1));
    for r in &mut rows[j0 as usize..j1 as usize] {
        *r |= bits & area.cols;
    }
}

/// A partial 16×16 block at `(i, j)`: its sixteen 4×4 blocks classified
/// together, per live edge one bit mask of those it does not reject and one
/// of those it accepts whole (branch-free: one at a time with a branch per
/// edge, a 2000-px triangle took 2.4x as long); then the partial ones within
/// the area evaluated per pixel.
fn block16(steps: &[Step; 3], live: Live, rows: &mut [u64; 64], area: &Area, i: u32, j: u32) {
    // The 4x4 blocks of this one that meet the area.
    let (si0, si1) = ((i.max(area.x.0) - i) / 4, ((i + 16).min(area.x.1) - 1 - i) / 4);
    let (sj0, sj1) = ((j.max(area.y.0) - j) / 4, ((j + 16).min(area.y.1) - 1 - j) / 4);
    let meet = grid_mask((si0, si1), (sj0, sj1));
    let (mut any, mut full) = (meet, meet);
    for (e, s) in steps.iter().enumerate() {
        if live >> e & 1 == 1 {
            let c = s.at(i, j);
            any &= inside(c + s.hi[1], 4 * s.sx, 4 * s.sy);
            full &= inside(c + s.lo[1], 4 * s.sx, 4 * s.sy);
        }
    }
    let mut f = full;
    while f != 0 {
        let l = f.trailing_zeros();
        f &= f - 1;
        fill(rows, area, j + l / 4 * 4, 4, 0xf << (i + l % 4 * 4));
    }
    let mut p = any & !full;
    while p != 0 {
        let l = p.trailing_zeros();
        p &= p - 1;
        let (i, j) = (i + l % 4 * 4, j + l / 4 * 4);
        let mut bits = 0xffffu32;
        for (e, s) in steps.iter().enumerate() {
            if live >> e & 1 == 1 {
                bits &= inside(s.at(i, j), s.sx, s.sy);
            }
        }
        for r in j.max(area.y.0)..(j + 4).min(area.y.1) {
            rows[r as usize] |= u64::from(bits >> (4 * (r - j)) & 0xf) << i & area.cols;
        }
    }
}

/// Bit `l` set when `c + (l % 4)·sx + (l / 4)·sy >= 0`: a 4×4 grid of
/// points `sx` apart across and `sy` up (unrolled: the products become adds).
#[inline(always)]
fn inside(c: i64, sx: i64, sy: i64) -> u32 {
    let mut m = 0;
    for l in 0..16 {
        m |= u32::from(c + (l % 4) as i64 * sx + (l / 4) as i64 * sy >= 0) << l;
    }
    m
}

#[cfg(test)]
mod tests;
