//! The block rasterizer against the row rasterizer (`cover`, the oracle) and
//! against a per-pixel i128 evaluation where `cover`'s i64 products would
//! overflow; shared edges covered exactly once.

use super::super::triangle::{cover, Prepared, ROWS_ORACLE};
use super::super::{line, point, triangle, RasterParams, RasterVertex, SpanSink};
use super::*;
use crate::geometry::varying::{VaryingLayout, MAX_VARYINGS};
use proptest::prelude::*;
use softgl_jit::FragmentSpan;
use std::collections::BTreeSet;

/// A vertex whose attributes do not matter (coverage only).
fn vertex(x: f32, y: f32, height: u32) -> RasterVertex {
    RasterVertex {
        x,
        y,
        y_down: height as f32 - y,
        z: 0.5,
        inv_w: 1.0,
        v: [0.0; MAX_VARYINGS],
    }
}

fn params(bounds: Rect, height: u32) -> RasterParams {
    RasterParams {
        bounds,
        depth: None,
        height,
        layout: VaryingLayout::default(),
        offset: None,
    }
}

fn tile_rect(tx: u32, ty: u32) -> Rect {
    Rect {
        x0: tx * TILE,
        y0: ty * TILE,
        x1: tx * TILE + TILE,
        y1: ty * TILE + TILE,
    }
}

fn intersect(a: Rect, b: Rect) -> Rect {
    Rect {
        x0: a.x0.max(b.x0),
        y0: a.y0.max(b.y0),
        x1: a.x1.min(b.x1),
        y1: a.y1.min(b.y1),
    }
}

/// The row rasterizer's coverage of `tile` within `clip`, from the snapped
/// points `p`: the oracle.
fn oracle(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    super::super::row_coverage(p, tile, clip)
}

/// What the render path emits for `tile` within `clip`: the triangle set
/// up within the bounds `clip` (a framebuffer's, many tiles wide) and
/// rasterized at once ([`cover`]), its spans cut to the tile.
fn render(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    let v = vertex(0.0, 0.0, 1024);
    let mut m = TileMask::empty(tile.x0, tile.y0);
    let mut sink = |s: &FragmentSpan| {
        let mut cut = FragmentSpan::new(s.x, s.y);
        (cut.len, cut.mask) = (s.len, s.mask);
        for b in 0..s.len {
            let x = s.x + b;
            if x < tile.x0 || x >= tile.x1 || s.y < tile.y0 || s.y >= tile.y1 {
                cut.mask &= !(1 << b);
            }
        }
        add_span(&mut m, tile, &cut)
    };
    cover((p, None), [&v; 3], None, &params(clip, 1024), &mut sink);
    m
}

/// Adds the fragments of span `s` to `m`, checking each is in `tile` and new.
fn add_span(m: &mut TileMask, tile: Rect, s: &FragmentSpan) {
    for b in 0..s.len {
        if s.mask >> b & 1 == 1 {
            let (x, y) = (s.x + b, s.y);
            assert!(
                x >= tile.x0 && x < tile.x1 && y >= tile.y0 && y < tile.y1,
                "({x}, {y}) off the tile"
            );
            assert!(!m.covers(x, y), "({x}, {y}) emitted twice");
            m.rows[(y - tile.y0) as usize] |= 1 << (x - tile.x0);
        }
    }
}

/// Every pixel of `tile` within `clip` tested on its own, in i128.
fn brute(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    let mut m = TileMask::empty(tile.x0, tile.y0);
    let Some(e) = Edges::new(p) else { return m };
    let r = intersect(tile, clip);
    for y in r.y0..r.y1 {
        for x in r.x0..r.x1 {
            let inside = e.edges.iter().all(|e| {
                let w = i128::from;
                let (sx, sy) = (i64::from(x) * ONE, i64::from(y) * ONE);
                w(e.dx) * w(sy - e.a.1) - w(e.dy) * w(sx - e.a.0) >= w(e.k)
            });
            if inside {
                m.rows[(y - tile.y0) as usize] |= 1 << (x - tile.x0);
            }
        }
    }
    m
}

/// A scene's coverage of `tile`: the triangle set up once within `clip`
/// ([`Prepared`]), then cut to the tile.
fn prepared(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    let mut m = TileMask::empty(tile.x0, tile.y0);
    if let Some(prep) = Prepared::new(p, clip) {
        let mut sink = |s: &FragmentSpan| add_span(&mut m, tile, s);
        prep.cover(tile, 1024, &mut sink, |_| None);
    }
    m
}

fn block(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    match Edges::new(p) {
        Some(e) => tile_coverage(&e, tile, clip),
        None => TileMask::empty(tile.x0, tile.y0),
    }
}

/// Rows as strings (top row first) for a readable failure.
fn show(m: &TileMask) -> String {
    m.rows
        .iter()
        .rev()
        .map(|r| {
            (0..64)
                .map(|i| if r >> i & 1 == 1 { '#' } else { '.' })
                .collect::<String>()
                + "\n"
        })
        .collect()
}

/// Block coverage (one tile, and the render path over many) against the
/// row rasterizer's.
fn check(p: [(i64, i64); 3], tile: Rect, clip: Rect) -> TileMask {
    let (b, o) = (block(p, tile, clip), oracle(p, tile, clip));
    assert!(
        b == o,
        "p = {p:?}, tile {tile:?}, clip {clip:?}\nblock:\n{}oracle:\n{}",
        show(&b),
        show(&o)
    );
    let r = render(p, tile, clip);
    assert!(
        r == o,
        "p = {p:?}, tile {tile:?}, clip {clip:?}\nrender path:\n{}oracle:\n{}",
        show(&r),
        show(&o)
    );
    b
}

#[test]
fn full_tile_and_nothing() {
    let t = tile_rect(1, 2);
    // A huge triangle over the whole framebuffer covers the tile entirely.
    let big = [(-(1 << 20), -(1 << 20)), (1 << 22, -(1 << 20)), (-(1 << 20), 1 << 22)];
    let m = check(big, t, t);
    assert_eq!(m.count(), 64 * 64);
    // Clipped to a 10x3 box at (5, 7) of the tile.
    let clip = Rect {
        x0: t.x0 + 5,
        y0: t.y0 + 7,
        x1: t.x0 + 15,
        y1: t.y0 + 10,
    };
    let m = check(big, t, clip);
    assert_eq!((m.count(), m.rows[7], m.rows[6]), (30, 0x3ff << 5, 0));
    // Degenerate: collinear points cover nothing.
    assert_eq!(
        check([(0, 0), (100 * ONE, 50 * ONE), (50 * ONE, 25 * ONE)], t, t).count(),
        0
    );
    // Beside the tile.
    assert_eq!(check([(0, 0), (10 * ONE, 0), (0, 10 * ONE)], t, t).count(), 0);
}

#[test]
fn right_triangle_exact_pixels() {
    // Centers (x, y) with x + y <= 4 (the hypotenuse through centers goes up
    // to the left: not owned), x >= 0 and y >= 0 (left and bottom: owned).
    let t = tile_rect(0, 0);
    let m = check([(0, 0), (4 * ONE, 0), (0, 4 * ONE)], t, t);
    let want: [u64; 5] = [0b1111, 0b111, 0b11, 0b1, 0];
    assert_eq!(&m.rows[..5], &want);
    assert_eq!(m.count(), 10);
}

/// Every triangle of a small grid of points (centres, half-pixel and
/// quarter-pixel offsets), both windings, on clip rects that cut it.
#[test]
fn small_grid_exhaustive() {
    let t = tile_rect(0, 0);
    let vals = [-ONE / 2, 0, ONE / 4, ONE, 3 * ONE / 2, 3 * ONE];
    let pts: Vec<(i64, i64)> = vals.iter().flat_map(|&x| vals.iter().map(move |&y| (x, y))).collect();
    let clips = [
        t,
        Rect {
            x0: 1,
            y0: 0,
            x1: 3,
            y1: 2,
        },
    ];
    for &a in &pts {
        for &b in &pts {
            for &c in &pts {
                for clip in clips {
                    check([a, b, c], t, clip);
                }
            }
        }
    }
}

/// Vertices at block corners and centres across a tile's 16x16 and 4x4
/// block boundaries, so that edges run along and through block borders.
#[test]
fn block_grid_exhaustive() {
    let t = tile_rect(1, 1);
    let o = 64 * ONE;
    let vals = [
        o - 8 * ONE,
        o,
        o + 15 * ONE + ONE / 2,
        o + 16 * ONE,
        o + 33 * ONE,
        o + 64 * ONE,
        o + 70 * ONE,
    ];
    let pts: Vec<(i64, i64)> = vals.iter().flat_map(|&x| vals.iter().map(move |&y| (x, y))).collect();
    let clip = Rect {
        x0: 70,
        y0: 64,
        x1: 200,
        y1: 120,
    };
    for &a in &pts {
        for (n, &b) in pts.iter().enumerate() {
            for &c in &pts[n..] {
                check([a, b, c], t, t);
                check([a, c, b], t, clip);
            }
        }
    }
}

#[test]
fn window_edges_match_triangle() {
    // The points `Edges::window` snaps are the ones `triangle` rasterizes,
    // including y values whose top-down snap differs from the bottom-up one.
    let height = 300;
    let t = tile_rect(1, 1);
    let mut rng = softgl_jit::rng::Rng::new(7);
    for _ in 0..2000 {
        let v = [0; 3].map(|_| vertex(rng.range(40.0, 200.0), rng.range(40.0, 200.0), height));
        let e = Edges::window([&v[0], &v[1], &v[2]], height);
        let b = e.map_or(TileMask::empty(t.x0, t.y0), |e| tile_coverage(&e, t, t));
        let mut o = TileMask::empty(t.x0, t.y0);
        let mut sink = |s: &FragmentSpan| add_span(&mut o, t, s);
        triangle([&v[0], &v[1], &v[2]], None, &params(t, height), &mut sink);
        assert_eq!(b, o, "{:?}", v.map(|v| (v.x, v.y)));
    }
}

/// Random triangle shapes around tile `(tx, ty)` (fixed point).
fn points(max_tile: u32) -> impl Strategy<Value = ([(i64, i64); 3], u32, u32)> {
    let tile = (0..max_tile, 0..max_tile);
    let scale = prop_oneof![Just(4 * ONE), Just(40 * ONE), Just(200 * ONE), Just(3000 * ONE)];
    let random = (tile.clone(), scale, any::<[(i32, i32); 3]>()).prop_map(|((tx, ty), s, r)| {
        let c = (i64::from(tx * 64 + 32) * ONE, i64::from(ty * 64 + 32) * ONE);
        let p = r.map(|(x, y)| (c.0 + i64::from(x) % s, c.1 + i64::from(y) % s));
        (p, tx, ty)
    });
    // Coordinates on a lattice of centres, half pixels or block corners, so
    // that vertices sit on centres and edges pass through them.
    let step = prop_oneof![Just(ONE / 2), Just(ONE), Just(4 * ONE), Just(16 * ONE)];
    let lattice = (tile.clone(), step, any::<[(i8, i8); 3]>()).prop_map(|((tx, ty), s, r)| {
        let o = (i64::from(tx * 64) * ONE, i64::from(ty * 64) * ONE);
        let p = r.map(|(x, y)| (o.0 + i64::from(x % 24) * s, o.1 + i64::from(y % 24) * s));
        (p, tx, ty)
    });
    // Slivers: a long edge and a third point within a few units of its line.
    let sliver = (tile.clone(), any::<(i32, i32, i32, i32)>(), 0..1024i64, -3..=3i64).prop_map(
        |((tx, ty), (x, y, dx, dy), t, off)| {
            let c = (i64::from(tx * 64 + 32) * ONE, i64::from(ty * 64 + 32) * ONE);
            let a = (c.0 + i64::from(x % (40 * 256)), c.1 + i64::from(y % (40 * 256)));
            let d = (i64::from(dx % (300 * 256)), i64::from(dy % (300 * 256)));
            let m = (a.0 + d.0 * t / 1024 + off, a.1 + d.1 * t / 1024 - off);
            ([a, (a.0 + d.0, a.1 + d.1), m], tx, ty)
        },
    );
    // Huge: up to ±2^30 units (4M pixels), where cover's i64 products still
    // fit; one vertex near the tile so that an edge crosses it.
    let huge = (tile.clone(), any::<[(i64, i64); 2]>(), any::<(i16, i16)>()).prop_map(|((tx, ty), far, (x, y))| {
        let c = (i64::from(tx * 64 + 32) * ONE, i64::from(ty * 64 + 32) * ONE);
        let near = (c.0 + i64::from(x) % (48 * ONE), c.1 + i64::from(y) % (48 * ONE));
        let f = far.map(|(x, y)| (x % (1 << 30), y % (1 << 30)));
        ([near, f[0], f[1]], tx, ty)
    });
    // Degenerate: collinear points, or two equal.
    let flat = (tile, any::<((i32, i32), (i16, i16))>(), -3..=3i64).prop_map(|((tx, ty), ((x, y), (dx, dy)), t)| {
        let a = (i64::from(x % (400 * 256)), i64::from(y % (400 * 256)));
        let d = (i64::from(dx), i64::from(dy));
        ([a, (a.0 + d.0, a.1 + d.1), (a.0 + t * d.0, a.1 + t * d.1)], tx, ty)
    });
    prop_oneof![3 => random, 3 => lattice, 2 => sliver, 2 => huge, 1 => flat]
}

/// A clip rect: the whole tile, or a random rect that may cut it.
fn clip_of(tile: Rect) -> impl Strategy<Value = Rect> {
    let cut = (0..80u32, 0..80u32, 0..80u32, 0..80u32).prop_map(move |(a, b, w, h)| Rect {
        x0: (tile.x0 + a).saturating_sub(8),
        y0: (tile.y0 + b).saturating_sub(8),
        x1: (tile.x0 + a).saturating_sub(8) + w,
        y1: (tile.y0 + b).saturating_sub(8) + h,
    });
    prop_oneof![Just(tile), cut]
}

/// Triangles of a few pixels near a tile's corner (most straddle a tile
/// edge), vertices anywhere on the sub-pixel grid or on centres and halves.
fn tiny() -> impl Strategy<Value = ([(i64, i64); 3], u32, u32)> {
    let tile = (1..4u32, 1..4u32);
    let size = prop_oneof![Just(ONE / 2), Just(2 * ONE), Just(6 * ONE), Just(12 * ONE)];
    let any_units =
        (tile.clone(), -12..12i64, -12..12i64, size, any::<[(i32, i32); 3]>()).prop_map(|((tx, ty), cx, cy, s, r)| {
            let c = ((i64::from(tx * 64) + cx) * ONE, (i64::from(ty * 64) + cy) * ONE);
            (r.map(|(x, y)| (c.0 + i64::from(x) % s, c.1 + i64::from(y) % s)), tx, ty)
        });
    let halves = (tile, any::<[(i8, i8); 3]>()).prop_map(|((tx, ty), r)| {
        let c = (i64::from(tx * 64) * ONE, i64::from(ty * 64) * ONE);
        (
            r.map(|(x, y)| (c.0 + i64::from(x % 16) * ONE / 2, c.1 + i64::from(y % 16) * ONE / 2)),
            tx,
            ty,
        )
    });
    prop_oneof![any_units, halves]
}

fn case() -> impl Strategy<Value = ([(i64, i64); 3], Rect, Rect, bool)> {
    (points(4), any::<bool>()).prop_flat_map(|((p, tx, ty), swap)| {
        let t = tile_rect(tx, ty);
        (Just(p), Just(t), clip_of(t), Just(swap))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4000, ..ProptestConfig::default() })]

    /// A triangle set up once and cut to each tile (a scene's flush) ==
    /// per-pixel i128, for tiny triangles (per-pixel masks) and any.
    #[test]
    fn prepared_equals_brute(
        (p, tx, ty) in tiny(),
        (cx, cy, cw, ch) in (0..90u32, 0..90u32, 0..200u32, 0..200u32),
        (q, tile, clip, _) in case(),
    ) {
        // The four tiles around the corner, within a clip (the bounds).
        let clip_tiny = Rect { x0: cx, y0: cy, x1: cx + cw, y1: cy + ch };
        for (cx, cy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let t = tile_rect(tx + cx - 1, ty + cy - 1);
            for c in [t, clip_tiny] {
                let got = prepared(p, t, c);
                prop_assert_eq!(got, brute(p, t, c), "p = {:?}, tile {:?}, clip {:?}", p, t, c);
            }
        }
        prop_assert_eq!(prepared(q, tile, clip), brute(q, tile, clip));
    }

    /// Block coverage == row coverage == per-pixel i128, pixel for pixel.
    #[test]
    fn block_equals_rows((p, tile, clip, swap) in case()) {
        let p = if swap { [p[0], p[2], p[1]] } else { p };
        let b = check(p, tile, clip);
        prop_assert_eq!(b, brute(p, tile, clip));
        if Edges::new(p).is_none() {
            prop_assert_eq!(b.count(), 0);
        }
    }

    /// The whole snap range (±2^40 units), past what `cover`'s i64 products
    /// hold: block coverage == per-pixel i128.
    #[test]
    fn block_exact_at_snap_limits(
        (tx, ty) in (0..64u32, 0..64u32),
        far in any::<[(i64, i64); 3]>(),
        near in any::<(i16, i16)>(),
        which in 0..3usize,
        clamp in any::<bool>(),
    ) {
        let t = tile_rect(tx, ty);
        let lim = 1i64 << 40;
        let mut p = far.map(|(x, y)| {
            if clamp { (x.signum() * lim, y.signum() * lim) } else { (x % lim, y % lim) }
        });
        // One vertex near the tile, so that edges cross it.
        p[which] = (i64::from(tx * 64 + 32) * ONE + i64::from(near.0), i64::from(ty * 64 + 32) * ONE + i64::from(near.1));
        prop_assert_eq!(block(p, t, t), brute(p, t, t));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Edges just inside the i32 form's limit (`|dx| + |dy|` up to
    /// 2^24 − 2 units, 65535 pixels) and just past it: block coverage and
    /// the render path == per-pixel i128.
    #[test]
    fn block_exact_at_narrow_limit(
        (tx, ty) in (0..64u32, 0..64u32),
        far in any::<[(i32, i32); 2]>(),
        near in any::<(i16, i16)>(),
        past in any::<bool>(),
    ) {
        let t = tile_rect(tx, ty);
        let reach = (1i64 << 23) - 1 + i64::from(past) * 4;
        let a = (i64::from(tx * 64 + 32) * ONE + i64::from(near.0), i64::from(ty * 64 + 32) * ONE + i64::from(near.1));
        let p = [
            a,
            (a.0 + i64::from(far[0].0) % reach, a.1 + i64::from(far[0].1) % reach),
            (a.0 + i64::from(far[1].0) % reach, a.1 + i64::from(far[1].1) % reach),
        ];
        let want = brute(p, t, t);
        prop_assert_eq!(block(p, t, t), want);
        prop_assert_eq!(prepared(p, t, t), want);
    }
}

/// Pixels of the fixed-point rectangle `[x0, x1) x [y0, y1)` by GL's rule:
/// centres on the left and bottom sides are in, on the right and top out.
fn rect_has(r: (i64, i64, i64, i64), x: u32, y: u32) -> bool {
    let (sx, sy) = (i64::from(x) * ONE, i64::from(y) * ONE);
    r.0 <= sx && sx < r.2 && r.1 <= sy && sy < r.3
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 600, ..ProptestConfig::default() })]

    /// A rectangle as a fan of triangles around an inner point, through
    /// extra points on its sides, over 3x3 tiles: every pixel of the
    /// rectangle is covered exactly once, no other pixel at all.
    #[test]
    fn fan_covers_rectangle_once(
        corners in (-20 * ONE..100 * ONE, -20 * ONE..100 * ONE, 110 * ONE..212 * ONE, 110 * ONE..212 * ONE),
        centre in (0..1000i64, 0..1000i64),
        on_sides in proptest::collection::vec((0..4usize, 1..1000i64), 0..6),
        grid in any::<bool>(),
    ) {
        let snap_to = |v: i64| if grid { v / (ONE / 2) * (ONE / 2) } else { v };
        let (x0, y0, x1, y1) = (snap_to(corners.0), snap_to(corners.1), snap_to(corners.2), snap_to(corners.3));
        let c = (x0 + (x1 - x0) * (centre.0 + 1) / 1002, y0 + (y1 - y0) * (centre.1 + 1) / 1002);
        let c = (snap_to(c.0).max(x0 + 1), snap_to(c.1).max(y0 + 1));
        // Boundary points, counter-clockwise from (x0, y0).
        let mut ring = Vec::new();
        for side in 0..4 {
            let (a, b) = [((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))][side];
            let mut ts: Vec<i64> = on_sides.iter().filter(|s| s.0 == side).map(|s| s.1).collect();
            ts.sort_unstable();
            ts.dedup();
            ring.push(a);
            for t in ts {
                ring.push((a.0 + (b.0 - a.0) * t / 1000, a.1 + (b.1 - a.1) * t / 1000));
            }
        }
        let tris: Vec<Edges> = (0..ring.len())
            .filter_map(|i| Edges::new([c, ring[i], ring[(i + 1) % ring.len()]]))
            .collect();
        for ty in 0..4 {
            for tx in 0..4 {
                let t = tile_rect(tx, ty);
                // Pixels covered once, and more than once, row by row.
                let (mut once, mut more) = ([0u64; 64], [0u64; 64]);
                for e in &tris {
                    let m = tile_coverage(e, t, t);
                    for j in 0..64 {
                        more[j] |= once[j] & m.rows[j];
                        once[j] |= m.rows[j];
                    }
                }
                for j in 0..64u32 {
                    let want = (0..64u32)
                        .filter(|&i| rect_has((x0, y0, x1, y1), t.x0 + i, t.y0 + j))
                        .fold(0u64, |w, i| w | 1 << i);
                    prop_assert_eq!((once[j as usize], more[j as usize]), (want, 0), "row {} of tile {:?}", j, t);
                }
            }
        }
    }

    /// Two triangles on either side of a shared edge, either winding each:
    /// no pixel covered by both, and every centre on the open shared segment
    /// covered by exactly one.
    #[test]
    fn shared_edge_once(
        (a, b) in ((0..96i64, 0..96i64), (0..96i64, 0..96i64)),
        (c, d) in ((0..400 * ONE, 0..400 * ONE), (0..400 * ONE, 0..400 * ONE)),
        swaps in any::<(bool, bool)>(),
        clip_cut in 0..64u32,
    ) {
        // a and b on centres or half pixels, so the shared edge goes through centres.
        let (a, b) = ((a.0 * ONE / 2, a.1 * ONE / 2), (b.0 * ONE / 2, b.1 * ONE / 2));
        let side = |p: (i64, i64)| (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0);
        prop_assume!(side(c) != 0 && side(d) != 0);
        // Put d on the other side of the line (its reflection through the
        // segment's midpoint has the opposite side).
        let d = if (side(c) > 0) == (side(d) > 0) { (a.0 + b.0 - d.0, a.1 + b.1 - d.1) } else { d };
        let t1 = if swaps.0 { [a, b, c] } else { [b, a, c] };
        let t2 = if swaps.1 { [a, b, d] } else { [b, a, d] };
        for ty in 0..2 {
            for tx in 0..2 {
                let t = tile_rect(tx, ty);
                let clip = Rect { x0: clip_cut, ..t };
                let (m1, m2) = (check(t1, t, clip), check(t2, t, clip));
                for (r1, r2) in m1.rows.iter().zip(&m2.rows) {
                    prop_assert_eq!(r1 & r2, 0);
                }
                let r = intersect(t, clip);
                for y in r.y0..r.y1 {
                    for x in r.x0..r.x1 {
                        let s = (i64::from(x) * ONE, i64::from(y) * ONE);
                        let on = side(s) == 0
                            && (s.0 - a.0) * (s.0 - b.0) + (s.1 - a.1) * (s.1 - b.1) < 0;
                        if on {
                            prop_assert!(m1.covers(x, y) != m2.covers(x, y), "centre ({}, {})", x, y);
                        }
                    }
                }
            }
        }
    }
}

/// The pixels a draw emits, each once (asserted).
fn drawn(draw: &dyn Fn(&mut dyn SpanSink)) -> BTreeSet<(u32, u32)> {
    let mut out = BTreeSet::new();
    let mut sink = |s: &FragmentSpan| {
        for b in (0..s.len).filter(|b| s.mask >> b & 1 == 1) {
            assert!(out.insert((s.x + b, s.y)), "({}, {}) emitted twice", s.x + b, s.y);
        }
    };
    draw(&mut sink);
    out
}

/// The pixels of a draw with the block rasterizer and with the row
/// rasterizer (the oracle) covering its triangles.
fn both_ways(draw: &dyn Fn(&mut dyn SpanSink)) -> [BTreeSet<(u32, u32)>; 2] {
    let blocks = drawn(draw);
    ROWS_ORACLE.with(|o| o.set(true));
    let rows = drawn(draw);
    ROWS_ORACLE.with(|o| o.set(false));
    [blocks, rows]
}

/// A window coordinate: on a pixel centre, on a pixel edge, on the
/// sub-pixel grid, anywhere, or far out (edges past the i32 form's limit).
fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![
        (0..300i32).prop_map(|c| c as f32 + 0.5),
        (0..300i32).prop_map(|c| c as f32),
        (0..300 * 256i32).prop_map(|c| c as f32 / 256.0),
        -20.0f32..320.0,
        prop_oneof![-200_000.0f32..-70_000.0, 70_000.0f32..200_000.0],
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1500, ..ProptestConfig::default() })]

    /// Triangles, lines of every width and points drawn through the
    /// rasterizer's entry points within random bounds: the block rasterizer
    /// and the row rasterizer give the same pixels, each once.
    #[test]
    fn primitives_blocks_equal_rows(
        p in [(coordinate(), coordinate()), (coordinate(), coordinate()), (coordinate(), coordinate())],
        width in 0.5f32..12.0,
        (bx, by, bw, bh) in (0..200u32, 0..200u32, 1..300u32, 1..300u32),
    ) {
        let height = 300;
        let bounds = Rect { x0: bx, y0: by, x1: (bx + bw).min(300), y1: (by + bh).min(300) };
        let params = params(bounds, height);
        let v = p.map(|(x, y)| vertex(x, y, height));
        let [b, r] = both_ways(&|s| triangle([&v[0], &v[1], &v[2]], None, &params, s));
        prop_assert_eq!(b, r, "triangle {:?}", p);
        let [b, r] = both_ways(&|s| line(&v[0], &v[1], width, None, &params, s));
        prop_assert_eq!(b, r, "line {:?} width {}", &p[..2], width);
        let [b, r] = both_ways(&|s| point(&v[2], width, &params, s));
        prop_assert_eq!(b, r, "point {:?} size {}", p[2], width);
    }
}
