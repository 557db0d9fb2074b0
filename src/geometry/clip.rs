//! Homogeneous clipping, before any division: against the near and far planes
//! and against a guard band in x and y (the rasterizer then bounds fragments to
//! the viewport, which is exact clipping without new vertices on the sides).
//!
//! Clip coordinates are f64 here. A primitive with a coordinate beyond 10^4,
//! or with a vertex (`w > 0`) outside the 10^4 guard band, is brought in
//! through guard bands 10^8 apart, so each intersection is computed from
//! endpoints at most 10^8 times larger than the plane it lands on (f64 keeps
//! ~16 digits, leaving 8); any other goes straight to the last step, as in
//! llvmpipe (which has no guard band). The last step, onto the
//! view volume itself, computes in f32 exactly as llvmpipe's clipper does
//! (`draw_pipe_clip.c`), so that clipped vertices, and the colours and depths
//! interpolated from them, carry the same bits. Polygons: planes right, left,
//! top, bottom, near, far; each crossing is `a + t·(b − a)`,
//! `t = d_a / (d_a − d_b)`, from the endpoint `a` nearer the plane (the inside
//! one on a tie), so `t` is small and a far endpoint (1e38, or a guard-band
//! vertex rounded to f32) moves the crossing only by its rounding times `t`.
//! Lines: each end is moved once from the ends the step starts from, by the
//! largest `t` of the planes it is outside of.

use super::fma::fma;
use super::varying::Varyings;
use glam::DVec4;

/// A vertex in clip space with the attributes clipping interpolates: the
/// first `n` slots of `v`, `n` the draw's `VaryingLayout::len` (the functions
/// here take it as a parameter and never touch the slots past it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    pub pos: DVec4,
    pub v: Varyings,
}

/// Scales of the nested guard bands, outermost first, relative to the final one.
pub const GUARD_LEVELS: [f64; 6] = [1e32, 1e24, 1e16, 1e8, 1e4, 1.0];

/// A primitive whose clip coordinates are all within this magnitude, and whose
/// vertices with `w > 0` are all inside the guard band of this scale, is
/// clipped in one f32 step, as llvmpipe clips it (a vertex with `w <= 0` is
/// outside every guard band, and would otherwise be brought in through all of
/// them, near and far planes first).
const DIRECT_BOUND: f64 = 1e4;

/// The guard scales to clip `vertices` through: all of them for a primitive
/// beyond `DIRECT_BOUND`, else the view volume alone.
pub fn guard_levels<'a>(mut vertices: impl Iterator<Item = &'a ClipVertex>) -> &'static [f64] {
    let near = |v: &ClipVertex| {
        v.pos.abs().max_element() <= DIRECT_BOUND && (v.pos.w <= 0.0 || outcode(v.pos, DIRECT_BOUND) & 0b11_1100 == 0)
    };
    if vertices.all(near) {
        &GUARD_LEVELS[GUARD_LEVELS.len() - 1..]
    } else {
        &GUARD_LEVELS
    }
}

/// The order llvmpipe clips against the view volume's planes (indices as in `dist`).
/// (The half-z near plane is where the near plane is: only one of them is ever set.)
const FINAL_ORDER: [usize; 7] = [3, 2, 5, 4, 0, NEAR_HALF_Z, 1];
/// The order the guard bands are clipped in.
const GUARD_ORDER: [usize; 7] = [0, NEAR_HALF_Z, 1, 2, 3, 4, 5];

impl ClipVertex {
    /// Whether the position and the first `n` varyings are finite.
    pub fn is_finite(&self, n: usize) -> bool {
        self.pos.is_finite() && self.v[..n].iter().all(|c| c.is_finite())
    }

    /// The point where the segment to `o` crosses a plane, given the signed
    /// distances `d` of `self` and `do_` of `o` (opposite signs). Computed as
    /// the weighted sum `(d·o − do·self) / (d − do)`, whose weights do not
    /// cancel, rather than `self + (o − self)·t`, which loses a small `w` next to
    /// a large one. Every component comes from the same two weights, so a
    /// rounding error moves the point along the segment, never off it.
    fn crossing(&self, o: &ClipVertex, d: f64, do_: f64, n: usize) -> ClipVertex {
        let sum = d - do_;
        let pos = (o.pos * d - self.pos * do_) / sum;
        let t = d / sum;
        let mut v = self.v;
        for (c, &oc) in v[..n].iter_mut().zip(&o.v[..n]) {
            *c = (f64::from(*c) + (f64::from(oc) - f64::from(*c)) * t) as f32;
        }
        ClipVertex { pos, v }
    }

    /// The crossing as llvmpipe computes it, in f32: `a + t·(b − a)`,
    /// `t = d_a / (d_a − d_b)`, from the endpoint `a` nearer the plane (the
    /// inside one on a tie), so that `t` is small and the far endpoint's
    /// magnitude cancels out. `d_in` and `d_out` are the distances of the
    /// inside vertex `self` and the outside vertex `o`.
    fn crossing_f32(&self, o: &ClipVertex, d_in: f32, d_out: f32, n: usize) -> ClipVertex {
        let (a, b, da, db) = if -d_out < d_in {
            (o, self, d_out, d_in)
        } else {
            (self, o, d_in, d_out)
        };
        a.lerp_f32(b, da / (da - db), n)
    }

    /// `self + t·(o − self)` in f32, position and the `n` varyings alike.
    fn lerp_f32(&self, o: &ClipVertex, t: f32, n: usize) -> ClipVertex {
        let (pa, pb) = (self.pos.as_vec4(), o.pos.as_vec4());
        let pos = (pa + (pb - pa) * t).as_dvec4();
        let mut v = self.v;
        for (c, &oc) in v[..n].iter_mut().zip(&o.v[..n]) {
            *c += (oc - *c) * t;
        }
        ClipVertex { pos, v }
    }
}

/// Signed distance to plane `k` of the view volume, in f32.
#[inline]
fn dist_f32(p: DVec4, k: usize) -> f32 {
    let p = p.as_vec4();
    match k {
        0 => p.z + p.w,
        1 => p.w - p.z,
        2 => p.x + p.w,
        3 => p.w - p.x,
        4 => p.y + p.w,
        5 => p.w - p.y,
        _ => p.z,
    }
}

/// Signed distance of `p` to clip plane `k` (inside when `>= 0`): near, far,
/// then left, right, bottom, top scaled by `g` (1 for the view volume itself);
/// 6: the near plane `z ≥ 0` of `GL_ZERO_TO_ONE` ([`NEAR_HALF_Z`]).
#[inline]
fn dist(p: DVec4, k: usize, g: f64) -> f64 {
    let (x, y, z, w) = (p.x, p.y, p.z, p.w);
    match k {
        0 => w + z,
        1 => w - z,
        2 => g * w + x,
        3 => g * w - x,
        4 => g * w + y,
        5 => g * w - y,
        _ => z,
    }
}

/// The plane index (and outcode bit) of the near plane under
/// `glClipControl(…, GL_ZERO_TO_ONE)`: `z ≥ 0`, in place of plane 0's `z ≥ −w`.
pub const NEAR_HALF_Z: usize = 6;

/// [`outcode`] with the near plane of the clip depth mode: `half_z` moves it to `z ≥ 0`.
#[inline]
pub fn outcode_in(p: DVec4, g: f64, half_z: bool) -> u8 {
    let c = outcode(p, g);
    if half_z {
        (c & !1) | (u8::from(p.z < 0.0) << NEAR_HALF_Z)
    } else {
        c
    }
}

/// [`outcode_f32`] with the near plane of the clip depth mode (see [`outcode_in`]).
#[inline(always)]
pub fn outcode_f32_in(p: glam::Vec4, half_z: bool) -> u8 {
    let c = outcode_f32(p);
    if half_z {
        (c & !1) | (u8::from(p.z < 0.0) << NEAR_HALF_Z)
    } else {
        c
    }
}

/// Bit `k` set when `p` is outside plane `k` at guard scale `g`.
#[inline]
pub fn outcode(p: DVec4, g: f64) -> u8 {
    (0..6).fold(0, |code, k| if dist(p, k, g) < 0.0 { code | (1 << k) } else { code })
}

/// [`outcode`] at guard scale 1 of a position given in f32 (what
/// `outcode(p.as_dvec4(), 1.0)` returns), computed in f32, three planes a
/// step (one add or subtract of four lanes): the sum or difference of two f32 values has the sign of the exact
/// one in f32 as in f64 (rounding to nearest never crosses zero, and
/// gradual underflow gives zero only for an exact zero; an overflow keeps
/// its sign; NaN compares false in both). The batch classifies every
/// vertex with it: 34 instructions a vertex in f64 on lit16 (callgrind; the
/// conversions to f64 on top), about 26 here.
#[inline(always)]
pub fn outcode_f32(p: glam::Vec4) -> u8 {
    let w = glam::Vec4::splat(p.w);
    let zxy = glam::Vec4::new(p.z, p.x, p.y, 0.0);
    // Bit 0, 1, 2: the near, left, bottom planes (`w + z`, `w + x`, `w + y`),
    // then far, right, top (`w − z`, …).
    let plus = (w + zxy).cmplt(glam::Vec4::ZERO).bitmask() & 7;
    let minus = (w - zxy).cmplt(glam::Vec4::ZERO).bitmask() & 7;
    /// Bits 0, 1, 2 moved to 0, 2, 4.
    const SPREAD: [u8; 8] = [0, 1, 4, 5, 16, 17, 20, 21];
    SPREAD[plus as usize] | SPREAD[minus as usize] << 1
}

/// The enabled user clip planes of a draw, in clip coordinates, and how
/// llvmpipe evaluates them (`docs/llvmpipe-facts.md` § "User clip planes").
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UserPlanes {
    pub planes: [[f32; 4]; 6],
    /// Bit `i` set when plane `i` is enabled.
    pub enabled: u8,
}

impl UserPlanes {
    /// Bit `i` set when `p` is outside enabled plane `i`, by draw's vertex
    /// test (`draw_llvm.c`): `0 > d`, `d` a chain of `fmuladd`s, which LLVM
    /// fuses on a CPU with FMA: `fma(w, pw, fma(z, pz, fma(y, py, x·px)))`.
    #[inline]
    pub fn code(&self, p: DVec4) -> u8 {
        if self.enabled == 0 {
            return 0;
        }
        let p = p.as_vec4();
        (0..6).fold(0, |code, i| {
            let q = &self.planes[i];
            let d = fma(q[3], p.w, fma(q[2], p.z, fma(q[1], p.y, q[0] * p.x)));
            if self.enabled & (1 << i) != 0 && 0.0 > d {
                code | (1 << i)
            } else {
                code
            }
        })
    }

    /// Distance to plane `i` as draw's clipper computes it (`draw_pipe_clip.c`
    /// `dot4`, in C order without fusing).
    fn dist(&self, p: DVec4, i: usize) -> f32 {
        let (p, q) = (p.as_vec4(), &self.planes[i]);
        p.x * q[0] + p.y * q[1] + p.z * q[2] + p.w * q[3]
    }
}

/// One Sutherland–Hodgman step in f32 against a plane whose distance is
/// `d(pos)`, as llvmpipe's clipper steps (`draw_pipe_clip.c` `do_clip_tri`).
/// An edge leaving through a user plane is a boundary edge (`user`), one
/// leaving through the view volume is not. `false` when a distance is not
/// finite (llvmpipe then drops the primitive).
fn clip_step_f32(
    poly: &[PolyVertex],
    out: &mut Vec<PolyVertex>,
    d: impl Fn(DVec4) -> f32,
    n: usize,
    user: bool,
) -> bool {
    out.clear();
    for i in 0..poly.len() {
        let (p, edge) = poly[i];
        let (q, _) = poly[(i + 1) % poly.len()];
        let (dp, dq) = (d(p.pos), d(q.pos));
        if user && !(dp.is_finite() && dq.is_finite()) {
            return false;
        }
        let (p_in, q_in) = (dp >= 0.0, dq >= 0.0);
        if p_in {
            out.push((p, edge));
        }
        if p_in && !q_in {
            out.push((p.crossing_f32(&q, dp, dq, n), user));
        } else if !p_in && q_in {
            out.push((q.crossing_f32(&p, dq, dp, n), edge));
        }
    }
    true
}

/// Clips `poly` against the user planes in `mask` (after the view volume, in
/// plane order, as llvmpipe); `false` when llvmpipe drops the polygon.
/// `out` is scratch space.
pub fn clip_polygon_user(
    poly: &mut Vec<PolyVertex>,
    out: &mut Vec<PolyVertex>,
    user: &UserPlanes,
    mask: u8,
    n: usize,
) -> bool {
    for i in 0..6 {
        if mask & (1 << i) == 0 || poly.len() < 3 {
            continue;
        }
        if !clip_step_f32(poly, out, |p| user.dist(p, i), n, true) {
            return false;
        }
        std::mem::swap(poly, out);
    }
    true
}

/// A polygon vertex and whether the edge starting at it is a boundary edge.
pub type PolyVertex = (ClipVertex, bool);

/// Clips the polygon `poly` (edge flags per vertex) against the planes set in
/// `planes` at guard scale `g` (Sutherland–Hodgman). Edges made by clipping
/// are not boundary edges. `n` varyings are interpolated; `out` is scratch
/// space (the caller keeps both across primitives: nothing is allocated per
/// primitive once they have grown).
pub fn clip_polygon(poly: &mut Vec<PolyVertex>, out: &mut Vec<PolyVertex>, planes: u8, g: f64, n: usize) {
    let last = g == 1.0;
    let order = if last { FINAL_ORDER } else { GUARD_ORDER };
    for k in order {
        if planes & (1 << k) == 0 || poly.is_empty() {
            continue;
        }
        if last {
            clip_step_f32(poly, out, |p| dist_f32(p, k), n, false);
            std::mem::swap(poly, out);
            continue;
        }
        out.clear();
        for i in 0..poly.len() {
            let (p, edge) = poly[i];
            let (q, _) = poly[(i + 1) % poly.len()];
            {
                let (dp, dq) = (dist(p.pos, k, g), dist(q.pos, k, g));
                let (p_in, q_in) = (dp >= 0.0, dq >= 0.0);
                if p_in {
                    out.push((p, edge));
                }
                if p_in != q_in {
                    out.push((p.crossing(&q, dp, dq, n), !p_in && edge));
                }
            }
        }
        std::mem::swap(poly, out);
    }
}

/// Clips segment `a → b` to the planes in `planes` at guard scale `g`;
/// `None` when nothing is left. The guard bands clip one plane after another
/// in f64; the view volume itself is clipped as llvmpipe clips a line: in f32,
/// each end moved once from the ends `a`, `b` by the largest `t` over the
/// planes it is outside of. `n` varyings are interpolated.
pub fn clip_segment(
    (a, b): (&ClipVertex, &ClipVertex),
    (planes, user): (u8, &UserPlanes),
    g: f64,
    n: usize,
) -> Option<(ClipVertex, ClipVertex)> {
    if g == 1.0 {
        return clip_segment_f32(a, b, (planes, user), n);
    }
    let (mut a, mut b) = (*a, *b);
    for k in GUARD_ORDER {
        if planes & (1 << k) == 0 {
            continue;
        }
        let (da, db) = (dist(a.pos, k, g), dist(b.pos, k, g));
        match (da >= 0.0, db >= 0.0) {
            (false, false) => return None,
            (true, true) => {}
            (false, true) => a = a.crossing(&b, da, db, n),
            (true, false) => b = a.crossing(&b, da, db, n),
        }
    }
    Some((a, b))
}

/// llvmpipe's line clip: `t0`, `t1` the largest `d_out / (d_out − d_in)` of
/// each end over the planes (the view volume's, then the user planes that
/// either end is outside of), the segment gone when `t0 + t1 >= 1`.
fn clip_segment_f32(
    a: &ClipVertex,
    b: &ClipVertex,
    (planes, user): (u8, &UserPlanes),
    n: usize,
) -> Option<(ClipVertex, ClipVertex)> {
    let (mut t0, mut t1) = (0.0f32, 0.0f32);
    let (ua, ub) = (user.code(a.pos), user.code(b.pos));
    let view = FINAL_ORDER.iter().filter(|&&k| planes & (1 << k) != 0);
    let users = (0..6).filter(|&i| (ua | ub) & (1 << i) != 0).map(|i| i + 7);
    for k in view.copied().chain(users) {
        let d = |p| if k < 7 { dist_f32(p, k) } else { user.dist(p, k - 7) };
        let (d0, d1) = (d(a.pos), d(b.pos));
        if d1 < 0.0 {
            t1 = t1.max(d1 / (d1 - d0));
        }
        if d0 < 0.0 {
            t0 = t0.max(d0 / (d0 - d1));
        }
        if t0 + t1 >= 1.0 {
            return None;
        }
    }
    // (In half-z mode with neither end behind `z = 0`, both are inside `z ≥ −w` too.)
    let half_z = planes & (1 << NEAR_HALF_Z) != 0;
    let a2 = if outcode_in(a.pos, 1.0, half_z) != 0 || ua != 0 {
        a.lerp_f32(b, t0, n)
    } else {
        *a
    };
    let b2 = if outcode_in(b.pos, 1.0, half_z) != 0 || ub != 0 {
        b.lerp_f32(a, t1, n)
    } else {
        *b
    };
    Some((a2, b2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outcode_f32_equals_outcode_in_f64() {
        let vals = [
            0.0f32,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1e-45,
            -1e-45,
            1e-30,
            -1e-30,
            3.4028235e38,
            -3.4028235e38,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            1.0 + f32::EPSILON,
            -(1.0 + f32::EPSILON),
        ];
        let mut seed = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            f32::from_bits((seed >> 16) as u32)
        };
        let check = |p: glam::Vec4| assert_eq!(outcode_f32(p), outcode(p.as_dvec4(), 1.0), "{p:?}");
        for &x in &vals {
            for &y in &vals {
                for &z in &vals {
                    for &w in &vals {
                        check(glam::Vec4::new(x, y, z, w));
                    }
                }
            }
        }
        for _ in 0..1_000_000 {
            let w = next();
            let p = glam::Vec4::new(next(), -w * (1.0 + next().clamp(-1e-6, 1e-6)), next(), w);
            check(p);
        }
    }
}
