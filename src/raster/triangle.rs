//! Triangles: exact fixed-point edge functions, one span interval per row.

use super::{
    ceil_div, color_to_unorm8, emit_row, floor_div, shade_unorm8, shade_varyings, snap, RasterParams, RasterVertex,
    SpanSink, ONE,
};
use crate::geometry::varying::{VaryingLayout, Varyings};
use softgl_jit::{DepthFormat, FogMode, FogUniforms, FragmentSpan};

/// `a * b + c` rounded once, as an FMA instruction gives it: the f32 product
/// is exact in f64, and the f64 sum rounds to f32 (a second rounding that can
/// differ from a true FMA only on rare ties), without needing FMA hardware.
#[inline]
fn fma32(a: f32, b: f32, c: f32) -> f32 {
    (f64::from(a) * f64::from(b) + f64::from(c)) as f32
}

/// An attribute plane in llvmpipe's frame: x right, y down from the top row,
/// evaluated at integer pixel coordinates for the pixel centers.
#[derive(Clone, Copy, Debug)]
struct Plane {
    a0: f32,
    dadx: f32,
    dady: f32,
}

impl Plane {
    #[inline]
    fn at(&self, px: f32, row: f32) -> f32 {
        fma32(self.dady, row, fma32(self.dadx, px, self.a0))
    }
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
pub fn triangle(v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams, sink: &mut dyn SpanSink) {
    let mut p = v.map(|v| (snap(v.x), snap(v.y)));
    let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1);
    if area == 0 || params.bounds.is_empty() {
        return;
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

    let shade = Shading::new(v, flat, params);
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
    /// Planes of r/w, g/w, b/w, a/w and 1/w.
    color: Option<([Plane; 4], Plane)>,
    /// The colour of every fragment, when nothing varies (flat shading, no fog).
    flat: Option<[u8; 4]>,
    /// The provoking vertex's varyings, for flat shading with fog.
    flat_v: Option<Varyings>,
    /// Planes of the secondary colour's r/w, g/w, b/w (colour sum).
    secondary: Option<[Plane; 3]>,
    /// Plane of the fog coordinate over w, with the fog mode and values.
    fog: Option<(Plane, (FogMode, FogUniforms))>,
    /// 1/w, when a varying is interpolated.
    inv_w: Plane,
    layout: VaryingLayout,
    depth: Option<(Plane, DepthFormat)>,
    /// Framebuffer height, to turn window rows into llvmpipe's top-down rows.
    height: u32,
}

impl Shading {
    fn new(v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) -> Shading {
        // llvmpipe orders the vertices by the sign of the snapped area in its
        // y-down frame, and swaps the first two when it is negative.
        let mut v = v;
        let q = v.map(|v| (snap(v.x), snap(v.y_down)));
        let area = (q[0].0 - q[1].0) * (q[2].1 - q[0].1) - (q[2].0 - q[0].0) * (q[0].1 - q[1].1);
        if area < 0 {
            v.swap(0, 1);
        }
        let setup = Setup::new(v.map(|v| (v.x, v.y_down)));
        let layout = params.layout;
        let over_w = |k: usize| setup.plane(v.map(|v| v.v[k] * v.inv_w));
        let inv_w = setup.plane(v.map(|v| v.inv_w));
        let color = layout
            .color()
            .filter(|_| flat.is_none())
            .map(|o| ([0, 1, 2, 3].map(|c| over_w(o + c)), inv_w));
        let secondary = layout
            .secondary()
            .filter(|_| flat.is_none())
            .map(|o| [0, 1, 2].map(|c| over_w(o + c)));
        let fog = layout
            .color()
            .and(layout.fog())
            .zip(params.fog)
            .map(|(o, f)| (over_w(o), f));
        let depth = params.depth.map(|f| {
            let mut z = v.map(|v| v.z as f32);
            if let Some((factor, units)) = params.offset {
                let slope = setup.plane(z);
                let o = offset(factor, units, slope.dadx, slope.dady, f);
                z = z.map(|z| (z + o).clamp(0.0, 1.0));
            }
            (setup.plane(z), f)
        });
        let flat_params = RasterParams { fog: None, ..*params };
        Shading {
            color,
            flat: flat
                .filter(|_| fog.is_none() && layout.color)
                .map(|f| shade_varyings(f, &flat_params)),
            flat_v: flat.filter(|_| fog.is_some()).copied(),
            secondary,
            fog,
            inv_w,
            layout,
            depth,
            height: params.height,
        }
    }

    #[inline]
    fn shade(&self, x: u32, y: u32, span: &mut FragmentSpan, i: usize) {
        let (px, row) = (x as f32, self.height.saturating_sub(y + 1) as f32);
        let rgba = if let Some(c) = self.flat {
            Some(c)
        } else if self.fog.is_none() && self.secondary.is_none() {
            self.color.as_ref().map(|(planes, iw)| {
                let w = 1.0 / iw.at(px, row);
                planes.map(|p| color_to_unorm8(p.at(px, row) * w))
            })
        } else {
            self.shade_stages(px, row)
        };
        if let Some(c) = rgba {
            span.r[i] = c[0];
            span.g[i] = c[1];
            span.b[i] = c[2];
            span.a[i] = c[3];
        }
        if let Some((plane, f)) = &self.depth {
            span.z[i] = crate::framebuffer::depth_to_unorm(f64::from(plane.at(px, row)), *f);
        }
    }

    /// The colour through the colour sum and fog.
    fn shade_stages(&self, px: f32, row: f32) -> Option<[u8; 4]> {
        let w = 1.0 / self.inv_w.at(px, row);
        let fog = self.fog.as_ref().map(|(p, f)| (p.at(px, row) * w, f));
        if let Some(f) = &self.flat_v {
            let o = self.layout.color()?;
            let secondary = self.layout.secondary().map(|s| [f[s], f[s + 1], f[s + 2]]);
            return Some(shade_unorm8([f[o], f[o + 1], f[o + 2], f[o + 3]], secondary, fog));
        }
        let (planes, _) = self.color.as_ref()?;
        let primary = planes.map(|p| p.at(px, row) * w);
        let secondary = self.secondary.map(|s| s.map(|p| p.at(px, row) * w));
        Some(shade_unorm8(primary, secondary, fog))
    }
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
