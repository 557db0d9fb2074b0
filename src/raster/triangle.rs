//! Triangles: exact fixed-point edge functions, one span interval per row.

use super::{ceil_div, color_to_unorm8, emit_row, floor_div, snap, RasterParams, RasterVertex, SpanSink, ONE};
use softgl_jit::FragmentSpan;

/// An attribute plane `a(x, y) = a0 + ax * (x - x0) + ay * (y - y0)`, in pixels.
#[derive(Clone, Copy, Debug)]
struct Plane {
    a0: f64,
    ax: f64,
    ay: f64,
}

impl Plane {
    fn new(p: [(f64, f64); 3], a: [f64; 3]) -> Plane {
        let (x10, y10) = (p[1].0 - p[0].0, p[1].1 - p[0].1);
        let (x20, y20) = (p[2].0 - p[0].0, p[2].1 - p[0].1);
        let det = x10 * y20 - x20 * y10;
        let (a10, a20) = (a[1] - a[0], a[2] - a[0]);
        let ax = (a10 * y20 - a20 * y10) / det;
        let ay = (a20 * x10 - a10 * x20) / det;
        // Re-anchor at the origin so evaluation is one multiply-add per axis.
        Plane {
            a0: a[0] - ax * p[0].0 - ay * p[0].1,
            ax,
            ay,
        }
    }

    #[inline]
    fn at(&self, x: f64, y: f64) -> f64 {
        self.a0 + self.ax * x + self.ay * y
    }
}

/// Rasterizes a triangle, either winding. `flat` replaces the interpolated color.
pub fn triangle(v: [&RasterVertex; 3], flat: Option<[f32; 4]>, params: &RasterParams, sink: &mut dyn SpanSink) {
    let mut p = v.map(|v| (snap(v.x), snap(v.y)));
    let mut v = v;
    let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    if area == 0 || params.bounds.is_empty() {
        return;
    }
    if area < 0 {
        p.swap(1, 2);
        v.swap(1, 2);
    }

    // Edge i runs from p[i] to p[i+1]; with counter-clockwise order the inside
    // is on its left. A center exactly on an edge is inside when the edge is a
    // left edge (going down) or a bottom edge (horizontal, going right).
    let edges = [0, 1, 2].map(|i| {
        let (a, b) = (p[i], p[(i + 1) % 3]);
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let owns = dy < 0 || (dy == 0 && dx > 0);
        (a, dx, dy, if owns { 0 } else { 1 })
    });

    let (min_x, max_x) = (
        p.iter().map(|q| q.0).min().unwrap_or(0),
        p.iter().map(|q| q.0).max().unwrap_or(0),
    );
    let (min_y, max_y) = (
        p.iter().map(|q| q.1).min().unwrap_or(0),
        p.iter().map(|q| q.1).max().unwrap_or(0),
    );
    let b = params.bounds;
    let px0 = ceil_div(min_x, ONE).max(i64::from(b.x0));
    let px1 = floor_div(max_x, ONE).min(i64::from(b.x1) - 1);
    let py0 = ceil_div(min_y, ONE).max(i64::from(b.y0));
    let py1 = floor_div(max_y, ONE).min(i64::from(b.y1) - 1);
    if px0 > px1 || py0 > py1 {
        return;
    }

    let shade = Shading::new(&p, &v, flat, params);
    let mut span = FragmentSpan::new(0, 0);
    for py in py0..=py1 {
        let sy = py * ONE;
        let (mut lo, mut hi) = (px0, px1);
        for &((ax, ay), dx, dy, k) in &edges {
            // E(px) = dx * (sy - ay) - dy * (px * ONE - ax) must be >= k.
            let c = dx * (sy - ay) + dy * ax;
            let m = dy * ONE;
            if m == 0 {
                if c < k {
                    lo = 1;
                    hi = 0;
                }
            } else if m > 0 {
                hi = hi.min(floor_div(c - k, m));
            } else {
                lo = lo.max(ceil_div(k - c, -m));
            }
        }
        if lo > hi {
            continue;
        }
        emit_row(sink, &mut span, py as u32, lo as u32, hi as u32, |x, s, i| {
            shade.shade(x, py as u32, s, i)
        });
    }
}

/// Per-fragment attribute evaluation for one triangle.
struct Shading {
    /// Planes of r, g, b, a (divided by w when perspective-correct) and 1/w.
    color: Option<([Plane; 4], Option<Plane>)>,
    flat: Option<[u8; 4]>,
    depth: Option<(Plane, softgl_jit::DepthFormat)>,
}

impl Shading {
    fn new(p: &[(i64, i64); 3], v: &[&RasterVertex; 3], flat: Option<[f32; 4]>, params: &RasterParams) -> Shading {
        // Snapped positions in pixels, in the grid where centers are integers.
        let pos = p.map(|(x, y)| (x as f64 / ONE as f64, y as f64 / ONE as f64));
        let color = match (params.color, flat) {
            (false, _) | (true, Some(_)) => None,
            (true, None) => {
                let iw = v.map(|v| f64::from(v.inv_w));
                let affine = iw[0] == iw[1] && iw[1] == iw[2];
                let planes = [0, 1, 2, 3].map(|c| {
                    let a = [0, 1, 2].map(|k| {
                        let val = f64::from(v[k].color[c]);
                        if affine {
                            val
                        } else {
                            val * iw[k]
                        }
                    });
                    Plane::new(pos, a)
                });
                Some((planes, (!affine).then(|| Plane::new(pos, iw))))
            }
        };
        let depth = params.depth.map(|f| {
            let mut plane = Plane::new(pos, v.map(|v| v.z));
            if let Some((factor, units)) = params.offset {
                let slope = plane.ax.abs().max(plane.ay.abs());
                let r = 1.0 / f64::from(f.max_value());
                let o = f64::from(factor) * slope + f64::from(units) * r;
                if o.is_finite() {
                    plane.a0 += o;
                }
            }
            (plane, f)
        });
        Shading {
            color,
            flat: flat.filter(|_| params.color).map(|c| c.map(color_to_unorm8)),
            depth,
        }
    }

    #[inline]
    fn shade(&self, x: u32, y: u32, span: &mut FragmentSpan, i: usize) {
        let (fx, fy) = (f64::from(x), f64::from(y));
        if let Some(c) = self.flat {
            span.r[i] = c[0];
            span.g[i] = c[1];
            span.b[i] = c[2];
            span.a[i] = c[3];
        } else if let Some((planes, iw)) = &self.color {
            let scale = iw.as_ref().map_or(1.0, |p| 1.0 / p.at(fx, fy));
            let ch = |k: usize| color_to_unorm8((planes[k].at(fx, fy) * scale) as f32);
            span.r[i] = ch(0);
            span.g[i] = ch(1);
            span.b[i] = ch(2);
            span.a[i] = ch(3);
        }
        if let Some((plane, f)) = &self.depth {
            span.z[i] = crate::framebuffer::depth_to_unorm(plane.at(fx, fy), *f);
        }
    }
}
