//! Triangles: exact fixed-point edge functions, one span interval per row.
//!
//! Within a box (a tile of a flush), `cover` finds the triangle's pixels
//! with the block rasterizer ([`super::block`]): a tile no pixel is in
//! costs nothing more (no plane set-up, no row), a tile wholly inside needs
//! no test per pixel, and the rest is decided by 16×16 and 4×4 blocks. Each
//! row with pixels is one run, handed to the sink with nothing but planes
//! ([`SpanSink::row`]). Until then the rows were found by walking each edge
//! from row to row ([`super::rows`], kept as the block rasterizer's oracle):
//! measured with callgrind, one thread, instructions per frame of
//! `osmesa/bench/fill.c` (with the plane set-up taking the snapped points
//! it is given), that walk took tris 939 M → 843 M, ops 1596 M → 1501 M,
//! fill 415 M → 381 M against a division per row.
//!
//! A triangle is set up once ([`Prepared`]; a scene does it when it
//! records the triangle): its snapped vertices made counter-clockwise, its
//! box within the bounds, and, for a box of at most 64 pixels, which of
//! them are inside, tested one by one in i64 (three additions a pixel, no
//! division: the triangles of a finely tessellated sphere are a pixel or
//! two). A triangle no pixel of which is inside goes no further (no planes,
//! no bin entry). A tile then only cuts that coverage to itself and finds
//! its rows (the mask's bytes, the box's rows when every pixel is inside,
//! else the block rasterizer's masks); the scene records the planes
//! ([`setup_planes`]) rather than the vertices, so nothing is snapped or set
//! up twice. Measured with callgrind, one thread, instructions a frame of
//! `lit16` (1.6 M triangles): 5317 M → 2936 M (3323 → 1835 a triangle;
//! Mesa llvmpipe: 2.56 G), lit 629 M → 500 M, tris 758 M → 713 M, ops
//! 1240 M → 1195 M, the images byte-identical. A box of one pixel, or of
//! at most 2×2, is tested without the mask loop (one or four tests, no
//! steps walked), and the scene's binning of a one-tile primitive and its
//! draw index are inline: lit16 2570 M → 2496 M a frame (callgrind, one
//! thread; lit 469 M → 473 M, whose larger boxes pay the two extra tests).

use super::block::{self, Area, TILE};
use super::edges::{ccw, ceil_one, edges_of, floor_one, Edge, Edges, SMALL};
use super::rows::Rows;
use super::{emit_row, snap, with_planes, RasterParams, RasterVertex, SpanSink, ONE};
use crate::framebuffer::Rect;
use crate::geometry::varying::Varyings;
use softgl_jit::interp::row_of;
use softgl_jit::shade::{slot, Planes};
use softgl_jit::{DepthFormat, FragmentSpan};

/// An attribute plane in llvmpipe's frame: x right, y down from the top row,
/// evaluated at integer pixel coordinates for the pixel centers (by the
/// fragment stage: `Planes::at`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Plane {
    pub a0: f32,
    pub dadx: f32,
    pub dady: f32,
}

/// Triangle setup in f32 from the unsnapped window positions, step for step
/// as llvmpipe computes it, so interpolated colors and depths match its bits
/// (docs/llvmpipe-facts.md, "attribute interpolation").
struct Setup {
    x0c: f32,
    y0c: f32,
    dx20o: f32,
    dy20o: f32,
    dx01o: f32,
    dy01o: f32,
}

impl Setup {
    fn new(p: [(f32, f32); 3]) -> Setup {
        let (dx01, dy01) = (p[0].0 - p[1].0, p[0].1 - p[1].1);
        let (dx20, dy20) = (p[2].0 - p[0].0, p[2].1 - p[0].1);
        let ooa = 1.0 / (dx01 * dy20 - dy01 * dx20);
        Setup {
            x0c: p[0].0 - 0.5,
            y0c: p[0].1 - 0.5,
            dx20o: dx20 * ooa,
            dy20o: dy20 * ooa,
            dx01o: dx01 * ooa,
            dy01o: dy01 * ooa,
        }
    }

    fn plane(&self, a: [f32; 3]) -> Plane {
        let (da01, da20) = (a[0] - a[1], a[2] - a[0]);
        let dadx = da01 * self.dy20o - da20 * self.dy01o;
        let dady = da20 * self.dx01o - da01 * self.dx20o;
        Plane {
            a0: a[0] - (dadx * self.x0c + dady * self.y0c),
            dadx,
            dady,
        }
    }
}

/// Rasterizes a triangle, either winding. `flat` (the provoking vertex's
/// varyings) replaces the interpolated colours.
///
/// Generic over the sink, so that a flush's fragment stage takes each row
/// with a direct, inlined call (`&mut dyn SpanSink` works as before).
pub fn triangle<S: SpanSink + ?Sized>(
    v: [&RasterVertex; 3],
    flat: Option<&Varyings>,
    params: &RasterParams,
    sink: &mut S,
) {
    // docs/llvmpipe-facts.md 2: the y snapped top-down, reflected into GL rows.
    let top = (i64::from(params.height) - 1) * ONE;
    cover(
        (Edges::window_points(v, params.height), Some(top)),
        v,
        flat,
        params,
        sink,
    );
}

/// The pixels [`triangle`] may cover: its snapped bounding box within
/// `params.bounds`, as `cover` finds it; `None` when it covers nothing.
pub fn triangle_box(v: [&RasterVertex; 3], params: &RasterParams) -> Option<Rect> {
    let e = Edges::window(v, params.height)?;
    let b = params.bounds;
    let x0 = e.px.0.max(i64::from(b.x0));
    let x1 = e.px.1.min(i64::from(b.x1) - 1);
    let y0 = e.py.0.max(i64::from(b.y0));
    let y1 = e.py.1.min(i64::from(b.y1) - 1);
    (x0 <= x1 && y0 <= y1).then(|| Rect {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32 + 1,
        y1: y1 as u32 + 1,
    })
}

/// [`triangle`] for a wide line's quad, whose corners are made in GL's
/// bottom-up frame and snapped there.
pub(super) fn triangle_y_up(
    v: [&RasterVertex; 3],
    flat: Option<&Varyings>,
    params: &RasterParams,
    sink: &mut dyn SpanSink,
) {
    cover((v.map(|v| (snap(v.x), snap(v.y))), None), v, flat, params, sink);
}

/// Covers the triangle of the snapped bottom-up positions `p` of `v`;
/// `top` when they are llvmpipe's snapped top-down positions reflected
/// about `top` ([`Edges::window_points`]), whose reflection back the plane
/// set-up then takes instead of snapping again.
pub(super) fn cover<S: SpanSink + ?Sized>(
    (p, top): ([(i64, i64); 3], Option<i64>),
    v: [&RasterVertex; 3],
    flat: Option<&Varyings>,
    params: &RasterParams,
    sink: &mut S,
) {
    let Some(prep) = Prepared::new(p, params.bounds) else {
        return;
    };
    let swap = match top {
        Some(_) => plane_swap(p),
        None => plane_swap_down(v.map(|v| (snap(v.x), snap(v.y_down)))),
    };
    prep.cover(params.bounds, params.height, sink, |planes| {
        setup_planes(v, swap, flat, params, &mut |k, p| planes.set(k, p.a0, p.dadx, p.dady))
    });
}

/// A triangle set up for coverage once (a scene does it when it records
/// the triangle, so that a flush's tiles only find their rows): its
/// snapped vertices made counter-clockwise, its pixel box within the
/// bounds, and, when the box is small, which of its pixels are inside.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Prepared {
    /// The box: inclusive pixel ranges.
    px: (u32, u32),
    py: (u32, u32),
    cover: Cover,
}

#[derive(Clone, Copy, Debug)]
enum Cover {
    /// Every pixel centre of the box is inside.
    Inside,
    /// Bit `w·j + i`, `w` the box's width: pixel `(px.0 + i, py.0 + j)`
    /// is inside (a box of at most [`MASK`] pixels).
    Masks(u64),
    /// The vertices, counter-clockwise: the rows are walked per box.
    Edges([(i64, i64); 3]),
}

/// The most pixels of a box whose pixels [`Prepared`] tests one by one
/// (three additions a pixel, no division), whatever its shape: a sliver
/// 30 pixels long and 2 high (a sphere's silhouette) is masked once, not
/// found per tile by blocks. (It was 8×8: with 64 pixels of any shape,
/// callgrind, one thread, instructions a frame: lit 467 M → 419 M, thrash
/// 82.6 M → 78.3 M, lit16 2280 M → 2305 M, the row shifts being variable.)
const MASK: i64 = 64;

impl Prepared {
    /// The triangle of the snapped bottom-up positions `p` (either
    /// winding) within `bounds`; `None` when no pixel of it is inside them.
    #[inline]
    pub(crate) fn new(p: [(i64, i64); 3], bounds: Rect) -> Option<Prepared> {
        let (min_x, max_x) = (p[0].0.min(p[1].0).min(p[2].0), p[0].0.max(p[1].0).max(p[2].0));
        let (min_y, max_y) = (p[0].1.min(p[1].1).min(p[2].1), p[0].1.max(p[1].1).max(p[2].1));
        let x0 = ceil_one(min_x).max(i64::from(bounds.x0));
        let x1 = floor_one(max_x).min(i64::from(bounds.x1) - 1);
        let y0 = ceil_one(min_y).max(i64::from(bounds.y0));
        let y1 = floor_one(max_y).min(i64::from(bounds.y1) - 1);
        if x0 > x1 || y0 > y1 {
            return None;
        }
        let small = min_x > -SMALL && max_x < SMALL && min_y > -SMALL && max_y < SMALL;
        let p = ccw(p, small)?;
        let (px, py) = ((x0 as u32, x1 as u32), (y0 as u32, y1 as u32));
        let cover = if x0 == x1 && y0 == y1 && small {
            // One pixel (most of a finely tessellated sphere's triangles
            // that cover any): its centre alone, no mask loop; what the
            // mask below makes of it (one bit of one, inside).
            let [e0, e1, e2] = edges_of(p);
            let at = |e: &Edge| e.dx * (y0 * ONE - e.a.1) - e.dy * (x0 * ONE - e.a.0) - e.k;
            if (at(&e0) | at(&e1) | at(&e2)) < 0 {
                return None;
            }
            Cover::Inside
        } else if x1 - x0 < 2 && y1 - y0 < 2 && small {
            // At most 2×2 pixels (most of the rest): the mask below, its
            // four tests without a loop.
            let [e0, e1, e2] = edges_of(p);
            let at = |e: &Edge| e.dx * (y0 * ONE - e.a.1) - e.dy * (x0 * ONE - e.a.0) - e.k;
            let (r0, r1, r2) = (at(&e0), at(&e1), at(&e2));
            let (sx0, sx1, sx2) = (-e0.dy * ONE, -e1.dy * ONE, -e2.dy * ONE);
            let (sy0, sy1, sy2) = (e0.dx * ONE, e1.dx * ONE, e2.dx * ONE);
            let (wide, tall) = (x1 > x0, y1 > y0);
            // The mask's rows are the box's width apart.
            let w = 1 + u32::from(wide);
            let inside = |c0: i64, c1: i64, c2: i64| u64::from((c0 | c1 | c2) >= 0);
            let m = inside(r0, r1, r2)
                | (inside(r0 + sx0, r1 + sx1, r2 + sx2) & u64::from(wide)) << 1
                | (inside(r0 + sy0, r1 + sy1, r2 + sy2) & u64::from(tall)) << w
                | (inside(r0 + sx0 + sy0, r1 + sx1 + sy1, r2 + sx2 + sy2) & u64::from(wide & tall)) << (w + 1);
            let all = 1 | u64::from(wide) << 1 | u64::from(tall) << w | u64::from(wide & tall) << (w + 1);
            match m {
                0 => return None,
                m if m == all => Cover::Inside,
                m => Cover::Masks(m),
            }
        } else if x1 - x0 < MASK && y1 - y0 < MASK && (x1 - x0 + 1) * (y1 - y0 + 1) <= MASK && small {
            // Within ±2^29 units and a box within ±2^21 pixels every edge
            // function is exact in i64 (`edges::SMALL`).
            let (w, h) = (x1 - x0 + 1, y1 - y0 + 1);
            let [e0, e1, e2] = edges_of(p);
            // E − k at (x0, y0), and its steps a column and a row.
            let at = |e: &Edge| e.dx * (y0 * ONE - e.a.1) - e.dy * (x0 * ONE - e.a.0) - e.k;
            let (mut r0, mut r1, mut r2) = (at(&e0), at(&e1), at(&e2));
            let (sx0, sx1, sx2) = (-e0.dy * ONE, -e1.dy * ONE, -e2.dy * ONE);
            let (sy0, sy1, sy2) = (e0.dx * ONE, e1.dx * ONE, e2.dx * ONE);
            let (mut m, mut all) = (0u64, 0u64);
            let mut bit = 1u64;
            let mut j = 0;
            while j < h {
                let (mut c0, mut c1, mut c2) = (r0, r1, r2);
                let mut i = 0;
                while i < w {
                    // Inside: no edge's value negative (no sign bit set).
                    if (c0 | c1 | c2) >= 0 {
                        m |= bit;
                    }
                    all |= bit;
                    (c0, c1, c2) = (c0 + sx0, c1 + sx1, c2 + sx2);
                    bit <<= 1;
                    i += 1;
                }
                (r0, r1, r2) = (r0 + sy0, r1 + sy1, r2 + sy2);
                j += 1;
            }
            match m {
                0 => return None,
                m if m == all => Cover::Inside,
                m => Cover::Masks(m),
            }
        } else {
            match Rows::classify(&edges_of(p), (x0, x1), (y0, y1))? {
                true => Cover::Inside,
                false => Cover::Edges(p),
            }
        };
        Some(Prepared { px, py, cover })
    }

    /// The most words [`Prepared::encode`] writes.
    pub(crate) const WORDS: usize = 14;

    /// Writes the set-up into `out` as 32-bit words, returning how many
    /// (at most [`Prepared::WORDS`]) and a 2-bit tag [`Prepared::decode`]
    /// takes back: the box as four u16 (a framebuffer side is at most
    /// 16384), then a mask's 64 bits or the vertices' i64 coordinates.
    /// A one-pixel or wholly covered triangle is 2 words, a masked one 4.
    #[inline(always)]
    pub(crate) fn encode(&self, out: &mut [u32; Prepared::WORDS]) -> (usize, u32) {
        out[0] = self.px.0 | self.px.1 << 16;
        out[1] = self.py.0 | self.py.1 << 16;
        match self.cover {
            Cover::Inside => (2, 0),
            Cover::Masks(m) => {
                (out[2], out[3]) = (m as u32, (m >> 32) as u32);
                (4, 1)
            }
            Cover::Edges(p) => {
                for (i, c) in p.iter().flat_map(|&(x, y)| [x, y]).enumerate() {
                    (out[2 + 2 * i], out[3 + 2 * i]) = (c as u32, (c >> 32) as u32);
                }
                (14, 2)
            }
        }
    }

    /// The set-up [`Prepared::encode`] wrote at the start of `words` with
    /// `tag`, and the words it took; `None` when `words` is short.
    #[inline(always)]
    pub(crate) fn decode(tag: u32, words: &[u32]) -> Option<(Prepared, usize)> {
        let (&[a, b], rest) = words.split_first_chunk::<2>()?;
        let (px, py) = ((a & 0xffff, a >> 16), (b & 0xffff, b >> 16));
        let wide = |lo: u32, hi: u32| u64::from(lo) | u64::from(hi) << 32;
        let (cover, n) = match tag {
            0 => (Cover::Inside, 2),
            1 => {
                let &[lo, hi] = rest.first_chunk::<2>()?;
                (Cover::Masks(wide(lo, hi)), 4)
            }
            _ => {
                let w = rest.first_chunk::<12>()?;
                let c = |i: usize| wide(w[2 * i], w[2 * i + 1]) as i64;
                (Cover::Edges([(c(0), c(1)), (c(2), c(3)), (c(4), c(5))]), 14)
            }
        };
        Some((Prepared { px, py, cover }, n))
    }

    /// The pixels the triangle may cover (its box within the bounds).
    pub(crate) fn rect(&self) -> Rect {
        Rect {
            x0: self.px.0,
            y0: self.py.0,
            x1: self.px.1 + 1,
            y1: self.py.1 + 1,
        }
    }

    /// Emits the triangle's pixels within `clip` into `sink`, after the
    /// planes `planes` writes (when some pixel of `clip` may be inside);
    /// `planes` returns the depth plane of 32-bit depth, which the spans
    /// carry ([`setup_planes`]). `height`: the framebuffer's.
    #[inline]
    pub(crate) fn cover<S: SpanSink + ?Sized>(
        &self,
        clip: Rect,
        height: u32,
        sink: &mut S,
        planes: impl FnOnce(&mut Planes) -> Option<(DepthFormat, Plane)>,
    ) {
        let px = (self.px.0.max(clip.x0), self.px.1.min(clip.x1.saturating_sub(1)));
        let py = (self.py.0.max(clip.y0), self.py.1.min(clip.y1.saturating_sub(1)));
        if px.0 > px.1 || py.0 > py.1 || clip.is_empty() {
            return;
        }
        // A tile's coverage, when a triangle has one (not zeroed otherwise).
        let mut tile;
        let kind = match self.cover {
            Cover::Inside => RowsKind::Box,
            Cover::Masks(m) if (px, py) == (self.px, self.py) => RowsKind::Masks(m),
            Cover::Masks(m) => {
                // The columns of `clip` in the mask's rows within it (a
                // box cut by tiles: rare for a box this small).
                let w = self.px.1 - self.px.0 + 1;
                let cols = (u64::MAX >> (63 - (px.1 - px.0))) << (px.0 - self.px.0);
                let keep = (py.0 - self.py.0..=py.1 - self.py.0).fold(0, |k, j| k | cols << (w * j));
                let m = m & keep;
                if m == 0 {
                    return;
                }
                RowsKind::Masks(m)
            }
            Cover::Edges(p) if rows_oracle() => {
                let wide = |(a, b): (u32, u32)| (i64::from(a), i64::from(b));
                match Rows::new(&edges_of(p), wide(px), wide(py)) {
                    Some(rows) => RowsKind::Walk(rows),
                    None => return,
                }
            }
            Cover::Edges(p) => {
                let edges = edges_of(p);
                let (ox, oy) = (px.0 & !(TILE - 1), py.0 & !(TILE - 1));
                if px.1 < ox + TILE && py.1 < oy + TILE {
                    // Within one tile (always, in a scene's flush): its
                    // coverage first, so that a tile the triangle misses
                    // costs no planes.
                    tile = [0; TILE as usize];
                    let area = Area::new((px.0 - ox, px.1 + 1 - ox), (py.0 - oy, py.1 + 1 - oy));
                    if !block::cover(&edges, (i64::from(ox), i64::from(oy)), &area, &mut tile) {
                        return;
                    }
                    RowsKind::Tile((ox, oy), &tile)
                } else {
                    RowsKind::Tiles(edges)
                }
            }
        };
        let rows = TileRows {
            px,
            py,
            origin: (self.px.0, self.py.0),
            width: self.px.1 - self.px.0 + 1,
            kind,
        };
        match with_planes(sink, planes) {
            None => rows.each(|py, lo, hi| sink.row(py, lo, hi)),
            // Only 32-bit depth fills the spans' slots (the planes give the rest).
            Some((format, z)) => {
                let mut span = FragmentSpan::new(0, 0);
                rows.each(|py, lo, hi| {
                    let row = row_of(py, height);
                    let mut fill_z = |x: u32, s: &mut FragmentSpan, i: usize| {
                        let z = z.dady.mul_add(row, z.dadx.mul_add(x as f32, z.a0));
                        s.z[i] = crate::framebuffer::depth_to_unorm(f64::from(z), format);
                    };
                    emit_row(sink, &mut span, py, lo, hi, Some(&mut fill_z));
                });
            }
        }
    }
}

/// The rows of a triangle within a box, found by [`Prepared::cover`].
struct TileRows<'t> {
    /// The box (inclusive), and the lower-left pixel of the mask's.
    px: (u32, u32),
    py: (u32, u32),
    origin: (u32, u32),
    /// The mask's box's width (its rows' distance).
    width: u32,
    kind: RowsKind<'t>,
}

enum RowsKind<'t> {
    /// Every pixel of the box.
    Box,
    /// A [`Cover::Masks`] cut to the box.
    Masks(u64),
    /// The box within one tile: the tile's lower-left pixel and its rows'
    /// coverage ([`block::cover`]).
    Tile((u32, u32), &'t [u64; TILE as usize]),
    /// A box over several tiles (a triangle rasterized at once, not
    /// binned): each tile's coverage found in turn.
    Tiles([Edge; 3]),
    /// The row rasterizer's rows (tests only: [`rows_oracle`]).
    Walk(Rows),
}

#[cfg(test)]
thread_local! {
    /// Tests: whether this thread's triangles are covered by the row
    /// rasterizer (the oracle) rather than the block rasterizer, so that a
    /// test can draw the same lines, points and triangles both ways.
    pub(crate) static ROWS_ORACLE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether [`ROWS_ORACLE`] is set (never, outside tests).
#[inline(always)]
fn rows_oracle() -> bool {
    #[cfg(test)]
    return ROWS_ORACLE.with(std::cell::Cell::get);
    #[cfg(not(test))]
    false
}

impl TileRows<'_> {
    /// Runs `row(py, first, last)` for each row that has pixels inside,
    /// bottom to top.
    #[inline]
    fn each(self, mut row: impl FnMut(u32, u32, u32)) {
        let (px, py) = (self.px, self.py);
        match self.kind {
            RowsKind::Box => {
                for y in py.0..=py.1 {
                    row(y, px.0, px.1);
                }
            }
            RowsKind::Masks(m) => {
                let (x0, y0) = self.origin;
                let row_bits = u64::MAX >> (64 - self.width);
                for y in py.0..=py.1 {
                    let bits = (m >> ((y - y0) * self.width)) & row_bits;
                    if bits != 0 {
                        row(y, x0 + bits.trailing_zeros(), x0 + 63 - bits.leading_zeros());
                    }
                }
            }
            RowsKind::Tile(origin, rows) => tile_rows(origin, rows, py, &mut row),
            RowsKind::Walk(rows) => rows.each(row),
            RowsKind::Tiles(edges) => {
                for ty in py.0 / TILE..=py.1 / TILE {
                    for tx in px.0 / TILE..=px.1 / TILE {
                        let (ox, oy) = (tx * TILE, ty * TILE);
                        let (x0, x1) = (px.0.max(ox), px.1.min(ox + TILE - 1));
                        let (y0, y1) = (py.0.max(oy), py.1.min(oy + TILE - 1));
                        let mut rows = [0; TILE as usize];
                        let area = Area::new((x0 - ox, x1 + 1 - ox), (y0 - oy, y1 + 1 - oy));
                        if block::cover(&edges, (i64::from(ox), i64::from(oy)), &area, &mut rows) {
                            tile_rows((ox, oy), &rows, (y0, y1), &mut row);
                        }
                    }
                }
            }
        }
    }
}

/// Runs `row(py, first, last)` for the rows `py` (inclusive) of a tile
/// whose lower-left pixel is `(ox, oy)` that have pixels in `rows`: a
/// triangle's pixels in a row are one run.
#[inline(always)]
fn tile_rows((ox, oy): (u32, u32), rows: &[u64; TILE as usize], py: (u32, u32), row: &mut impl FnMut(u32, u32, u32)) {
    for y in py.0..=py.1 {
        let bits = rows[(y - oy) as usize];
        if bits != 0 {
            row(y, ox + bits.trailing_zeros(), ox + 63 - bits.leading_zeros());
        }
    }
}

/// Whether llvmpipe swaps the first two vertices of the triangle of
/// snapped top-down positions `q` for its plane set-up: when their area, in
/// its y-down frame, is negative (in i64, as it computes it).
#[inline]
fn plane_swap_down(q: [(i64, i64); 3]) -> bool {
    let area = (q[0].0.wrapping_sub(q[1].0))
        .wrapping_mul(q[2].1.wrapping_sub(q[0].1))
        .wrapping_sub((q[2].0.wrapping_sub(q[0].0)).wrapping_mul(q[0].1.wrapping_sub(q[1].1)));
    area < 0
}

/// [`plane_swap_down`] of the snapped top-down positions whose reflection
/// into GL rows is `p` ([`Edges::window_points`]): reflecting the y of all
/// three negates both y differences of the area, which is the same value
/// (to the bit, in wrapping i64) from the bottom-up positions.
#[inline]
pub(crate) fn plane_swap(p: [(i64, i64); 3]) -> bool {
    let area = (p[1].0.wrapping_sub(p[0].0))
        .wrapping_mul(p[2].1.wrapping_sub(p[0].1))
        .wrapping_sub((p[2].0.wrapping_sub(p[0].0)).wrapping_mul(p[1].1.wrapping_sub(p[0].1)));
    area < 0
}

/// Sets the planes of a triangle's attributes for the fragment stage up,
/// in llvmpipe's order, handing each to `put(slot, plane)`: 1/w, the
/// colours (the flat ones constant), the secondary colour, the fog
/// coordinate and the texture coordinates over w, depth (with polygon
/// offset) last. Only the slots the layout uses are put. `swap`: whether
/// llvmpipe swaps the first two vertices ([`plane_swap`]). Returns the
/// depth format and plane of the depth values the rasterizer computes per
/// fragment itself (32-bit depth, which the shading stage leaves to the
/// span).
pub(crate) fn setup_planes(
    v: [&RasterVertex; 3],
    swap: bool,
    flat: Option<&Varyings>,
    params: &RasterParams,
    put: &mut impl FnMut(usize, Plane),
) -> Option<(DepthFormat, Plane)> {
    let mut v = v;
    if swap {
        v.swap(0, 1);
    }
    let setup = Setup::new([(v[0].x, v[0].y_down), (v[1].x, v[1].y_down), (v[2].x, v[2].y_down)]);
    let layout = params.layout;
    let over_w = |k: usize| setup.plane([v[0].v[k] * v[0].inv_w, v[1].v[k] * v[1].inv_w, v[2].v[k] * v[2].inv_w]);
    put(slot::INV_W, setup.plane([v[0].inv_w, v[1].inv_w, v[2].inv_w]));
    let colours = [
        (layout.color(), slot::COLOR, 4),
        (layout.secondary(), slot::SECONDARY, 3),
    ];
    for (at, to, n) in colours {
        let Some(o) = at else { continue };
        for c in 0..n {
            let p = match flat {
                Some(f) => Plane {
                    a0: f[o + c],
                    dadx: 0.0,
                    dady: 0.0,
                },
                None => over_w(o + c),
            };
            put(to + c, p);
        }
    }
    if let Some(o) = layout.fog() {
        put(slot::FOG, over_w(o));
    }
    // (`tex_units` walks the eight units: not for a layout with none.)
    if layout.tex != 0 {
        for (unit, o) in layout.tex_units() {
            for c in 0..4 {
                put(slot::tex(unit) + c, over_w(o + c));
            }
        }
    }
    let mut per_fragment_z = None;
    if let Some(f) = params.depth {
        let mut z = [v[0].z as f32, v[1].z as f32, v[2].z as f32];
        if let Some((factor, units)) = params.offset {
            let slope = setup.plane(z);
            let o = offset(factor, units, slope.dadx, slope.dady, f);
            let at = |z: f32| (z + o).clamp(0.0, 1.0);
            z = [at(z[0]), at(z[1]), at(z[2])];
        }
        let plane = setup.plane(z);
        put(slot::Z, plane);
        if f == DepthFormat::D32 {
            per_fragment_z = Some((f, plane));
        }
    }
    per_fragment_z
}

/// Polygon offset in window depth, as llvmpipe computes it in f32:
/// `units · 2 / max + max(|dz/dx|, |dz/dy|) · factor`, where `max` is the
/// largest depth value (llvmpipe's unit is twice the minimum resolvable
/// difference: measured, docs/llvmpipe-facts.md). Not-a-number offsets are 0;
/// infinite ones saturate like huge finite ones once depth is clamped.
pub fn offset(factor: f32, units: f32, dzdx: f32, dzdy: f32, format: DepthFormat) -> f32 {
    let o = units * (2.0 / format.max_value() as f32) + dzdx.abs().max(dzdy.abs()) * factor;
    if o.is_nan() {
        0.0
    } else {
        o.clamp(-2.0, 2.0)
    }
}
