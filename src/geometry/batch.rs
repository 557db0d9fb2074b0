//! Vertex batches: vertices are fetched and transformed to clip space 256 at a
//! time, as primitive assembly reaches them, so a draw of any size needs one
//! batch of memory and the transform runs as a tight loop.
//!
//! [`VertexBatch::transform`] is the one place a vertex's varyings are filled,
//! as the draw's [`VertexStage`] says: colours copied (and clamped) or lit
//! (front and back, primary and secondary, [`super::lighting`]), the fog
//! coordinate taken from the eye-space depth or from `glFogCoord`, the
//! texture coordinates generated and transformed ([`crate::texture::texgen`]).
//!
//! A lit draw whose colours depend on the normal alone
//! ([`LightSetup::lights_many`]) is transformed [`CHUNK`] vertices at a
//! time instead (`VertexBatch::transform_lit_chunk`): the normals gathered
//! as the vertices are read, lit together ([`LightSetup::light_many`]), the
//! colours written from columns chosen once a chunk, then each vertex
//! classified. The vertices of `glBegin`/`glEnd` are read in place
//! ([`Vertices::Slice`]), not through a call returning a copy. Measured on
//! the lit16 frame (1.6 M vertices, callgrind): the batch's refill went
//! from 518 to 296 instructions a vertex with these, the exact inline
//! [`super::fma`] (no `fmaf` call; one f32 multiply and add for a scale
//! that is a power of two), the f32 outcode
//! ([`super::clip::outcode_f32`]) and the finiteness of lit colours taken
//! as given (`Geometry::classify_lit`).
//!
//! A draw lit through the general path (positional or spot lights, local
//! viewer: [`LightSetup::is_fast`] false) is transformed and classified
//! without its colours and texture coordinates; those are computed when a
//! primitive that is not trivially rejected needs the vertex
//! ([`VertexBatch::light_pending`]), the colours through a per-draw cache
//! by input (`LitCache`). Measured on MuJoCo's floor plane
//! (`osmesa/bench/mujoco_passes.c`, the plane pass: a list of 40,000
//! quads, 3 lights, most of the plane outside the view; callgrind, 1
//! thread): 2,640 instructions a vertex, 1,194 with the cache, 192 with
//! both.

use super::clip::{outcode_f32_in, ClipVertex};
use super::lighting::{LightInput, LightSetup, LitColors, ManyLit, CHUNK};
use super::varying::{VaryingLayout, Varyings, MAX_VARYINGS};
use super::Geometry;
use super::{InVertex, Vertices};
use crate::raster::RasterVertex;
use crate::texture::texgen::TexCoordStage;
use glam::{DVec4, Mat4, Vec4};
use std::borrow::Borrow;

/// Vertices transformed at once.
pub const BATCH: usize = 256;

/// The fewest vertices a refill lights with [`LightSetup::light_many`]
/// (fewer go one at a time: its arrays cost more to set up than they save).
const MANY_MIN: usize = 8;

/// Where the fog coordinate of a vertex comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FogSource {
    /// `GL_FRAGMENT_DEPTH`: `|z_eye|`, z_eye computed as Mesa's fixed-function
    /// vertex program does when it needs no other eye coordinate (a `DP4` of
    /// the position with the modelview's third row, `docs/llvmpipe-facts.md`).
    EyeDepth { row: Vec4 },
    /// `GL_FOG_COORD`: `|fog_coord|` of the vertex.
    FogCoord,
}

/// The per-draw constants of the vertex stage: what each vertex computes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexStage<'a> {
    /// Object to clip coordinates.
    pub mvp: Mat4,
    /// The varyings to fill.
    pub layout: VaryingLayout,
    /// The fog coordinate's source, when `layout.fog`.
    pub fog: FogSource,
    /// With `GL_LIGHTING`: the colours are lit, not copied. `None` when
    /// lighting is off (no normal is then transformed, nothing computed).
    pub lighting: Option<LightSetup>,
    /// Materials that vary per vertex (`glMaterial` between `glBegin` and
    /// `glEnd`, which Mesa keeps as vertex attributes): when not empty, a
    /// vertex is lit by `vertex_materials[v.material]` instead of `lighting`.
    pub vertex_materials: &'a [LightSetup],
    /// The texture coordinates of the units `layout` carries and where the
    /// vertices' come from (`None` when it carries none: no texture work at all).
    pub tex_coords: Option<(&'a TexCoordStage, TexFetch<'a>)>,
}

/// Texture coordinates `(s, t, r, q)` of vertex `i` for unit `u`, as
/// `fetch(i, u)`: apart from [`InVertex`] so that an untextured draw neither
/// fetches nor copies them.
#[derive(Clone, Copy)]
pub struct TexFetch<'a>(pub &'a dyn Fn(usize, usize) -> Vec4);

impl std::fmt::Debug for TexFetch<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("TexFetch")
    }
}

impl PartialEq for TexFetch<'_> {
    /// The same function.
    fn eq(&self, o: &Self) -> bool {
        std::ptr::addr_eq(self.0, o.0)
    }
}

impl VertexStage<'_> {
    /// A stage transforming by `mvp`, filling the colours `layout` carries.
    pub fn new(mvp: Mat4, layout: VaryingLayout) -> VertexStage<'static> {
        VertexStage {
            mvp,
            layout,
            fog: FogSource::FogCoord,
            lighting: None,
            vertex_materials: &[],
            tex_coords: None,
        }
    }

    /// Vertex `v` (index `i` of the draw) in clip space with its varyings.
    pub fn transform(&self, i: usize, v: &InVertex) -> ClipVertex {
        let mut out = ClipVertex {
            pos: DVec4::ZERO,
            v: [0.0; MAX_VARYINGS],
        };
        out.pos = self.transform_into(i, v, &mut out.v);
        out
    }

    /// [`Self::transform`] writing the varyings into `out` in place (no
    /// copy of the vertex): the slots of the layout, the same slots for
    /// every vertex of a draw (the others are left as they are), and
    /// returning the clip-space position.
    pub fn transform_into(&self, i: usize, v: &InVertex, out: &mut Varyings) -> DVec4 {
        self.transform_slots(&Slots::of(&self.layout), i, v, out).as_dvec4()
    }

    /// [`Self::transform_into`] with the layout's offsets found beforehand.
    #[inline]
    fn transform_slots(&self, slots: &Slots, i: usize, v: &InVertex, out: &mut Varyings) -> Vec4 {
        if let Some(light) = &self.lighting {
            let light = self.vertex_materials.get(usize::from(v.material)).unwrap_or(light);
            let lit = light.light_vertex(&LightInput {
                pos: v.pos,
                normal: v.normal,
                color: v.color,
            });
            slots.put_lit(&lit, out);
        } else {
            if let Some(o) = slots.color {
                out[o..o + 4].copy_from_slice(&clamp_color(v.color));
            }
            if let Some(o) = slots.secondary {
                out[o..o + 4].copy_from_slice(&clamp_color(v.secondary));
            }
        }
        self.transform_rest(slots, i, v, out)
    }

    /// The part of [`Self::transform_slots`] after the colours: the fog
    /// coordinate, the texture coordinates, the clip position.
    #[inline(always)]
    fn transform_rest(&self, slots: &Slots, i: usize, v: &InVertex, out: &mut Varyings) -> Vec4 {
        let pos = self.transform_fog_pos(slots, v, out);
        self.transform_tex(i, v, out);
        pos
    }

    /// The texture coordinates of vertex `v` (index `i`), when the layout carries any.
    #[inline(always)]
    fn transform_tex(&self, i: usize, v: &InVertex, out: &mut Varyings) {
        if let Some((t, fetch)) = self.tex_coords {
            t.fill(v, |u| (fetch.0)(i, u), out);
        }
    }

    /// The fog coordinate of `v` and its clip position.
    #[inline(always)]
    fn transform_fog_pos(&self, slots: &Slots, v: &InVertex, out: &mut Varyings) -> Vec4 {
        if let Some(o) = slots.fog {
            out[o] = match self.fog {
                FogSource::EyeDepth { row } => match self.lighting.as_ref().and_then(|l| l.eye_position(v.pos)) {
                    Some(eye) => eye[2].abs(),
                    None => eye_dot(row, v.pos).abs(),
                },
                FogSource::FogCoord => v.fog_coord.abs(),
            };
        }
        self.mvp * v.pos
    }
}

/// The offsets of a layout's colour and fog slots, found once per draw
/// rather than at every vertex.
#[derive(Clone, Copy, Debug)]
struct Slots {
    color: Option<usize>,
    back_color: Option<usize>,
    secondary: Option<usize>,
    back_secondary: Option<usize>,
    fog: Option<usize>,
}

impl Slots {
    fn of(l: &VaryingLayout) -> Slots {
        Slots {
            color: l.color(),
            back_color: l.back_color(),
            secondary: l.secondary(),
            back_secondary: l.back_secondary(),
            fog: l.fog(),
        }
    }

    /// Writes lit colours into the slots the layout carries.
    #[inline(always)]
    fn put_lit(&self, lit: &LitColors, out: &mut Varyings) {
        for (slot, c) in [
            (self.color, &lit.front),
            (self.back_color, &lit.back),
            (self.secondary, &lit.front_secondary),
            (self.back_secondary, &lit.back_secondary),
        ] {
            if let Some(o) = slot {
                out[o..o + 4].copy_from_slice(c);
            }
        }
    }
}

/// GL clamps vertex colors to `[0, 1]`; NaN reads as 0 on every target.
fn clamp_color(c: Vec4) -> [f32; 4] {
    c.to_array().map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) })
}

/// `DP4` as llvmpipe's vertex shaders run it (`lower_fdot` with `ffma`
/// lowered, `nir_lower_alu_width.c`): products summed from the last
/// component, `((p.w·m.w + p.z·m.z) + p.y·m.y) + p.x·m.x`, each step rounded.
pub fn eye_dot(m: Vec4, p: Vec4) -> f32 {
    let mut s = p.w * m.w;
    s += p.z * m.z;
    s += p.y * m.y;
    s + p.x * m.x
}

/// A transformed vertex as the batch keeps it: its clip position, and its
/// window position computed once (not once per triangle that uses it) next to
/// its varyings, so that a triangle needing no clipping borrows its three
/// vertices as they are.
#[derive(Clone, Copy, Debug)]
pub struct BatchVertex {
    /// Clip coordinates, as the f32 transform makes them (clipping widens
    /// them to f64: kept narrow, four vertices fit in 1 KB, which a small
    /// draw's allocation serves from malloc's per-thread cache).
    pub pos: Vec4,
    /// The varyings (`win.v`) and, when `inside`, the window position as
    /// [`Geometry::project_as`](super::Geometry) maps a vertex of the draw.
    pub win: RasterVertex,
    /// Outcode at the view volume ([`outcode`] at guard scale 1) and the
    /// enabled user planes the vertex is outside of.
    pub codes: (u8, u8),
    /// Whether the position and the slots `finite_len` covers are finite.
    pub finite: bool,
    /// Finite, inside the view volume and every enabled user plane (both
    /// codes 0), and projected to finite window coordinates: a primitive of
    /// such vertices needs no clipping.
    pub inside: bool,
    /// `glEdgeFlag` of the vertex.
    pub edge: bool,
    /// Whether its lit colours and texture coordinates are still to be
    /// computed (the general lighting path computes them when a primitive
    /// needs the vertex, [`VertexBatch::light_pending`]): until then
    /// those slots hold stale values.
    pub pending: bool,
}

impl BatchVertex {
    /// The vertex as clipping takes it (a copy of its varyings).
    pub fn clip(&self) -> ClipVertex {
        ClipVertex {
            pos: self.pos.as_dvec4(),
            v: self.win.v,
        }
    }
}

/// A vertex before its first transform.
const EMPTY: BatchVertex = BatchVertex {
    pos: Vec4::ZERO,
    win: RasterVertex {
        x: 0.0,
        y: 0.0,
        y_down: 0.0,
        z: 0.0,
        inv_w: 0.0,
        v: [0.0; MAX_VARYINGS],
    },
    codes: (0, 0),
    finite: false,
    inside: false,
    edge: true,
    pending: false,
};

/// The vertex window's memory, kept across draws (by the context) so that a
/// draw neither allocates it nor fills it with [`EMPTY`] first: that was
/// 4 instructions a vertex on the lit16 frame and 16–21 on lit, whose draws
/// are short. Every draw of one [`VaryingLayout`] writes the same slots of
/// the entries it loads, so an entry left by an earlier draw of the same
/// layout differs from [`EMPTY`] only in what the draw overwrites before
/// reading; a draw of another layout starts from an empty window.
#[derive(Debug, Default)]
pub struct Window {
    verts: Vec<BatchVertex>,
    /// The layout every entry of `verts` was written under.
    layout: Option<VaryingLayout>,
    /// The lit-colour cache's memory ([`LitCache`]), kept across draws.
    lit: LitCache,
}

impl Window {
    /// The entries for a draw of `layout` (emptied, its allocation kept,
    /// when the last draw had another layout).
    fn take(&mut self, layout: &VaryingLayout) -> Vec<BatchVertex> {
        let mut verts = std::mem::take(&mut self.verts);
        if self.layout != Some(*layout) {
            verts.clear();
            self.layout = Some(*layout);
        }
        verts
    }

    /// The entries back after the draw.
    fn give_back(&mut self, verts: Vec<BatchVertex>) {
        self.verts = verts;
    }

    /// The lit-colour cache for a new draw: its entries of earlier draws
    /// no longer hit (their `draw` is another), none is cleared.
    fn take_lit(&mut self) -> LitCache {
        let mut cache = std::mem::take(&mut self.lit);
        cache.draw = cache.draw.wrapping_add(1);
        if cache.draw == 0 {
            // After 2^32 draws: entries of draw 0 would hit again.
            cache.entries.clear();
            cache.draw = 1;
        }
        cache
    }
}

/// Entries of the [`LitCache`] (a power of two).
const LIT_CACHE: usize = 2048;

/// One remembered vertex: the bits of its lighting input and its colours.
#[derive(Clone, Copy, Debug)]
struct LitEntry {
    /// The draw it was lit in ([`LitCache::draw`]); 0: never.
    draw: u32,
    key: [u32; 11],
    lit: LitColors,
}

/// The colours the general lighting path ([`LightSetup::light`]) gave
/// this draw's vertices, by the bits of their position, normal and colour:
/// lighting is a function of those alone in a draw (one [`LightSetup`]), so
/// a vertex met again takes its colours from here, the same bits. Quads,
/// separate triangles and grids repeat their vertices: MuJoCo's floor, a
/// list of 40,000 `GL_QUADS`, gives each grid point to four quads, the
/// neighbour in the next row 800 vertices later, which a direct-mapped
/// table of 2048 keeps. Mesa's display-list compiler merges such vertices
/// too (docs/llvmpipe-facts.md §23). The fast path (infinite lights, no
/// spot, non-local viewer) lights a vertex for less than a look-up and
/// does not use it. Measured on MuJoCo's plane pass (3 lights, one a
/// spot, local viewer; callgrind, `osmesa/bench/mujoco_passes.c`): 2640
/// instructions a vertex before, 1194 with it (a 70% hit rate).
#[derive(Clone, Debug, Default)]
pub struct LitCache {
    /// Allocated at the first draw that uses it, then kept.
    entries: Vec<LitEntry>,
    /// The current draw's number, never 0.
    draw: u32,
}

impl LitCache {
    /// The colours `light` gives `v`, remembered or computed.
    #[inline]
    fn light(&mut self, light: &LightSetup, v: &LightInput) -> LitColors {
        if self.entries.is_empty() {
            self.entries.resize(
                LIT_CACHE,
                LitEntry {
                    draw: 0,
                    key: [0; 11],
                    lit: LitColors::default(),
                },
            );
        }
        let (p, n, c) = (v.pos.to_array(), v.normal.to_array(), v.color.to_array());
        let key = [p[0], p[1], p[2], p[3], n[0], n[1], n[2], c[0], c[1], c[2], c[3]].map(f32::to_bits);
        let mut h = 0u32;
        for k in key {
            h = (h ^ k).wrapping_mul(0x9e37_79b1);
        }
        let slot = (h >> (32 - LIT_CACHE.trailing_zeros())) as usize;
        let Some(e) = self.entries.get_mut(slot) else {
            return light.light_vertex(v);
        };
        if e.draw != self.draw || e.key != key {
            *e = LitEntry {
                draw: self.draw,
                key,
                lit: light.light_vertex(v),
            };
        }
        e.lit
    }
}

/// A sliding window of transformed vertices, plus vertex 0, which fans,
/// polygons and line loops refer back to.
///
/// Vertices are written in place (the old `get` returned a 230-byte vertex by
/// value and the triangle closure copied three of them per triangle: 14% of
/// the lit16 frame went to that memmove); primitives borrow them through
/// [`VertexBatch::vertex`] after [`VertexBatch::load`].
pub struct VertexBatch<'a> {
    stage: &'a VertexStage<'a>,
    slots: Slots,
    geometry: &'a Geometry<'a>,
    fetch: Vertices<'a>,
    count: usize,
    /// Index of `window[0]`.
    base: usize,
    /// Vertices `base..base + len`, then (once the window has moved past
    /// it) vertex 0 at `window[BATCH]`; other entries are stale.
    window: Vec<BatchVertex>,
    /// Lit colours of this draw by input, when the general path lights it.
    lit: LitCache,
    len: usize,
    /// Where vertex 0 is in `window`: 0, then `BATCH`.
    zero: usize,
}

impl<'a> VertexBatch<'a> {
    /// A batch over `count` vertices, `fetch` giving them, which
    /// `geometry` classifies and projects.
    pub fn new(
        stage: &'a VertexStage<'a>,
        geometry: &'a Geometry<'a>,
        count: usize,
        fetch: Vertices<'a>,
        window: &mut Window,
    ) -> VertexBatch<'a> {
        VertexBatch {
            stage,
            slots: Slots::of(&stage.layout),
            geometry,
            fetch,
            count,
            base: 0,
            window: window.take(&stage.layout),
            lit: window.take_lit(),
            len: 0,
            zero: 0,
        }
    }

    /// Transforms vertex `i` into `out`. Every vertex of the draw writes the
    /// same varying slots, so reusing an entry leaves nothing stale in them.
    #[inline]
    fn transform(&self, i: usize, v: &InVertex, out: &mut BatchVertex) {
        out.pos = self.stage.transform_slots(&self.slots, i, v, &mut out.win.v);
        out.edge = v.edge;
        out.pending = false;
        self.geometry.classify(out);
    }

    /// [`Self::transform`] of a draw lit through the general path, but
    /// neither lit nor given texture coordinates yet: [`Self::light_pending`]
    /// does both for the vertices of the primitives drawn. Lit colours are finite (clamped, NaN made 0),
    /// so the vertex is classified without them (`classify_lit`).
    #[inline]
    fn transform_unlit(&self, v: &InVertex, out: &mut BatchVertex) {
        out.pos = self.stage.transform_fog_pos(&self.slots, v, &mut out.win.v);
        out.edge = v.edge;
        out.pending = true;
        self.geometry.classify_lit(out);
    }

    /// Lights the vertices `indices` of the current primitive (loaded by
    /// [`Self::load`]) that are still pending, through the [`LitCache`],
    /// and computes their texture coordinates.
    #[inline]
    pub fn light_pending(&mut self, indices: &[usize]) {
        for &i in indices {
            let at = if i == 0 { self.zero } else { i - self.base };
            if !self.window.get(at).is_some_and(|v| v.pending) {
                continue;
            }
            let Some(light) = &self.stage.lighting else {
                continue;
            };
            let fetched;
            let v = match self.fetch {
                Vertices::Slice(s) => s.get(i),
                Vertices::Fetch(f) => {
                    fetched = f(i);
                    Some(&fetched)
                }
            };
            let Some(v) = v else {
                continue;
            };
            let input = LightInput {
                pos: v.pos,
                normal: v.normal,
                color: v.color,
            };
            let lit = self.lit.light(light, &input);
            let out = &mut self.window[at];
            self.slots.put_lit(&lit, &mut out.win.v);
            self.stage.transform_tex(i, v, &mut out.win.v);
            out.pending = false;
        }
    }

    /// Transforms vertices `first..first + out.len()` into `out`, each read
    /// by `get(i)` (a reference into the draw's vertices, or one made).
    #[inline(always)]
    fn transform_run<V: Borrow<InVertex>>(&self, first: usize, out: &mut [BatchVertex], get: impl Fn(usize) -> V) {
        let one_setup = self.stage.vertex_materials.is_empty();
        let many = self
            .stage
            .lighting
            .as_ref()
            .filter(|l| l.lights_many() && one_setup && out.len() >= MANY_MIN);
        let general = self.stage.lighting.as_ref().filter(|l| !l.is_fast() && one_setup);
        match (many, general) {
            (Some(light), _) => {
                for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
                    self.transform_lit_chunk(light, first + c * CHUNK, chunk, &get);
                }
            }
            (None, Some(_)) => {
                for (k, o) in out.iter_mut().enumerate() {
                    self.transform_unlit(get(first + k).borrow(), o);
                }
            }
            (None, None) => {
                for (k, o) in out.iter_mut().enumerate() {
                    self.transform(first + k, get(first + k).borrow(), o);
                }
            }
        }
    }

    /// [`Self::transform`] for vertices `first..first + out.len()` (at most
    /// [`CHUNK`]) of a draw that [`LightSetup::light_many`] lights: the
    /// normals gathered as each vertex is fetched, the colours then computed
    /// for all of them at once, written, and the vertices classified.
    #[inline(always)]
    fn transform_lit_chunk<V: Borrow<InVertex>>(
        &self,
        light: &LightSetup,
        first: usize,
        out: &mut [BatchVertex],
        get: &impl Fn(usize) -> V,
    ) {
        let mut normals = [[0.0f32; CHUNK]; 3];
        for (k, o) in out.iter_mut().enumerate() {
            let v = get(first + k);
            let v = v.borrow();
            let n = light.lighting_normal(v.normal);
            (normals[0][k], normals[1][k], normals[2][k]) = (n[0], n[1], n[2]);
            o.pos = self.stage.transform_rest(&self.slots, first + k, v, &mut o.win.v);
            o.edge = v.edge;
            o.pending = false;
        }
        let mut lit = ManyLit::default();
        light.light_many(&normals, out.len(), &mut lit);
        // The slots to write and their columns, picked once a chunk (picked
        // at each vertex, the choice cost 30 instructions a vertex on lit16).
        let columns = light.many_columns(&lit);
        let mut put = [(0, columns[0]); 4];
        let mut len = 0;
        let s = &self.slots;
        for (slot, column) in [s.color, s.secondary, s.back_color, s.back_secondary]
            .into_iter()
            .zip(columns)
        {
            if let Some(o) = slot.filter(|&o| o + 4 <= MAX_VARYINGS) {
                put[len] = (o, column);
                len += 1;
            }
        }
        for (k, o) in out.iter_mut().enumerate().take(CHUNK) {
            for &(at, (c, a)) in &put[..len] {
                o.win.v[at..at + 4].copy_from_slice(&[c[0][k], c[1][k], c[2][k], a]);
            }
            self.geometry.classify_lit(o);
        }
    }

    /// Makes the vertices of a primitive whose newest (largest) index is
    /// `newest` available to [`Self::vertex`]. Assembly asks for indices that
    /// never fall more than three behind the newest one (or for vertex 0), so
    /// refilling the window from `newest - 3` keeps every vertex of the
    /// current primitive; the ones already transformed are moved, not
    /// transformed again.
    #[inline]
    pub fn load(&mut self, newest: usize) {
        if newest >= self.base && newest < self.base + self.len {
            return;
        }
        self.refill(newest);
    }

    fn refill(&mut self, newest: usize) {
        let base = newest.saturating_sub(3);
        if self.base == 0 && base != 0 && self.len > 0 {
            // Fans, polygons and line loops refer back to vertex 0.
            self.window.resize(BATCH + 1, EMPTY);
            self.window[BATCH] = self.window[0];
            self.zero = BATCH;
        }
        let end = (base + BATCH).min(self.count);
        let n = end - base;
        if self.window.len() < n {
            self.window.resize(n, EMPTY);
        }
        // Vertices kept from the old window: `base..old_end`, moved to the front.
        let old_end = self.base + self.len;
        let kept = if base >= self.base && base < old_end {
            let kept = (old_end - base).min(n);
            let from = base - self.base;
            self.window.copy_within(from..from + kept, 0);
            kept
        } else {
            0
        };
        let mut window = std::mem::take(&mut self.window);
        let out = &mut window[kept..n];
        match self.fetch {
            Vertices::Slice(s) => self.transform_run(base + kept, out, |i| &s[i]),
            Vertices::Fetch(f) => self.transform_run(base + kept, out, f),
        }
        self.window = window;
        self.base = base;
        self.len = n;
    }

    /// Whether a vertex of the draw is outside the view volume or an enabled
    /// user plane. A draw that fits in one window is transformed for it
    /// (the work its primitives then reuse); a longer one is scanned by
    /// position alone.
    pub fn any_outside(&mut self) -> bool {
        if self.count <= BATCH {
            if self.count > 0 {
                self.load(self.count.min(4) - 1);
            }
            return self.window[..self.count].iter().any(|v| v.codes != (0, 0));
        }
        (0..self.count).any(|i| {
            let p = self.stage.mvp * self.fetch.pos(i);
            outcode_f32_in(p, self.geometry.half_z) != 0 || self.geometry.user.code(p.as_dvec4()) != 0
        })
    }

    /// Ends the draw: its entries back to `window` for the next draw.
    pub fn finish(self, window: &mut Window) {
        window.give_back(self.window);
        window.lit = self.lit;
    }

    /// Vertex `i`, loaded by [`Self::load`] for the current primitive.
    #[inline]
    pub fn vertex(&self, i: usize) -> &BatchVertex {
        &self.window[if i == 0 { self.zero } else { i - self.base }]
    }
}
