//! The geometry pipeline of one draw: transform, primitive assembly, clip
//! codes with trivial accept/reject, homogeneous clipping, perspective divide,
//! viewport transform, facing and culling, polygon mode, then rasterization.
//!
//! Two paths for a primitive. The batch ([`batch::VertexBatch`]) classifies
//! and projects each vertex once, as it transforms it; a primitive whose
//! vertices are all finite and inside the view volume and the user planes
//! (nothing to clip at any guard level) is culled from those window
//! positions and handed to the sink by reference, with no vertex copied
//! (`Geometry::triangle`). Any other goes through clipping
//! (`Geometry::polygon`), which copies its vertices into scratch buffers
//! kept for the whole draw (nothing allocated per primitive). Both compute
//! the same bits: the fast path is the general one with its no-op steps left
//! out. Measured on the lit16 frame (1.6 M triangles, callgrind): 5843
//! instructions a triangle with two vectors and six vertex copies per
//! triangle, 3379 with the fast path (the front end's share, all but the
//! sink's binning and rasterizing, from about 3100 to about 640).

pub mod assemble;
pub mod batch;
pub mod clip;
pub mod fma;
pub mod lighting;
pub mod varying;

use crate::framebuffer::{Framebuffer, Rect};
use crate::raster::{self, PrimSink, RasterParams, RasterVertex};
use crate::state::{FrontFace, PolygonMode, RasterState, ShadeModel};
use assemble::{assemble, Primitive, QuadSplit};
use batch::{VertexBatch, VertexStage};
use clip::{
    clip_polygon, clip_polygon_user, clip_segment, guard_levels, outcode_in, ClipVertex, PolyVertex, UserPlanes,
};
use glam::{Vec3, Vec4};
use varying::{copy_slots, VaryingLayout, Varyings};

pub use crate::state::PrimitiveMode;

/// The `k`th edge (or vertex) of an `n`-gon drawn as lines or points in
/// the order Mesa's draw module makes them (what feedback records):
/// its unfilled stage draws a triangle's edges as v2-v0, v0-v1, v1-v2 and
/// its points as v0, v1, v2 (`draw_pipe_unfilled.c`); a clipped polygon
/// reaches it as a fan `(v[i-1], v[i], v[0])` whose edge flags leave its
/// edges in order from v0 and its points as v1, v0, v2, … (v1, v2, v0 for a
/// triangle) (`emit_poly`, `draw_pipe_clip.c`).
fn unfilled_order(mode: PolygonMode, clipped: bool, n: usize, k: usize) -> usize {
    match (mode, clipped) {
        (PolygonMode::Line, false) => (k + 2) % 3,
        (PolygonMode::Point, true) if n == 3 => (k + 1) % 3,
        (PolygonMode::Point, true) if k < 2 => 1 - k,
        _ => k,
    }
}

/// The largest viewport side (`GL_MAX_VIEWPORT_DIMS`, as Mesa reports it).
pub const MAX_VIEWPORT: i32 = 16384;

/// A vertex as the API hands it over: object position and the current (or
/// array) values of its other attributes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InVertex {
    pub pos: Vec4,
    pub color: Vec4,
    /// `glSecondaryColor` (alpha 0, unused).
    pub secondary: Vec4,
    /// `glFogCoord`.
    pub fog_coord: f32,
    pub normal: Vec3,
    /// `glEdgeFlag`: whether the polygon edge starting here is a boundary
    /// edge, drawn under polygon mode `Line`/`Point`.
    pub edge: bool,
    /// Which of the draw's per-vertex materials lights this vertex
    /// ([`batch::VertexStage::vertex_materials`]); 0 when they do not vary.
    /// (Texture coordinates are not here: a draw fetches them apart, for
    /// the units it samples only, [`batch::TexFetch`].)
    pub material: u16,
}

impl InVertex {
    /// A vertex at `pos` with `color` and GL's initial values for the rest.
    pub fn new(pos: Vec4, color: Vec4) -> InVertex {
        InVertex {
            pos,
            color,
            secondary: Vec4::new(0.0, 0.0, 0.0, 1.0),
            fog_coord: 0.0,
            normal: Vec3::Z,
            edge: true,
            material: 0,
        }
    }
}

/// Where a draw's vertices come from.
#[derive(Clone, Copy)]
pub enum Vertices<'a> {
    /// Vertex `i` is `v[i]` (`glBegin`/`glEnd`), read in place: no call
    /// and no copy of the vertex.
    Slice(&'a [InVertex]),
    /// `f(i)` makes vertex `i` (vertex arrays).
    Fetch(&'a dyn Fn(usize) -> InVertex),
}

impl Vertices<'_> {
    /// The object position of vertex `i`.
    #[inline]
    fn pos(&self, i: usize) -> Vec4 {
        match self {
            Vertices::Slice(v) => v[i].pos,
            Vertices::Fetch(f) => f(i).pos,
        }
    }
}

/// How a draw hands its vertices over, as far as llvmpipe's quad split
/// depends on it (`docs/llvmpipe-facts.md` §12).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawSource {
    /// `glBegin`/`glEnd` or `glDrawArrays`; `per_vertex_color` says whether
    /// the colour varies per vertex (`glColor` between `begin` and `end`, or
    /// a colour array) rather than being the current colour.
    Arrays { per_vertex_color: bool },
    /// `glDrawElements`.
    Elements,
}

/// Twice the signed area of the polygon of the `n` points `point(i)`, in f64
/// (y up: positive is counter-clockwise).
#[inline]
fn signed_area(n: usize, point: impl Fn(usize) -> (f32, f32)) -> f64 {
    (0..n)
        .map(|i| {
            let (p, q) = (point(i), point((i + 1) % n));
            f64::from(p.0) * f64::from(q.1) - f64::from(q.0) * f64::from(p.1)
        })
        .sum()
}

/// What the clipping path reuses from one primitive to the next.
#[derive(Default)]
struct Scratch {
    /// The polygon being clipped.
    clipped: Vec<PolyVertex>,
    /// The output of a clipping step.
    out: Vec<PolyVertex>,
    /// The clipped polygon in window coordinates, with its edge flags.
    win: Vec<(RasterVertex, bool)>,
}

/// The pixels inside both `a` and `b`.
fn intersect(a: Rect, b: Rect) -> Rect {
    a.intersect(b)
}

/// The viewport transform, in f32 as llvmpipe computes it.
#[derive(Clone, Copy, Debug)]
struct Viewport {
    scale: [f32; 3],
    translate: [f32; 3],
    /// Scale and translate of y in llvmpipe's top-down frame.
    flipped_y: (f32, f32),
    /// `scale`, `translate` (x, y, z) and `flipped_y` widened to f64 for
    /// [`fma::fma_wide`], once a draw.
    wide: [(f64, f64); 4],
    /// Whether each of those scales is a power of two ([`fma::fma_by_pow2`]).
    pow2: [bool; 4],
    /// All four are: a vertex of the draw is then mapped by
    /// [`Viewport::map_pow2`], the four coordinates at once.
    all_pow2: bool,
    /// The scales and translates of x, y, `flipped_y` and z, in that order
    /// (the lanes of [`Viewport::map_pow2`]).
    scale4: Vec4,
    translate4: Vec4,
}

impl Viewport {
    /// `fma(c·(1/w), scale, translate)` of x, y, `flipped_y` and z (the
    /// lanes) when every scale is a power of two, as four
    /// [`fma::fma_by_pow2`] compute it, in one multiply and one add of
    /// the four lanes: the same f32 operations on each (`c·(1/w)`, its
    /// product by the scale, exact when normal, plus the translate).
    /// `None` when a product is not normal (zero, tiny, huge, NaN): the
    /// caller then takes the scalar path, which handles those. Measured
    /// on lit16 (callgrind, one thread, two frames): the batch's refill
    /// from 655 M to 573 M instructions, 26 fewer a vertex.
    #[inline(always)]
    fn map_pow2(&self, p: Vec4, inv_w: f32) -> Option<Vec4> {
        let prod = Vec4::new(p.x, p.y, p.y, p.z) * inv_w * self.scale4;
        let a = prod.abs();
        let normal = a.cmpge(Vec4::splat(f32::MIN_POSITIVE)) & a.cmplt(Vec4::splat(f32::INFINITY));
        normal.all().then(|| prod + self.translate4)
    }

    /// `fma(q, s, t)` for the scale and translate `s`, `t` of coordinate
    /// `k` (x, y, z, then `flipped_y`), through [`fma::fma_by_pow2`] when
    /// the scale is a power of two.
    #[inline(always)]
    fn fused(&self, q: f32, k: usize, s: f32, t: f32) -> f32 {
        if self.pow2[k] {
            fma::fma_by_pow2(q, s, t, self.wide[k])
        } else {
            fma::fma_wide(q, self.wide[k].0, self.wide[k].1)
        }
    }
}

/// Per-draw constants of the geometry pipeline.
pub struct Geometry<'s> {
    /// Select or feedback mode: the sink records, nothing is rasterized. It
    /// hears of line stipple resets ([`PrimSink::reset_stipple`]: feedback's
    /// `GL_LINE_RESET_TOKEN`) where Mesa's draw module makes them:
    /// only its unfilled stage passes them on, one a triangle drawn as lines
    /// (`draw_pipe_unfilled.c`; line primitives' resets stop at its stipple stage).
    pub recording: bool,
    state: &'s RasterState,
    viewport: Viewport,
    /// `glClipControl`: the near plane is `z ≥ 0` (`GL_ZERO_TO_ONE`).
    half_z: bool,
    /// `glClipControl`: `GL_UPPER_LEFT` (window winding reversed, facing with it).
    upper_left: bool,
    /// Triangles: clipped to the view volume, and bounded by the viewport.
    params: RasterParams,
    /// `params` with the polygon offset of filled faces, if enabled.
    fill_params: RasterParams,
    /// Points and lines: clipped to the view volume, their width may reach
    /// past the viewport up to the framebuffer's edges, as in llvmpipe.
    wide_params: RasterParams,
    /// The varyings every vertex carries.
    layout: VaryingLayout,
    /// The enabled user clip planes, in clip coordinates.
    user: UserPlanes,
    /// `layout.finite_len()`, asked at every vertex.
    finite_len: usize,
    /// `layout.fog()`, asked at every lit vertex.
    fog_slot: Option<usize>,
    /// Row 2 of the inverse projection (a vertex's eye z from its clip
    /// position), when points are attenuated (`PointParams`).
    point_eye_z: Option<glam::Vec4>,
}

impl<'s> Geometry<'s> {
    /// Sets up a draw into `fb` with `state`; `depth` says whether any
    /// fragment stage reads depth, `layout` which varyings are carried.
    pub fn new(state: &'s RasterState, fb: &Framebuffer, depth: bool, layout: VaryingLayout) -> Geometry<'s> {
        let (vp, sc) = (state.viewport, state.scissor);
        let (vw, vh) = (vp.width.min(MAX_VIEWPORT), vp.height.min(MAX_VIEWPORT));
        // (`glClipControl`: the z mapping and the sign of y's scale, `crate::clip_control`.)
        let (z_scale, z_translate) = state.clip_control.depth_xform(state.depth_range);
        let y_scale = state.clip_control.y_scale(vh as f32);
        let viewport = Viewport {
            scale: [vw as f32 / 2.0, y_scale, z_scale],
            translate: [
                vp.x as f32 + vw as f32 / 2.0,
                vp.y as f32 + vh as f32 / 2.0,
                z_translate,
            ],
            flipped_y: (-y_scale, (fb.height() as f32 - vp.y as f32) - vh as f32 / 2.0),
            wide: [(0.0, 0.0); 4],
            pow2: [false; 4],
            all_pow2: false,
            scale4: Vec4::ZERO,
            translate4: Vec4::ZERO,
        };
        let viewport = Viewport {
            wide: [
                (viewport.scale[0].into(), viewport.translate[0].into()),
                (viewport.scale[1].into(), viewport.translate[1].into()),
                (viewport.scale[2].into(), viewport.translate[2].into()),
                (viewport.flipped_y.0.into(), viewport.flipped_y.1.into()),
            ],
            pow2: [
                viewport.scale[0],
                viewport.scale[1],
                viewport.scale[2],
                viewport.flipped_y.0,
            ]
            .map(fma::is_pow2),
            ..viewport
        };
        let viewport = Viewport {
            all_pow2: viewport.pow2.iter().all(|&p| p),
            scale4: Vec4::new(
                viewport.scale[0],
                viewport.scale[1],
                viewport.flipped_y.0,
                viewport.scale[2],
            ),
            translate4: Vec4::new(
                viewport.translate[0],
                viewport.translate[1],
                viewport.flipped_y.1,
                viewport.translate[2],
            ),
            ..viewport
        };
        // With the scissor test on, rows and columns outside the box are not
        // rasterized at all (its fragments would all be discarded): piglit's
        // gl-1.0-scissor-many (a 1-pixel box per pixel) went from 18 s to 0.35 s.
        let fb_rect = match state.scissor_test {
            true => intersect(
                fb.bounds(),
                fb.clip_rect(sc.x.into(), sc.y.into(), sc.width.into(), sc.height.into()),
            ),
            false => fb.bounds(),
        };
        let vp_rect = fb.clip_rect(i64::from(vp.x), i64::from(vp.y), i64::from(vw), i64::from(vh));
        let bounds = intersect(fb_rect, vp_rect);
        let depth_format = fb.depth_format().filter(|_| depth);
        let params = RasterParams {
            bounds,
            height: fb.height(),
            depth: depth_format,
            layout,
            offset: None,
        };
        let wide_params = RasterParams {
            bounds: fb_rect,
            ..params
        };
        let fill_offset = state.offset_fill.then_some((state.offset_factor, state.offset_units));
        Geometry {
            recording: false,
            state,
            viewport,
            half_z: state.clip_control.half_z(),
            upper_left: state.clip_control.upper_left(),
            params,
            fill_params: RasterParams {
                offset: fill_offset,
                ..params
            },
            wide_params,
            layout,
            user: UserPlanes::default(),
            finite_len: layout.finite_len(),
            fog_slot: layout.fog(),
            point_eye_z: None,
        }
    }

    /// Enables the user clip planes of the state for this draw: each eye
    /// plane times the inverse `projection` (Mesa's `_ClipUserPlane`,
    /// `main/clip.c`), in f32.
    /// Prepares the point sizes of attenuated points (GL 1.4), which need
    /// each vertex's eye depth: found from its clip position through the
    /// inverse of `projection`.
    pub fn set_point_projection(&mut self, projection: &glam::Mat4) {
        if self.state.point_params.attenuated() {
            self.point_eye_z = Some(crate::inverse::inverse(projection).row(2));
        }
    }

    /// The size of a point whose vertex is at clip position `clip`.
    fn point_size_at(&self, clip: glam::Vec4) -> f32 {
        let z_eye = self.point_eye_z.map_or(0.0, |r| r.dot(clip));
        self.state.point_params.size(self.state.point_size, z_eye)
    }

    pub fn set_user_planes(&mut self, projection: &glam::Mat4) {
        let l = &self.state.lighting;
        if !l.clipping() {
            return;
        }
        let inv = crate::inverse::inverse(projection).to_cols_array();
        for i in 0..6 {
            if !l.clip_enabled[i] {
                continue;
            }
            let e = l.clip_planes[i].map(|c| c as f32);
            self.user.planes[i] = [0, 1, 2, 3].map(|j| {
                let c = &inv[4 * j..4 * j + 4];
                e[0] * c[0] + e[1] * c[1] + e[2] * c[2] + e[3] * c[3]
            });
            self.user.enabled |= 1 << i;
        }
    }

    /// Draws `count` vertices, `fetch` giving them, as `mode` into
    /// `sink`, running `stage` over them in batches in `window` (kept by
    /// the caller from draw to draw).
    pub fn draw(
        &self,
        stage: &VertexStage,
        (mode, source): (PrimitiveMode, DrawSource),
        count: usize,
        fetch: Vertices,
        sink: &mut dyn PrimSink,
        window: &mut batch::Window,
    ) {
        if self.params.bounds.is_empty() && !self.recording {
            return;
        }
        let mut batch = VertexBatch::new(stage, self, count, fetch, window);
        let quads = if mode == PrimitiveMode::Quads && self.quads_split_v1_v3(&mut batch, source) {
            QuadSplit::Pipeline
        } else {
            QuadSplit::Direct
        };
        let unfilled = self.unfilled();
        // The provoking vertex's varyings go with a primitive under flat
        // shading or with uniform colours (the rasterizer takes its colours
        // from them), borrowed from the batch.
        let flat_shaded = self.state.shade_model == ShadeModel::Flat || self.layout.uniform_colors;
        let mut scratch = Scratch::default();
        if mode == PrimitiveMode::QuadStrip {
            // The quads of a strip as `assemble` makes them, in a loop of
            // their own: each triangle inlined, not a call of the closure
            // below through `assemble`. Measured on lit16 (1 thread): 7
            // instructions a triangle fewer (callgrind), and the samples
            // in the assembly loop (perf) from about 740 to 555 a run.
            for q in (0..count.saturating_sub(3)).step_by(2) {
                let [v0, v1, v2, v3] = [q, q + 1, q + 2, q + 3];
                // Boundary in polygon order v0 v1 v3 v2.
                // (Two calls, not a loop over the two: the loop's array of
                // indices went through the stack, its reads stalling.)
                let (u, f) = (unfilled, flat_shaded);
                self.batch_triangle(
                    &mut batch,
                    ([v0, v1, v3], v3, [true, true, false]),
                    (u, f),
                    &mut scratch,
                    sink,
                );
                self.batch_triangle(
                    &mut batch,
                    ([v0, v3, v2], v3, [false, true, true]),
                    (u, f),
                    &mut scratch,
                    sink,
                );
            }
            batch.finish(window);
            return;
        }
        assemble(mode, count, quads, |prim| match prim {
            Primitive::Point(i) => {
                batch.load(i);
                batch.light_pending(&[i]);
                let v = batch.vertex(i);
                if v.inside {
                    sink.point(&v.win, self.point_size_at(v.pos), &self.wide_params);
                }
            }
            Primitive::Line { a, b, provoking } => {
                batch.load(a.max(b).max(provoking));
                batch.light_pending(&[a, b, provoking]);
                let (va, vb) = (batch.vertex(a), batch.vertex(b));
                let flat = flat_shaded.then(|| &batch.vertex(provoking).win.v);
                if va.inside && vb.inside {
                    // Nothing to clip at any guard level, both ends mapped as
                    // vertices of the draw: what `line` computes for them.
                    sink.line(&va.win, &vb.win, self.state.line_width, flat, &self.wide_params);
                } else {
                    self.line(&va.clip(), &vb.clip(), flat.copied(), sink)
                }
            }
            Primitive::Triangle { v, provoking, edges } => self.batch_triangle(
                &mut batch,
                (v, provoking, edges),
                (unfilled, flat_shaded),
                &mut scratch,
                sink,
            ),
        });
        batch.finish(window);
    }

    /// Triangle `v` of the draw (`provoking`, boundary `edges`) from the
    /// batch: borrowed as it is when it needs no clipping and is filled,
    /// else trivially rejected or clipped ([`Self::polygon`]).
    #[inline(always)]
    fn batch_triangle(
        &self,
        batch: &mut VertexBatch,
        (v, provoking, edges): ([usize; 3], usize, [bool; 3]),
        (unfilled, flat_shaded): (bool, bool),
        scratch: &mut Scratch,
        sink: &mut dyn PrimSink,
    ) {
        batch.load(v[0].max(v[1]).max(v[2]).max(provoking));
        let [a, b, c] = v.map(|i| batch.vertex(i));
        let direct = !unfilled && a.inside && b.inside && c.inside;
        if !direct {
            // Trivially rejected (what `polygon` checks first) before
            // copying the vertices: a culled glBegin/glEnd quad.
            let codes = a.codes.0 & b.codes.0 & c.codes.0;
            let user = a.codes.1 & b.codes.1 & c.codes.1;
            if !(a.finite && b.finite && c.finite) || codes != 0 || user != 0 {
                return;
            }
        }
        // Lit now that the triangle is drawn (a rejected one needs no colour).
        if a.pending || b.pending || c.pending || batch.vertex(provoking).pending {
            batch.light_pending(&[v[0], v[1], v[2], provoking]);
        }
        let [a, b, c] = v.map(|i| batch.vertex(i));
        let flat = flat_shaded.then(|| &batch.vertex(provoking).win.v);
        if direct {
            self.triangle([&a.win, &b.win, &c.win], flat, sink);
        } else {
            // A vertex's edge flag ANDs with the assembly's boundary flag
            // for every triangle mode, as llvmpipe's unfilled stage does
            // (docs/llvmpipe-facts.md, "Edge flags").
            let vs = [a, b, c];
            let poly = [0, 1, 2].map(|k| (vs[k].clip(), edges[k] && (!unfilled || vs[k].edge)));
            self.polygon(poly, flat.copied(), scratch, sink)
        }
    }

    /// Classifies a transformed vertex (its position and varyings set):
    /// its codes, whether it is finite, and whether it is inside the view
    /// volume and the user planes and mapped to finite window coordinates,
    /// which are then written into `v.win` (as `project_as(v, true)` maps them).
    #[inline]
    fn classify(&self, v: &mut batch::BatchVertex) {
        // Every slot tested (no early exit): a branch-free loop.
        let finite = v.win.v[..self.finite_len].iter().fold(true, |ok, c| ok & c.is_finite());
        self.classify_as(v, finite);
    }

    /// [`Self::classify`] for a vertex whose colour slots hold lit colours,
    /// finite by construction (clamped, NaN made 0): of its varyings only
    /// the fog coordinate is tested (the loop over all of them cost about
    /// 20 instructions a vertex on lit16, callgrind).
    #[inline]
    fn classify_lit(&self, v: &mut batch::BatchVertex) {
        let finite = self.fog_slot.is_none_or(|o| v.win.v[o].is_finite());
        self.classify_as(v, finite);
    }

    /// [`Self::classify`] given whether the varyings are finite.
    #[inline(always)]
    fn classify_as(&self, v: &mut batch::BatchVertex, varyings_finite: bool) {
        let pos = v.pos;
        let finite = pos.is_finite() & varyings_finite;
        v.finite = finite;
        v.codes = (clip::outcode_f32_in(pos, self.half_z), self.user.code(pos.as_dvec4()));
        v.inside = false;
        if finite && v.codes == (0, 0) {
            if let Some((x, y, y_down, z, inv_w)) = self.map_f32(pos, true) {
                let w = &mut v.win;
                (w.x, w.y, w.y_down, w.z, w.inv_w) = (x, y, y_down, z, inv_w);
                v.inside = true;
            }
        }
    }

    /// Whether llvmpipe splits this draw's quads along v1-v3
    /// (`docs/llvmpipe-facts.md` §12): indexed draws (its `draw_elements`),
    /// flat shading of a per-vertex or lit colour (its `draw_arrays` with constant
    /// interpolation), and draws through its draw pipeline: a face drawn as
    /// lines or points, or a vertex outside the view volume.
    fn quads_split_v1_v3(&self, batch: &mut VertexBatch, source: DrawSource) -> bool {
        let direct_v1_v3 = match source {
            DrawSource::Elements => true,
            DrawSource::Arrays { per_vertex_color } => {
                // Lit colours are vertex-shader outputs, so the fragment shader
                // reads them as (flat) inputs however the colour was given.
                (per_vertex_color || self.state.lighting.enabled) && self.state.shade_model == ShadeModel::Flat
            }
        };
        direct_v1_v3 || self.unfilled() || batch.any_outside()
    }

    /// Whether a face is drawn as lines or points.
    fn unfilled(&self) -> bool {
        [true, false]
            .iter()
            .any(|&front| self.state.polygon_mode(front) != PolygonMode::Fill)
    }

    /// Two-sided selection: for a back face, the back colours (when the
    /// layout carries them) replace the front ones the rasterizer reads.
    fn select_face(&self, v: &mut Varyings, front: bool) {
        if front {
            return;
        }
        let l = &self.layout;
        if let (Some(f), Some(b)) = (l.color(), l.back_color()) {
            let src = *v;
            copy_slots(v, f, &src, b, 4);
        }
        if let (Some(f), Some(b)) = (l.secondary(), l.back_secondary()) {
            let src = *v;
            copy_slots(v, f, &src, b, 4);
        }
    }

    /// Perspective divide and viewport transform; `None` when not finite.
    /// A vertex of the draw (`fused`) is mapped by draw's compiled shader,
    /// `fma(c·(1/w), scale, translate)` (`generate_viewport`, `draw_llvm.c`);
    /// one the clipper made, in C without fusing (`interp`,
    /// `draw_pipe_clip.c`) (docs/llvmpipe-facts.md §11).
    fn project_as(&self, v: &ClipVertex, fused: bool) -> Option<RasterVertex> {
        let (x, y, y_down, z, inv_w) = self.map(v.pos, fused)?;
        Some(RasterVertex {
            x,
            y,
            y_down,
            z,
            inv_w,
            v: v.v,
        })
    }

    /// The window coordinates of [`Self::project_as`]: `(x, y, y_down, z, 1/w)`.
    #[inline]
    fn map(&self, pos: glam::DVec4, fused: bool) -> Option<(f32, f32, f32, f64, f32)> {
        self.map_f32(pos.as_vec4(), fused)
    }

    /// [`Self::map`] of a position given in f32.
    #[inline(always)]
    fn map_f32(&self, p: Vec4, fused: bool) -> Option<(f32, f32, f32, f64, f32)> {
        let inv_w = 1.0 / p.w;
        let vp = &self.viewport;
        if fused && vp.all_pow2 {
            if let Some(r) = vp.map_pow2(p, inv_w) {
                // x, y, z (lanes 0, 1, 3) and 1/w finite, as below.
                let ok = r.is_finite_mask().bitmask() & 0b1011 == 0b1011 && inv_w.is_finite();
                return ok.then_some((r.x, r.y, r.z, f64::from(r.w), inv_w));
            }
        }
        let map = |c: f32, k: usize, s: f32, t: f32| {
            if fused {
                vp.fused(c * inv_w, k, s, t)
            } else {
                c * inv_w * s + t
            }
        };
        let (s, t) = (vp.scale, vp.translate);
        let x = map(p.x, 0, s[0], t[0]);
        let y = map(p.y, 1, s[1], t[1]);
        let y_down = map(p.y, 3, vp.flipped_y.0, vp.flipped_y.1);
        let z = map(p.z, 2, s[2], t[2]);
        let ok = x.is_finite() && y.is_finite() && z.is_finite() && inv_w.is_finite();
        ok.then_some((x, y, y_down, f64::from(z), inv_w))
    }

    fn line(&self, a: &ClipVertex, b: &ClipVertex, flat: Option<Varyings>, sink: &mut dyn PrimSink) {
        let n = self.layout.len();
        let f = self.layout.finite_len();
        if !(a.is_finite(f) && b.is_finite(f))
            || outcode_in(a.pos, 1.0, self.half_z) & outcode_in(b.pos, 1.0, self.half_z) != 0
        {
            return;
        }
        if self.user.code(a.pos) & self.user.code(b.pos) != 0 {
            return;
        }
        let (a0, b0) = (*a, *b);
        let (mut a, mut b) = (*a, *b);
        for &g in guard_levels([a, b].iter()) {
            let planes = outcode_in(a.pos, g, self.half_z) | outcode_in(b.pos, g, self.half_z);
            let user = if g == 1.0 {
                self.user.code(a.pos) | self.user.code(b.pos)
            } else {
                0
            };
            if planes != 0 || user != 0 {
                let Some(clipped) = clip_segment((&a, &b), (planes, &self.user), g, n) else {
                    return;
                };
                (a, b) = clipped;
            }
        }
        let drawn = |c: &ClipVertex| c.pos == a0.pos || c.pos == b0.pos;
        if let (Some(ra), Some(rb)) = (self.project_as(&a, drawn(&a)), self.project_as(&b, drawn(&b))) {
            sink.line(&ra, &rb, self.state.line_width, flat.as_ref(), &self.wide_params);
        }
    }

    /// A triangle of vertices of the draw that needs no clipping, drawn
    /// filled: what [`Self::polygon`] computes for it, without copying a
    /// vertex (unless a back face selects its back colours).
    #[inline(always)]
    fn triangle(&self, v: [&RasterVertex; 3], flat: Option<&Varyings>, sink: &mut dyn PrimSink) {
        let area = signed_area(3, |i| (v[i].x, v[i].y));
        if area == 0.0 && !self.recording {
            return;
        }
        let front = self.facing(area);
        if self.state.culls(front) {
            return;
        }
        let params = &self.fill_params;
        if !front && (self.layout.back_color || self.layout.back_secondary) {
            let mut w = v.map(|v| *v);
            for v in &mut w {
                self.select_face(&mut v.v, front);
            }
            let mut f = flat.copied();
            if let Some(f) = f.as_mut() {
                self.select_face(f, front);
            }
            sink.triangle([&w[0], &w[1], &w[2]], f.as_ref(), params);
        } else {
            sink.triangle(v, flat, params);
        }
    }

    /// Whether a polygon of signed window area `area` is front-facing. A
    /// zero-area polygon is drawn by no fragment; in selection and feedback
    /// (`recording`) it is still recorded, as a back face, as Mesa's draw
    /// module does for them (`draw_pipe_cull.c`: `det == 0` passes unless
    /// back faces are culled).
    #[inline(always)]
    fn facing(&self, area: f64) -> bool {
        if area == 0.0 && self.recording {
            return false;
        }
        ((area > 0.0) == (self.state.front_face == FrontFace::Ccw)) != self.upper_left
    }

    /// The general triangle: clipped, projected, culled, drawn as its
    /// polygon mode says. `scratch` holds the clipped polygon (kept across
    /// primitives: nothing is allocated per primitive once it has grown).
    fn polygon(
        &self,
        poly: [PolyVertex; 3],
        mut flat: Option<Varyings>,
        scratch: &mut Scratch,
        sink: &mut dyn PrimSink,
    ) {
        let n = self.layout.len();
        let f = self.layout.finite_len();
        if poly.iter().any(|(v, _)| !v.is_finite(f)) {
            return;
        }
        let codes = poly.map(|(v, _)| outcode_in(v.pos, 1.0, self.half_z));
        let user = poly.map(|(v, _)| self.user.code(v.pos));
        if codes[0] & codes[1] & codes[2] != 0 || user[0] & user[1] & user[2] != 0 {
            return;
        }
        let Scratch { clipped, out, win } = scratch;
        clipped.clear();
        clipped.extend_from_slice(&poly);
        let mut was_clipped = false;
        for &g in guard_levels(poly.iter().map(|(v, _)| v)) {
            let planes = clipped
                .iter()
                .fold(0, |acc, (v, _)| acc | outcode_in(v.pos, g, self.half_z));
            if planes != 0 {
                clip_polygon(clipped, out, planes, g, n);
                was_clipped = true;
            }
        }
        // User planes after the view volume's, as llvmpipe's clipper orders them.
        let user_mask = user[0] | user[1] | user[2];
        if user_mask != 0 {
            if !clip_polygon_user(clipped, out, &self.user, user_mask, n) {
                return;
            }
            was_clipped = true;
        }
        win.clear();
        for (v, edge) in clipped.iter() {
            let drawn = poly.iter().any(|(o, _)| o.pos == v.pos);
            match self.project_as(v, drawn) {
                Some(rv) => win.push((rv, *edge)),
                None => return,
            }
        }
        if win.len() < 3 {
            return;
        }
        // Facing from the signed area in window space (y up: positive is CCW).
        let area = signed_area(win.len(), |i| (win[i].0.x, win[i].0.y));
        let front = self.facing(area);
        if self.state.culls(front) {
            return;
        }
        if self.layout.back_color || self.layout.back_secondary {
            for (v, _) in win.iter_mut() {
                self.select_face(&mut v.v, front);
            }
            if let Some(f) = flat.as_mut() {
                self.select_face(f, front);
            }
        }
        let flat = flat.as_ref();
        let mode = self.state.polygon_mode(front);
        let offset_on = match mode {
            PolygonMode::Fill => self.state.offset_fill,
            PolygonMode::Line => self.state.offset_line,
            PolygonMode::Point => self.state.offset_point,
        };
        let offset = offset_on.then_some((self.state.offset_factor, self.state.offset_units));
        match mode {
            PolygonMode::Fill => {
                if area == 0.0 && !self.recording {
                    return;
                }
                let params = RasterParams { offset, ..self.params };
                if was_clipped {
                    // llvmpipe fans a clipped polygon as (v[i-1], v[i], v[0]); the
                    // order fixes which vertex anchors the f32 setup (measured: the
                    // other fans and starting vertices give 6-8x more depth differences).
                    for i in 2..win.len() {
                        sink.triangle([&win[i - 1].0, &win[i].0, &win[0].0], flat, &params);
                    }
                } else {
                    sink.triangle([&win[0].0, &win[1].0, &win[2].0], flat, &params);
                }
            }
            PolygonMode::Line | PolygonMode::Point => {
                if self.recording {
                    // Every triangle reaches draw's unfilled stage with a reset.
                    sink.reset_stipple();
                }
                let dz = offset.map_or(0.0, |(factor, units)| self.offset_of(win, factor, units));
                for (v, _) in win.iter_mut() {
                    v.z += dz;
                }
                let shifted = &*win;
                // Under line stipple, the edges in llvmpipe's order (its
                // counter runs on along them): a triangle's last edge first,
                // as draw's `draw_pipe_unfilled.c` emits v2→v0, v0→v1, v1→v2;
                // a clipped polygon's from the first (`emit_poly` of
                // `draw_pipe_clip.c` fans it, the stipple reset at the first).
                // Recorded (select, feedback): draw's unfilled order.
                let n = shifted.len();
                let first = if mode == PolygonMode::Line && self.state.line_stipple {
                    sink.reset_stipple();
                    if was_clipped {
                        0
                    } else {
                        n - 1
                    }
                } else {
                    0
                };
                for k in 0..n {
                    let i = if self.recording {
                        unfilled_order(mode, was_clipped, n, k)
                    } else {
                        (first + k) % n
                    };
                    let (v, edge) = &shifted[i];
                    if !edge {
                        continue;
                    }
                    if mode == PolygonMode::Line {
                        let next = &shifted[(i + 1) % shifted.len()].0;
                        sink.line(v, next, self.state.line_width, flat, &self.params);
                    } else {
                        let mut v = *v;
                        if let (Some(f), Some(o)) = (flat, self.layout.color()) {
                            copy_slots(&mut v.v, o, f, o, 4);
                        }
                        if let (Some(f), Some(o)) = (flat, self.layout.secondary()) {
                            copy_slots(&mut v.v, o, f, o, 4);
                        }
                        // (Polygon-mode points are sized as at eye depth 0:
                        // their clip position is not at hand here.)
                        sink.point(
                            &v,
                            self.state.point_params.size(self.state.point_size, 0.0),
                            &self.params,
                        );
                    }
                }
            }
        }
    }

    /// Polygon offset for a polygon drawn as lines or points: from the depth
    /// slope of its plane in window space, by the same formula as filled ones.
    fn offset_of(&self, win: &[(RasterVertex, bool)], factor: f32, units: f32) -> f64 {
        let Some(format) = self.params.depth else { return 0.0 };
        let (a, b, c) = (&win[0].0, &win[1].0, &win[2].0);
        let (x1, y1, z1) = (f64::from(b.x - a.x), f64::from(b.y - a.y), b.z - a.z);
        let (x2, y2, z2) = (f64::from(c.x - a.x), f64::from(c.y - a.y), c.z - a.z);
        let det = x1 * y2 - x2 * y1;
        let (zx, zy) = if det == 0.0 {
            (0.0, 0.0)
        } else {
            ((z1 * y2 - z2 * y1) / det, (z2 * x1 - z1 * x2) / det)
        };
        let max_z = [a.z, b.z, c.z].iter().fold(0.0f32, |m, z| m.max((*z as f32).abs()));
        f64::from(raster::offset(factor, units, zx as f32, zy as f32, format, max_z))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::FramebufferDesc;

    /// The four-lane viewport map gives the scalar path's bits (positions
    /// with products of every kind: normal, zero, tiny, huge, NaN).
    #[test]
    fn pow2_map_equals_the_scalar_map() {
        let fb = Framebuffer::new(FramebufferDesc::rgba8_d24s8(1024, 1024)).unwrap();
        let state = RasterState::new(1024, 1024);
        let g = Geometry::new(&state, &fb, true, VaryingLayout::default());
        assert!(g.viewport.all_pow2);
        let mut scalar = Geometry::new(&state, &fb, true, VaryingLayout::default());
        scalar.viewport.all_pow2 = false;
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 16) as u32
        };
        let specials = [0.0, -0.0, 1e-40, 1e-30, 3e38, f32::INFINITY, f32::NAN, 1.0, -1.0, 0.5];
        for k in 0..400_000 {
            let mut c = [0.0f32; 4].map(|_| {
                let r = next();
                match r % 4 {
                    0 => f32::from_bits(next()),
                    1 => specials[(next() % 10) as usize],
                    _ => (r as f32 / u32::MAX as f32) * 4.0 - 2.0,
                }
            });
            if k % 3 == 0 {
                c[3] = c[3].abs() + 0.5;
            }
            let p = Vec4::from_array(c);
            let (a, b) = (g.map_f32(p, true), scalar.map_f32(p, true));
            let bits = |m: Option<(f32, f32, f32, f64, f32)>| {
                m.map(|(x, y, yd, z, w)| (x.to_bits(), y.to_bits(), yd.to_bits(), z.to_bits(), w.to_bits()))
            };
            assert_eq!(bits(a), bits(b), "{p:?}");
        }
    }
}
