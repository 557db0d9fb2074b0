//! Homogeneous clipping, before any division: against the near and far planes
//! and against a guard band in x and y (the rasterizer then bounds fragments to
//! the viewport, which is exact clipping without new vertices on the sides).

use glam::Vec4;

/// A vertex in clip space with the attributes clipping interpolates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    pub pos: Vec4,
    pub color: Vec4,
}

impl ClipVertex {
    pub fn is_finite(&self) -> bool {
        self.pos.is_finite() && self.color.is_finite()
    }

    fn lerp(&self, o: &ClipVertex, t: f64) -> ClipVertex {
        let l = |a: Vec4, b: Vec4| (a.as_dvec4() + (b.as_dvec4() - a.as_dvec4()) * t).as_vec4();
        ClipVertex {
            pos: l(self.pos, o.pos),
            color: l(self.color, o.color),
        }
    }
}

/// Signed distance of `p` to clip plane `k` (inside when `>= 0`): near, far,
/// then left, right, bottom, top scaled by `g` (1 for the view volume itself).
#[inline]
fn dist(p: Vec4, k: usize, g: f64) -> f64 {
    let (x, y, z, w) = (f64::from(p.x), f64::from(p.y), f64::from(p.z), f64::from(p.w));
    match k {
        0 => w + z,
        1 => w - z,
        2 => g * w + x,
        3 => g * w - x,
        4 => g * w + y,
        _ => g * w - y,
    }
}

/// Bit `k` set when `p` is outside plane `k` at guard scale `g`.
pub fn outcode(p: Vec4, g: f64) -> u8 {
    (0..6).fold(0, |code, k| if dist(p, k, g) < 0.0 { code | (1 << k) } else { code })
}

/// A polygon vertex and whether the edge starting at it is a boundary edge.
pub type PolyVertex = (ClipVertex, bool);

/// Clips the polygon `poly` (edge flags per vertex) against the planes set in
/// `planes` at guard scale `g` (Sutherland–Hodgman). Edges made by clipping
/// are not boundary edges.
pub fn clip_polygon(poly: &mut Vec<PolyVertex>, planes: u8, g: f64) {
    let mut out: Vec<PolyVertex> = Vec::with_capacity(poly.len() + 6);
    for k in 0..6 {
        if planes & (1 << k) == 0 || poly.is_empty() {
            continue;
        }
        out.clear();
        for i in 0..poly.len() {
            let (p, edge) = poly[i];
            let (q, _) = poly[(i + 1) % poly.len()];
            let (dp, dq) = (dist(p.pos, k, g), dist(q.pos, k, g));
            let (p_in, q_in) = (dp >= 0.0, dq >= 0.0);
            if p_in {
                out.push((p, edge));
            }
            if p_in != q_in {
                let t = dp / (dp - dq);
                out.push((p.lerp(&q, t), !p_in && edge));
            }
        }
        std::mem::swap(poly, &mut out);
    }
}

/// Clips segment `a → b` to the planes in `planes` at guard scale `g`
/// (Liang–Barsky); `None` when nothing is left.
pub fn clip_segment(a: &ClipVertex, b: &ClipVertex, planes: u8, g: f64) -> Option<(ClipVertex, ClipVertex)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for k in 0..6 {
        if planes & (1 << k) == 0 {
            continue;
        }
        let (da, db) = (dist(a.pos, k, g), dist(b.pos, k, g));
        if da < 0.0 && db < 0.0 {
            return None;
        }
        if da < 0.0 {
            t0 = t0.max(da / (da - db));
        } else if db < 0.0 {
            t1 = t1.min(da / (da - db));
        }
    }
    (t0 <= t1).then(|| (a.lerp(b, t0), a.lerp(b, t1)))
}
