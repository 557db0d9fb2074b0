//! Exact answers for scenes whose reference cannot be Mesa: triangles with
//! vertices near ±1e30, which llvmpipe's and softpipe's f32 clippers lose.
//!
//! Coverage is decided in exact arithmetic: the clip-space vertices (f32)
//! and the pixel centres are scaled to integers-or-f32 values that f64 holds
//! exactly (x·W, y·H: the sign of an orientation does not change when each
//! axis is scaled by a positive number), and the orientation determinant is
//! summed as an f64 expansion (Shewchuk's two-sum, two-product and
//! grow-expansion), so its sign is the sign of the real number. A pixel
//! centre exactly on an edge would need the fill rule; the scenes have none,
//! and the oracle panics if one appears.

use super::Size;
use image::{Rgba, RgbaImage};

/// `a + b` as an exact pair (sum, error).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a * b` as an exact pair (product, error), through a fused multiply-add.
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Adds `b` to the nonoverlapping expansion `e` (smallest first), exactly.
fn grow(e: &mut Vec<f64>, b: f64) {
    let mut q = b;
    for x in e.iter_mut() {
        let (s, err) = two_sum(q, *x);
        *x = err;
        q = s;
    }
    e.push(q);
}

/// The exact sign of `(b - a) x (c - a)`: positive when a, b, c turn
/// counter-clockwise.
pub fn orientation(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> std::cmp::Ordering {
    let diff = |p: f64, q: f64| {
        let (d, e) = two_sum(p, -q);
        [d, e]
    };
    let (bx, by, cx, cy) = (diff(b[0], a[0]), diff(b[1], a[1]), diff(c[0], a[0]), diff(c[1], a[1]));
    let mut sum = Vec::with_capacity(16);
    for (l, r, sign) in [(bx, cy, 1.0), (by, cx, -1.0)] {
        for x in l {
            for y in r {
                let (p, e) = two_product(x, y);
                grow(&mut sum, sign * p);
                grow(&mut sum, sign * e);
            }
        }
    }
    // Nonoverlapping and ordered by magnitude: the last nonzero term has the sign.
    let top = sum.iter().rev().find(|v| **v != 0.0).copied().unwrap_or(0.0);
    top.partial_cmp(&0.0).expect("finite")
}

/// Whether `p` is strictly inside triangle `t`, exactly; panics when `p`
/// lies on an edge (the oracle has no fill rule).
fn inside(t: [[f64; 2]; 3], p: [f64; 2]) -> bool {
    let [a, b, c] = t;
    let turn = orientation(a, b, c);
    [(a, b), (b, c), (c, a)].iter().all(|&(u, v)| {
        let o = orientation(u, v, p);
        assert!(
            o != std::cmp::Ordering::Equal,
            "pixel centre {p:?} lies on an edge: the oracle has no fill rule"
        );
        o == turn
    })
}

/// A colour in [0, 1] to 8 bits, rounded to nearest.
fn unorm8(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// A triangle in clip space (w = 1, identity matrices) in one colour.
#[derive(Clone, Copy, Debug)]
pub struct ClipTriangle {
    pub vertices: [[f32; 2]; 3],
    pub color: [f32; 4],
}

impl ClipTriangle {
    /// Whether the centre of window pixel (x, y) (y up) is inside, exactly.
    pub fn covers(&self, s: Size, x: u32, y: u32) -> bool {
        // Clip x·W against the centre's 2x + 1 - W (and y likewise): both exact in f64.
        let scale = |v: [f32; 2]| [v[0] as f64 * s.w as f64, v[1] as f64 * s.h as f64];
        let p = [(2 * x + 1) as f64 - s.w as f64, (2 * y + 1) as f64 - s.h as f64];
        inside(self.vertices.map(scale), p)
    }
}

/// A smooth-shaded triangle in window coordinates (the scenes' pixel-unit
/// orthographic projection), z in object units in [-1, 1].
#[derive(Clone, Copy, Debug)]
pub struct SmoothTriangle {
    pub vertices: [[f32; 3]; 3],
    pub colors: [[f32; 4]; 3],
}

/// `triangles` drawn in order with the depth test LESS over a transparent
/// black clear (depth 1), top row first. Coverage is exact; depth and
/// colours are interpolated in f64 (relative error near 1e-16, against the
/// 2^-24 of a depth buffer and the 1/510 of a colour's rounding), colours
/// rounded to nearest.
pub fn depth_tested_image(triangles: &[SmoothTriangle], s: Size) -> RgbaImage {
    // glOrtho(.., -1, 1) maps object z to window depth (1 - z) / 2: nearer is larger z.
    let mut depth = vec![-1.0f64; (s.w * s.h) as usize];
    let mut image = RgbaImage::new(s.w, s.h);
    for t in triangles {
        let v = t.vertices.map(|v| [v[0] as f64, v[1] as f64]);
        let area =
            |a: [f64; 2], b: [f64; 2], c: [f64; 2]| (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        let whole = area(v[0], v[1], v[2]);
        if orientation(v[0], v[1], v[2]) == std::cmp::Ordering::Equal {
            continue;
        }
        for y in 0..s.h {
            for x in 0..s.w {
                let p = [x as f64 + 0.5, y as f64 + 0.5];
                if !inside(v, p) {
                    continue;
                }
                let l = [area(p, v[1], v[2]), area(v[0], p, v[2]), area(v[0], v[1], p)].map(|a| a / whole);
                let lerp = |f: &dyn Fn(usize) -> f64| (0..3).map(|i| l[i] * f(i)).sum::<f64>();
                let z = lerp(&|i| t.vertices[i][2] as f64);
                let d = &mut depth[(y * s.w + x) as usize];
                if z > *d {
                    *d = z;
                    let c: [u8; 4] = std::array::from_fn(|k| unorm8(lerp(&|i| t.colors[i][k] as f64)));
                    image.put_pixel(x, s.h - 1 - y, Rgba(c));
                }
            }
        }
    }
    image
}

/// The exact image of `triangles` drawn in order over a transparent black
/// clear, top row first (as the back ends return images).
pub fn image(triangles: &[ClipTriangle], s: Size) -> RgbaImage {
    RgbaImage::from_fn(s.w, s.h, |col, row| {
        let y = s.h - 1 - row;
        triangles
            .iter()
            .rev()
            .find(|t| t.covers(s, col, y))
            .map_or(Rgba([0; 4]), |t| Rgba(t.color.map(|c| unorm8(c as f64))))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering::{Equal, Greater, Less};

    #[test]
    fn orientation_is_exact_where_f64_is_not() {
        let big = 1e30;
        // (-big, -big) -> (big, big) is the line y = x; f64 evaluated naively
        // loses the 1e-3 against 1e30 and calls all three collinear.
        let naive =
            |a: [f64; 2], b: [f64; 2], c: [f64; 2]| (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        let (a, b) = ([-big, -big], [big, big]);
        assert_eq!(naive(a, b, [0.0, 1e-3]), 0.0);
        assert_eq!(orientation(a, b, [0.0, 1e-3]), Greater);
        assert_eq!(orientation(a, b, [1e-3, 0.0]), Less);
        assert_eq!(orientation(a, b, [7.0, 7.0]), Equal);
        assert_eq!(orientation([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), Greater);
    }

    #[test]
    fn a_unit_triangle_covers_the_centres_inside_it() {
        let s = Size {
            w: 4,
            h: 4,
            full: false,
        };
        // Clip (-1,-1), (1,-1), (-1,1): the lower-left half of the window,
        // centres with x + 0.5 + y + 0.5 < 4; those with x + y = 3 lie on
        // the diagonal.
        let t = ClipTriangle {
            vertices: [[-1.0, -1.0], [1.0, -1.0], [-1.0, 1.0]],
            color: [1.0; 4],
        };
        for y in 0..4 {
            for x in 0..4 {
                if x + y != 3 {
                    assert_eq!(t.covers(s, x, y), x + y < 3, "({x}, {y})");
                }
            }
        }
        let on_edge = std::panic::catch_unwind(|| t.covers(s, 1, 2));
        assert!(on_edge.is_err(), "a centre on an edge is refused");
    }
}
