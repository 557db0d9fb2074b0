//! `Context`: the GL-shaped state machine of the Rust API.
//!
//! Every call that GL can reject returns `Err(GlError)` and changes no state;
//! the first error since the last [`Context::get_error`] is also kept, GL-style,
//! for callers (such as the C ABI) that poll.

use crate::accum::AccumOp;
use crate::error::{GlError, GlResult};
use crate::fog::{FogCoordSrc, FogParam, FogState};
use crate::fragment::Backend;
use crate::framebuffer::{Clear, Framebuffer, FramebufferDesc, ReadFormat, Rect};
use crate::geometry::batch::{FogSource, TexFetch, VertexStage};
use crate::geometry::lighting::LightSetup;
use crate::geometry::varying::VaryingLayout;
use crate::geometry::{DrawSource, Geometry, InVertex, Vertices, MAX_VIEWPORT};
pub use crate::immediate::ImmediateRun;
use crate::immediate::{self, VertexFormat};
use crate::lighting::{
    ColorMaterialMode, LightModelParam, LightParam, LightParamName, Material, MaterialParam, MaterialParamName,
};
use crate::matrix::{self, MatrixMode, MatrixStack};
use crate::raster::background::Background;
use crate::raster::scene::{DrawState, Scene};
use crate::raster::stipple::LineStipple;
use crate::state::{
    Capability, ClearMask, Face, FrontFace, PolygonMode, PrimitiveMode, RasterState, ShadeModel, WindowRect,
};
use crate::texture::texgen::TexCoordStage;
use crate::texture::unit::{TexturePlan, TextureUnits};
use crate::texture::TextureStore;
use crate::tracked::Tracked;
use glam::{Mat4, Vec3, Vec3A, Vec4};
use softgl_jit::texture::MAX_UNITS;
use softgl_jit::FragmentUniforms;
use softgl_jit::{
    BlendEquation, BlendFactor, BlendKey, CacheStats, ColorMask, CompareFunc, DepthFormat, FragmentKey, LogicOp,
    ShadeKey, SpecialistCache, Stage, StencilOp,
};

/// One vertex attribute array: `size` floats per element, elements `stride`
/// floats apart (0 means tightly packed).
#[derive(Clone, Copy, Debug)]
pub struct AttribArray<'a> {
    pub size: usize,
    pub stride: usize,
    pub data: &'a [f32],
}

impl<'a> AttribArray<'a> {
    /// A tightly packed array of `size`-component elements.
    pub fn new(size: usize, data: &'a [f32]) -> AttribArray<'a> {
        AttribArray { size, stride: 0, data }
    }

    fn step(&self) -> usize {
        if self.stride == 0 {
            self.size
        } else {
            self.stride
        }
    }

    /// Number of complete elements in `data`.
    fn len(&self) -> usize {
        if self.data.len() < self.size {
            0
        } else {
            (self.data.len() - self.size) / self.step() + 1
        }
    }

    /// Element `i`, missing components filled from `fill` (GL's `0, 0, 0, 1`).
    fn get(&self, i: usize, fill: Vec4) -> Vec4 {
        let s = &self.data[i * self.step()..][..self.size];
        let mut v = fill.to_array();
        v[..self.size].copy_from_slice(s);
        Vec4::from_array(v)
    }

    fn check(&self, sizes: std::ops::RangeInclusive<usize>) -> GlResult {
        if !sizes.contains(&self.size) || (self.stride != 0 && self.stride < self.size) {
            return Err(GlError::InvalidValue);
        }
        Ok(())
    }
}

/// The arrays a `draw_arrays`/`draw_elements` call reads (`glVertexPointer`,
/// `glColorPointer`, …, with their client states enabled). Attributes without
/// an array take the current value.
#[derive(Clone, Copy, Debug)]
pub struct VertexArrays<'a> {
    /// 2, 3 or 4 components.
    pub position: AttribArray<'a>,
    /// 3 or 4 components.
    pub color: Option<AttribArray<'a>>,
    /// 3 components (`glNormalPointer`).
    pub normal: Option<AttribArray<'a>>,
    /// `glSecondaryColorPointer`: 3 components.
    pub secondary: Option<AttribArray<'a>>,
    /// `glFogCoordPointer`: 1 component.
    pub fog_coord: Option<AttribArray<'a>>,
    /// `glEdgeFlagPointer`: 1 component, 0 for a non-boundary edge.
    pub edge_flag: Option<AttribArray<'a>>,
    /// `glTexCoordPointer` per unit (`glClientActiveTexture`): 1 to 4 components.
    pub tex_coords: [Option<AttribArray<'a>>; MAX_UNITS],
}

impl<'a> VertexArrays<'a> {
    /// Positions only.
    pub fn positions(size: usize, data: &'a [f32]) -> VertexArrays<'a> {
        VertexArrays {
            position: AttribArray::new(size, data),
            color: None,
            normal: None,
            secondary: None,
            fog_coord: None,
            edge_flag: None,
            tex_coords: [None; MAX_UNITS],
        }
    }

    /// Positions with per-vertex colors.
    pub fn with_colors(pos_size: usize, pos: &'a [f32], color_size: usize, color: &'a [f32]) -> VertexArrays<'a> {
        VertexArrays {
            color: Some(AttribArray::new(color_size, color)),
            ..VertexArrays::positions(pos_size, pos)
        }
    }

    /// The same arrays with unit `unit`'s texture coordinates (`size` floats each).
    pub fn with_tex_coords(mut self, unit: usize, size: usize, coords: &'a [f32]) -> VertexArrays<'a> {
        self.tex_coords[unit] = Some(AttribArray::new(size, coords));
        self
    }

    /// The same arrays with per-vertex normals (3 floats each).
    pub fn with_normals(self, normal: &'a [f32]) -> VertexArrays<'a> {
        VertexArrays {
            normal: Some(AttribArray::new(3, normal)),
            ..self
        }
    }

    fn check(&self) -> GlResult<usize> {
        self.position.check(2..=4)?;
        let mut len = self.position.len();
        for (array, sizes) in [
            (&self.color, 3..=4),
            (&self.secondary, 3..=3),
            (&self.fog_coord, 1..=1),
            (&self.edge_flag, 1..=1),
        ] {
            if let Some(a) = array {
                a.check(sizes)?;
                len = len.min(a.len());
            }
        }
        if let Some(n) = &self.normal {
            n.check(3..=3)?;
            len = len.min(n.len());
        }
        for t in self.tex_coords.iter().flatten() {
            t.check(1..=4)?;
            len = len.min(t.len());
        }
        Ok(len)
    }
}

/// Index data for `draw_elements`.
#[derive(Clone, Copy, Debug)]
pub enum Indices<'a> {
    U8(&'a [u8]),
    U16(&'a [u16]),
    U32(&'a [u32]),
}

impl Indices<'_> {
    fn len(&self) -> usize {
        match self {
            Indices::U8(i) => i.len(),
            Indices::U16(i) => i.len(),
            Indices::U32(i) => i.len(),
        }
    }

    /// Index `k` (which must be below `len`).
    fn get(&self, k: usize) -> usize {
        match self {
            Indices::U8(i) => usize::from(i[k]),
            Indices::U16(i) => usize::from(i[k]),
            Indices::U32(i) => i[k] as usize,
        }
    }

    fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.len()).map(|k| self.get(k))
    }
}

/// Vertex `i` of `arrays`, attributes without an array taking `current`'s.
fn fetch(arrays: &VertexArrays<'_>, i: usize, current: &CurrentAttribs) -> InVertex {
    InVertex {
        pos: arrays.position.get(i, Vec4::W),
        color: arrays.color.map_or(current.color, |c| c.get(i, Vec4::W)),
        secondary: arrays.secondary.map_or(current.secondary, |c| c.get(i, Vec4::W)),
        fog_coord: arrays.fog_coord.map_or(current.fog_coord, |c| c.get(i, Vec4::ZERO).x),
        normal: arrays
            .normal
            .map_or(current.normal.into(), |n| n.get(i, Vec4::ZERO).truncate()),
        edge: arrays
            .edge_flag
            .map_or(current.edge_flag, |e| e.get(i, Vec4::ONE).x != 0.0),
        material: 0,
    }
}

/// Unit `u`'s texture coordinates of vertex `i` of `arrays` (`current`'s without an array).
fn fetch_tex(arrays: &VertexArrays<'_>, i: usize, u: usize, current: &CurrentAttribs) -> Vec4 {
    arrays.tex_coords[u].map_or(current.tex_coords[u], |a| a.get(i, Vec4::W))
}

/// The current vertex attributes (`glColor`, `glNormal`, `glTexCoord`,
/// `glSecondaryColor`, `glFogCoord`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurrentAttribs {
    pub color: Vec4,
    /// 16 bytes, written by `glNormal` as one store and read by `glVertex`
    /// as one load: as a `Vec3`, its three 4-byte stores were read back by
    /// an 8-byte load spanning two of them, which the store cannot forward
    /// (a stall of about 30% of `glVertex3f`'s samples on the lit16 frame).
    pub normal: Vec3A,
    /// `glMultiTexCoord` per unit (`glTexCoord`: unit 0).
    pub tex_coords: [Vec4; MAX_UNITS],
    /// RGB and 1 (GL 1.4's initial `(0, 0, 0, 1)`).
    pub secondary: Vec4,
    pub fog_coord: f32,
    /// `glIndex`: kept (and queryable) but without effect in RGBA mode.
    pub index: f32,
    /// `glEdgeFlag`.
    pub edge_flag: bool,
}

/// `verts.push(v)` when `verts` is full, out of the way of `glVertex`.
#[cold]
#[inline(never)]
fn push_growing(verts: &mut Vec<InVertex>, v: InVertex) {
    verts.push(v);
}

impl CurrentAttribs {
    /// A vertex at `pos` with these attributes (and vertex material `material`).
    #[inline(always)]
    pub fn vertex(&self, pos: Vec4, material: u16) -> InVertex {
        InVertex {
            pos,
            color: self.color,
            secondary: self.secondary,
            fog_coord: self.fog_coord,
            normal: self.normal.into(),
            edge: self.edge_flag,
            material,
        }
    }
}

/// The fragment key, the varying layout and the textures of a draw made now
/// with `state` into `fb`: the key's shading stage interpolates what the
/// layout carries; texture units take part only when a stage reads the
/// fragment colour. (A function of the fields, so that the draw can borrow
/// the textures while it compiles a specialist.)
pub(crate) fn plan<'a>(
    state: &RasterState,
    fb: &Framebuffer,
    ordered_dither: bool,
    (units, store): (&TextureUnits, &'a TextureStore),
) -> (FragmentKey, VaryingLayout, TexturePlan<'a>) {
    let mut key = state.fragment_key(fb, ordered_dither);
    // Multisampling's alpha stages, with GL_MULTISAMPLE on in a multisampled
    // framebuffer only (`st_atom_blend.c`); the sample's threshold is set
    // per sample by the draw (`AlphaCoverage`).
    let ms = &state.multisample;
    let msaa = ms.enabled && fb.samples() > 1;
    let coverage = softgl_jit::AlphaCoverage {
        quarters: (msaa && ms.alpha_to_coverage).then_some(0),
        to_one: msaa && ms.alpha_to_one,
    };
    let reads_color = coverage.quarters.is_some()
        || key
            .stages()
            .as_slice()
            .iter()
            .any(|s| matches!(s, Stage::Pack { .. } | Stage::AlphaTest(_)));
    let mut layout = state.varying_layout(reads_color);
    let textures = match reads_color {
        true => units.plan(store),
        false => TexturePlan::default(),
    };
    layout.tex = textures.mask;
    key.shade = Some(ShadeKey {
        color: layout.color,
        flat: layout.color && state.shade_model == ShadeModel::Flat,
        color_sum: layout.secondary,
        fog: layout.fog.then_some(state.fog.mode),
        depth: key.depth.is_some() && key.depth_format != Some(DepthFormat::D32),
        tex: textures.keys,
        coverage,
    });
    (key, layout, textures)
}

/// Which colours a draw gives per vertex (Mesa's `_VaryingInputs`,
/// `docs/llvmpipe-facts.md` §20): a colour array, or a colour in the
/// `begin`/`end` vertex format. Unlit, the others are the current values,
/// which llvmpipe reads as constants.
#[derive(Clone, Copy, Debug)]
struct Varying {
    color: bool,
    secondary: bool,
}

impl Varying {
    /// The colour arrays of `arrays`.
    fn of(arrays: &VertexArrays<'_>) -> Varying {
        Varying {
            color: arrays.color.is_some(),
            secondary: arrays.secondary.is_some(),
        }
    }
}

/// How a draw reads its vertices: `fetch(i)` is vertex `i`, `tex(i, u)` its
/// texture coordinates for unit `u` (asked only for the units it samples).
type Fetch<'a> = (Vertices<'a>, &'a dyn Fn(usize, usize) -> Vec4);

/// A primitive between `begin` and `end`.
/// What [`Begun`] holds, kept empty between primitives.
type Spare = (Vec<InVertex>, Vec<[Material; 2]>, Vec<[Vec4; MAX_UNITS]>);

struct Begun {
    mode: PrimitiveMode,
    verts: Vec<InVertex>,
    /// The materials (front, back) the vertices were given, when `glMaterial`
    /// was called in between (Mesa keeps materials as vertex attributes,
    /// `vbo/vbo_exec_api.c` `_mesa_Materialfv`): the first is the material at
    /// `begin`; empty when none was called. `InVertex::material` indexes it.
    materials: Vec<[Material; 2]>,
    /// Whether one of those calls set the shininess.
    shininess_varies: bool,
    /// The texture coordinates of each vertex, kept only when a unit has a
    /// target enabled (`tex_units`, bit `u`: the units a draw may sample).
    tex: Vec<[Vec4; MAX_UNITS]>,
    tex_units: u8,
}

/// A software GL 1.x context with its own framebuffer. `Send`: it owns all its data.
pub struct Context {
    /// The framebuffer drawn into: the window's, or a framebuffer object's
    /// attachments assembled (`src/fbo.rs`).
    pub(crate) fb: Framebuffer,
    /// Framebuffer and renderbuffer objects, and the window framebuffer
    /// while an object is drawn into (`src/fbo.rs`).
    pub(crate) fbo: crate::fbo::FboState,
    pub(crate) state: Tracked<RasterState>,
    pub(crate) modelview: MatrixStack,
    pub(crate) projection: MatrixStack,
    matrix_mode: MatrixMode,
    pub(crate) current: CurrentAttribs,
    /// Texture units: enables, environment, generation, matrices.
    pub(crate) tex_units: Tracked<TextureUnits>,
    /// The primitive between `begin` and `end`.
    begun: Option<Begun>,
    /// Which colours `begin`/`end` draws carry per vertex (Mesa's vertex format).
    format: VertexFormat,
    error: Option<GlError>,
    pub(crate) backend: Backend,
    pub(crate) specialists: SpecialistCache,
    /// Whether `GL_DITHER` dithers (see [`Context::set_ordered_dither`]).
    pub(crate) ordered_dither: bool,
    /// Texture objects, their bindings per unit, the active unit (`texture/`).
    pub(crate) textures: Tracked<crate::texture::TextureStore>,
    /// Buffer objects and their bindings (`buffer.rs`).
    buffers: crate::buffer::BufferStore,
    /// Occlusion queries (`query.rs`).
    queries: crate::query::QueryStore,
    /// Draws and clears not yet rasterized (`raster/scene.rs`).
    pub(crate) scene: Scene,
    /// A scene flushing on the pool while `scene` records, holding the
    /// framebuffer's buffers (`fb` is hollow meanwhile: `raster/background.rs`).
    pub(crate) background: Background,
    /// The vertex, material and texture-coordinate storage `begin` reuses.
    spare: Spare,
    /// Threads a flush rasterizes tiles on.
    pub(crate) threads: usize,
    /// The last untextured draw's plan, reused while nothing it was made of changes.
    plan_cache: Option<CachedPlan>,
    /// The geometry's vertex window, reused by every draw (`batch::Window`).
    window: crate::geometry::batch::Window,
    /// `glRasterPos`/`glWindowPos` and what they latched (`raster_pos.rs`).
    pub(crate) raster: crate::raster_pos::RasterPos,
    /// `glPixelZoom`, `glPixelTransfer`, `glPixelMap` (`pixel_transfer.rs`).
    pub(crate) pixel: crate::pixel_transfer::PixelState,
    /// Samples 1.. of a multisampled framebuffer: each one's scene and
    /// background flush (their buffers are `fb`'s other samples; `fb`
    /// itself is sample 0: `multisample.rs`).
    lanes: Vec<Lane>,
    /// Where every sample's depth, and stencil, are known equal: the
    /// rectangle a clear set in all of them, while only draws with
    /// `GL_MULTISAMPLE` off (which cover and write every sample alike)
    /// came since. A filled polygon drawn with it off inside them needs no
    /// copy of sample 0's tests ([`Context::one_sample_tests`]).
    pub(crate) samples_same: [Option<Rect>; 2],
    /// Whether `scene` (and its background flush) records for every sample
    /// of a multisampled framebuffer, its flushes writing all of them: the
    /// draws whose samples share their shading ([`Context::share_samples`]).
    /// Otherwise each sample other than 0 records into its lane.
    shared: bool,
    /// Whether multisampled draws may share their shading between samples
    /// (`SOFTGL_MSAA_SHARED=0` at creation, or
    /// [`Context::set_msaa_shared_shading`], turns it off: the same bytes,
    /// each sample shading again).
    msaa_share: bool,
    /// Lanes of an earlier multisampled framebuffer, kept with their
    /// scenes' memory for the next (MuJoCo binds its 4× object and a 1×
    /// shadow map in turn: fresh lanes refilled their scenes' vectors in
    /// fresh pages at every bind, [`Context::follow_samples`]).
    /// `glRenderMode`, selection and feedback (`select.rs`).
    pub(crate) render_mode: crate::select::RenderModeState,
}

/// One more sample of a multisampled framebuffer: what it records into and
/// flushes with, beside the context's own scene (sample 0).
#[derive(Debug, Default)]
struct Lane {
    scene: Scene,
    background: Background,
}

/// A draw's plan (`plan`) and uniforms, and what they were made of: the
/// generations of the state, texture units and texture objects, the
/// framebuffer's formats and the dither mode. Kept only for plans that sample
/// no texture (a textured plan borrows the texels).
#[derive(Clone, Copy, Debug)]
struct CachedPlan {
    made_of: (u64, u64, u64, (FramebufferDesc, bool), bool),
    key: FragmentKey,
    layout: VaryingLayout,
    uniforms: FragmentUniforms,
}

/// What [`Context::scene_stats`] reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SceneStats {
    pub pending_primitives: usize,
    pub pending_bytes: usize,
    pub peak_bytes: usize,
    pub flushes: u64,
}

impl Drop for Context {
    /// Rasterizes what is pending: a context's last draws reach its
    /// framebuffer (lent memory too) even without a `glFinish`.
    fn drop(&mut self) {
        if self.shared {
            // The scene and its flush in flight hold every sample.
            let _ = self.background.settle(&mut self.fb);
            let _ = self.scene.flush(&mut self.fb, self.threads);
        }
        let mut samples = std::mem::take(&mut self.fb.samples);
        let _ = self.background.settle(&mut self.fb);
        let _ = self.scene.flush(&mut self.fb, self.threads);
        for (lane, fb) in self.lanes.iter_mut().zip(&mut samples) {
            let _ = lane.background.settle(fb);
            let _ = lane.scene.flush(fb, self.threads);
        }
        self.fb.samples = samples;
    }
}

impl Context {
    /// A context drawing into a new framebuffer described by `desc`.
    pub fn new(desc: FramebufferDesc) -> GlResult<Context> {
        Ok(Context::with_framebuffer(Framebuffer::new(desc)?))
    }

    /// A context drawing into a new framebuffer of `samples` samples a
    /// pixel (1, or 4: `multisample.rs`).
    pub fn new_multisample(desc: FramebufferDesc, samples: u32) -> GlResult<Context> {
        Ok(Context::with_framebuffer(Framebuffer::new_multisample(desc, samples)?))
    }

    /// A context drawing into `fb` (e.g. one over lent colour memory), with
    /// GL's initial state for its size.
    pub fn with_framebuffer(fb: Framebuffer) -> Context {
        let desc = *fb.desc();
        let fb_samples = fb.samples();
        Context {
            state: Tracked::new(RasterState::new(desc.width, desc.height)),
            fb,
            fbo: Default::default(),
            modelview: MatrixStack::new(matrix::MAX_MODELVIEW_DEPTH),
            projection: MatrixStack::new(matrix::MAX_PROJECTION_DEPTH),
            matrix_mode: MatrixMode::Modelview,
            tex_units: Tracked::default(),
            current: CurrentAttribs {
                color: Vec4::ONE,
                normal: Vec3A::Z,
                tex_coords: [Vec4::W; MAX_UNITS],
                secondary: Vec4::W,
                fog_coord: 0.0,
                index: 1.0,
                edge_flag: true,
            },
            begun: None,
            format: VertexFormat::default(),
            error: None,
            backend: Backend::from_env(),
            specialists: SpecialistCache::from_env(),
            ordered_dither: std::env::var("SOFTGL_DITHER").is_ok_and(|v| v.trim() == "1"),
            textures: Tracked::new(crate::texture::TextureStore::new()),
            buffers: crate::buffer::BufferStore::new(),
            queries: crate::query::QueryStore::new(),
            scene: Scene::default(),
            background: Background::default(),
            spare: Spare::default(),
            threads: crate::raster::pool::default_threads(),
            plan_cache: None,
            window: Default::default(),
            raster: crate::raster_pos::RasterPos::default(),
            pixel: crate::pixel_transfer::PixelState::default(),
            lanes: (1..fb_samples).map(|_| Lane::default()).collect(),
            samples_same: [None; 2],
            shared: false,
            msaa_share: std::env::var("SOFTGL_MSAA_SHARED").map_or(true, |v| v.trim() != "0"),
            render_mode: Default::default(),
        }
    }

    /// The window framebuffer (the context's own, object 0), with every
    /// draw made so far rasterized into it.
    pub fn framebuffer(&mut self) -> &Framebuffer {
        self.finish_scene();
        self.fbo.window.as_ref().unwrap_or(&self.fb)
    }

    /// The buffer objects (GL 1.5) and their bindings.
    pub fn buffers(&self) -> &crate::buffer::BufferStore {
        &self.buffers
    }

    /// The buffer objects, to change.
    pub fn buffers_mut(&mut self) -> &mut crate::buffer::BufferStore {
        &mut self.buffers
    }

    /// The occlusion queries (GL 1.5).
    pub fn queries(&self) -> &crate::query::QueryStore {
        &self.queries
    }

    /// The occlusion queries, to make, begin, end and delete.
    pub fn queries_mut(&mut self) -> &mut crate::query::QueryStore {
        &mut self.queries
    }

    /// The number of fragments query `name` counted: the scene is flushed
    /// first, so the count is whole (GL's `GL_QUERY_RESULT`).
    pub fn query_result(&mut self, name: u32) -> GlResult<u64> {
        self.queries.samples(name)?;
        self.finish_scene();
        self.queries.settled(name);
        self.queries.samples(name)
    }

    /// Whether query `name`'s result is available (GL's
    /// `GL_QUERY_RESULT_AVAILABLE`), as llvmpipe answers: not the first
    /// time after `end_query`, which flushes the scene; yes from then on.
    pub fn query_available(&mut self, name: u32) -> GlResult<bool> {
        let available = self.queries.available(name)?;
        if !available {
            self.finish_scene();
        }
        Ok(available)
    }

    /// The window framebuffer's size and formats (no flush needed).
    pub fn framebuffer_desc(&self) -> &FramebufferDesc {
        self.fbo.window.as_ref().unwrap_or(&self.fb).desc()
    }

    /// The window framebuffer, for callers that lend or hand out its memory
    /// (the C ABI), with every draw made so far rasterized into it.
    pub fn framebuffer_mut(&mut self) -> &mut Framebuffer {
        self.finish_scene();
        self.fbo.window.as_mut().unwrap_or(&mut self.fb)
    }

    /// Makes `fb` the window framebuffer and returns the previous one, with
    /// every draw made so far rasterized into it. The state (viewport,
    /// scissor box, …) is kept, as when a GL context is made current on
    /// another drawable; a bound framebuffer object stays bound.
    pub fn replace_framebuffer(&mut self, mut fb: Framebuffer) -> Framebuffer {
        self.finish_scene();
        fb.set_color_enabled(!self.fbo.window_draw_none);
        match self.fbo.window.as_mut() {
            Some(w) => std::mem::replace(w, fb),
            None => {
                self.grow_lanes(fb.samples());
                self.samples_same = [None; 2];
                std::mem::replace(&mut self.fb, fb)
            }
        }
    }

    /// The scenes of samples 1.. of a multisampled framebuffer, each with
    /// its sample's buffers: a pixel rectangle or bitmap (whose quad covers
    /// whole pixels, every sample of them: llvmpipe's `st_cb_bitmap.c` and
    /// `st_cb_drawpixels.c` quads) is recorded into each as into `scene`.
    pub(crate) fn lane_scenes(&mut self) -> impl Iterator<Item = (&mut Scene, &Framebuffer)> {
        self.share_samples(false);
        self.lanes.iter_mut().map(|l| &mut l.scene).zip(&self.fb.samples)
    }

    /// Lets multisampled draws share their shading between the samples
    /// (the default) or not: the same bytes either way (tests draw both).
    pub fn set_msaa_shared_shading(&mut self, on: bool) {
        self.msaa_share = on;
    }

    /// Makes `scene` record for every sample of the framebuffer (`on`: the
    /// draws whose samples share their shading) or for sample 0 only, the
    /// lanes for the others, rasterizing what is pending first when that
    /// changes: each sample's draws then run in the order they were made.
    fn share_samples(&mut self, on: bool) {
        if self.shared != on {
            self.finish_scene();
            self.shared = on;
        }
    }

    /// Gives the context a lane a sample of `fb` beyond the first, after
    /// `fb` was replaced (a framebuffer object bound or released; every
    /// lane's scene is empty then: the caller finished the scene first).
    pub(crate) fn follow_samples(&mut self) {
        self.samples_same = [None; 2];
        self.grow_lanes(self.fb.samples());
    }

    /// Makes room for the lanes of a framebuffer of `samples` samples.
    /// Lanes are kept when a framebuffer of fewer samples is bound (the
    /// lanes past its samples are empty and unused: every use zips them
    /// with the samples): MuJoCo binds its single-sampled resolve and
    /// shadow framebuffers every frame, and each lane's scene (records,
    /// bins) was dropped and grown again, page by page, every frame (its
    /// `Scene::grow` alone 3 M instructions a noshadow frame, callgrind,
    /// beside the page faults).
    fn grow_lanes(&mut self, samples: u32) {
        let n = samples as usize - 1;
        if self.lanes.len() < n {
            self.lanes.resize_with(n, Lane::default);
        }
    }

    /// Threads a flush rasterizes tiles on (`SOFTGL_THREADS` at creation,
    /// else the cores). Images are the same bytes for any count.
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// Sets the threads a flush rasterizes on (1 to 64).
    pub fn set_threads(&mut self, threads: usize) {
        self.threads = threads.clamp(1, crate::raster::pool::MAX_THREADS);
    }

    /// The deferred scene: primitives and bytes recorded and not yet
    /// rasterized, the most bytes it held at once, and the flushes run.
    pub fn scene_stats(&self) -> SceneStats {
        let (peak_bytes, flushes) = self.scene.peak();
        SceneStats {
            pending_primitives: self.scene.primitives(),
            pending_bytes: self.scene.bytes(),
            peak_bytes,
            flushes,
        }
    }

    /// Sets the bytes past which the scene is flushed, mid-draw if need be,
    /// in the background (0: [`crate::raster::scene::SCENE_BOUND`], 16 MiB).
    pub fn set_scene_bound(&mut self, bytes: usize) {
        self.scene.set_bound(bytes);
    }

    /// The framebuffer as the draws rasterized so far left it, without
    /// rasterizing the pending ones: for its sizes and formats.
    pub fn framebuffer_pending(&self) -> &Framebuffer {
        self.fbo.window.as_ref().unwrap_or(&self.fb)
    }

    /// Rasterizes every recorded draw and clear into the framebuffer; a
    /// fragment stage's failure is recorded as `GL_INVALID_OPERATION`.
    pub(crate) fn finish_scene(&mut self) {
        let r = Self::finish_fields(
            (&mut self.fb, &mut self.scene, &mut self.background),
            &mut self.lanes,
            self.threads,
            self.shared,
        );
        if let Err(_e) = r {
            self.error.get_or_insert(GlError::InvalidOperation);
        }
    }

    /// [`Context::finish_scene`] on the fields it touches (a draw switches
    /// [`Context::shared`] while its textures are borrowed).
    fn finish_fields(
        (fb, scene, background): (&mut Framebuffer, &mut Scene, &mut Background),
        lanes: &mut [Lane],
        threads: usize,
        shared: bool,
    ) -> Result<(), softgl_jit::FragmentError> {
        let mut r = Ok(());
        if shared {
            // The scene records for every sample: its flushes take them all
            // (the lanes are empty).
            let before = background.join(fb);
            r = before.and(scene.flush(fb, threads));
        }
        // The other samples are out of `fb` while it may go to a flush.
        let mut samples = std::mem::take(&mut fb.samples);
        // Every sample's flush in flight takes all the threads, then the
        // samples' scenes are flushed together (`Scene::flush_all`).
        for lane in lanes.iter().take(samples.len()) {
            lane.background.hurry();
        }
        r = r.and(background.join(fb));
        for (lane, fb) in lanes.iter_mut().zip(&mut samples) {
            r = r.and(lane.background.join(fb));
        }
        let mut jobs = vec![(&mut *scene, &mut *fb)];
        jobs.extend(lanes.iter_mut().map(|l| &mut l.scene).zip(samples.iter_mut()));
        r = r.and(Scene::flush_all(jobs, threads));
        fb.samples = samples;
        r
    }

    /// Records `error` GL-style (kept unless one is already pending), for
    /// calls made through a layer above this API (the C ABI's unimplemented
    /// entry points, its argument checks).
    pub fn record_error(&mut self, error: GlError) {
        self.error.get_or_insert(error);
    }

    /// Whether a `begin` awaits its `end`.
    pub fn inside_begin(&self) -> bool {
        self.begun.is_some()
    }

    /// The matrix mode `glMatrixMode` set.
    pub fn current_matrix_mode(&self) -> MatrixMode {
        self.matrix_mode
    }

    /// The rasterization and fragment state.
    pub fn state(&self) -> &RasterState {
        &self.state
    }

    pub fn current(&self) -> &CurrentAttribs {
        &self.current
    }

    /// The back end running the per-fragment stages (`SOFTGL_BACKEND` at creation).
    pub fn backend(&self) -> Backend {
        self.backend
    }

    /// Chooses the back end for later draws.
    pub fn set_backend(&mut self, backend: Backend) {
        self.backend = backend;
    }

    /// Whether `GL_DITHER` (on by default in GL) dithers colour stored in
    /// 5-6-5 buffers with a 4x4 ordered (Bayer) dither. Off by default
    /// (`SOFTGL_DITHER=1` at creation turns it on): llvmpipe ignores
    /// `GL_DITHER` and truncates each unorm8 channel to its high bits, and
    /// softgl does the same so that 5-6-5 images equal llvmpipe's.
    pub fn set_ordered_dither(&mut self, on: bool) {
        self.ordered_dither = on;
    }

    /// What the specialist cache has done: hits, misses, evictions, failed
    /// compiles and compile times.
    pub fn specialist_stats(&self) -> CacheStats {
        self.specialists.stats()
    }

    /// Compiles every fragment key from now on in `tier` (`None`: each key's
    /// own policy, `SOFTGL_JIT_TIER` or tiered for textured keys). Tests use
    /// `Tier::Optimized` to check the code a draw runs after its upgrade.
    pub fn set_jit_tier(&mut self, tier: Option<softgl_jit::Tier>) {
        self.specialists.set_tier(tier);
    }

    /// How many specialists to keep (at least one; `SOFTGL_SPECIALISTS` at creation,
    /// else 64). Shrinking evicts the least recently used and frees their code.
    pub fn set_specialist_capacity(&mut self, capacity: usize) {
        self.specialists.set_capacity(capacity);
    }

    /// `glGetError`: the first error since the last call, then none.
    pub fn get_error(&mut self) -> Option<GlError> {
        self.error.take()
    }

    /// Records `r`'s error (if none is pending) and passes `r` on.
    pub(crate) fn record<T>(&mut self, r: GlResult<T>) -> GlResult<T> {
        if let Err(e) = &r {
            self.error.get_or_insert(*e);
        }
        r
    }

    /// Most calls are errors between `begin` and `end`; outside, each is a
    /// state change or draw, which ends what Mesa's immediate mode buffers
    /// (`FLUSH_VERTICES`, see [`VertexFormat::flush`]).
    pub(crate) fn outside(&mut self) -> GlResult {
        let r = if self.begun.is_some() {
            Err(GlError::InvalidOperation)
        } else {
            self.format.flush();
            Ok(())
        };
        self.record(r)
    }

    /// Applies `f` to the state unless inside `begin`/`end`.
    fn set(&mut self, f: impl FnOnce(&mut RasterState)) -> GlResult {
        self.outside()?;
        f(self.state.get_mut());
        Ok(())
    }

    /// Checks `ok`, recording `InvalidValue` when false.
    pub(crate) fn require(&mut self, ok: bool) -> GlResult {
        self.outside()?;
        self.record(if ok { Ok(()) } else { Err(GlError::InvalidValue) })
    }

    // ----- capabilities -----

    /// `glEnable`; a light or clip plane past the last is `InvalidEnum`.
    /// Enabling `ColorMaterial` makes the material follow the current colour.
    pub fn enable(&mut self, cap: Capability) -> GlResult {
        self.outside()?;
        self.record(if cap.valid() { Ok(()) } else { Err(GlError::InvalidEnum) })?;
        if let Some(f) = self.texture_flag_mut(cap) {
            *f = true;
            return Ok(());
        }
        let color = self.current.color;
        self.set(|s| {
            if let Some(f) = s.flag_mut(cap) {
                *f = true;
            }
            if cap == Capability::ColorMaterial {
                s.lighting.track_color(color);
            }
        })
    }

    pub fn disable(&mut self, cap: Capability) -> GlResult {
        self.outside()?;
        self.record(if cap.valid() { Ok(()) } else { Err(GlError::InvalidEnum) })?;
        if let Some(f) = self.texture_flag_mut(cap) {
            *f = false;
            return Ok(());
        }
        self.set(|s| {
            if let Some(f) = s.flag_mut(cap) {
                *f = false;
            }
        })
    }

    /// `glIsEnabled`; texture capabilities are the active unit's.
    pub fn is_enabled(&self, cap: Capability) -> bool {
        self.texture_flag(cap).unwrap_or_else(|| self.state.flag(cap))
    }

    // ----- clearing, viewport -----

    /// `glClearColor`, kept unclamped as Mesa keeps it (`_mesa_ClearColor`):
    /// a float buffer is cleared to it as given, a unorm one clamps it;
    /// `GL_COLOR_CLEAR_VALUE` reads [`Context::clear_color_value`].
    pub fn clear_color(&mut self, r: f32, g: f32, b: f32, a: f32) -> GlResult {
        self.set(|s| s.clear_color = [r, g, b, a])
    }

    pub fn clear_depth(&mut self, depth: f64) -> GlResult {
        self.set(|s| s.clear_depth = if depth.is_nan() { 0.0 } else { depth.clamp(0.0, 1.0) })
    }

    pub fn clear_stencil(&mut self, value: i32) -> GlResult {
        self.set(|s| s.clear_stencil = value)
    }

    /// Whether fragment colours are clamped to `[0, 1]` in float colour
    /// buffers too (`GL_CLAMP_FRAGMENT_COLOR` `GL_TRUE`, what
    /// `OSMesaColorClamp(GL_TRUE)` sets); false is GL's `GL_FIXED_ONLY`,
    /// the default: only fixed-point buffers clamp.
    pub fn set_clamp_fragment_color(&mut self, clamp: bool) -> GlResult {
        self.set(|s| s.clamp_fragment_color = clamp)
    }

    /// `glClearAccum`: each channel clamped to `[-1, 1]` (NaN reads as 0).
    pub fn clear_accum(&mut self, r: f32, g: f32, b: f32, a: f32) -> GlResult {
        self.set(|s| s.clear_accum = [r, g, b, a].map(|c| if c.is_nan() { 0.0 } else { c.clamp(-1.0, 1.0) }))
    }

    /// The framebuffer's bounds, cut by the scissor box when the scissor test is on.
    fn scissored_bounds(&self) -> Rect {
        let s = &self.state;
        if s.scissor_test {
            let b = s.scissor;
            self.fb
                .clip_rect(i64::from(b.x), i64::from(b.y), i64::from(b.width), i64::from(b.height))
        } else {
            self.fb.bounds()
        }
    }

    /// `glClear`: honours the scissor test, the color mask, the depth mask and
    /// the stencil write mask. The accumulation buffer, if any, is cleared
    /// at once (draws pending before it are rasterized first).
    pub fn clear(&mut self, mask: ClearMask) -> GlResult {
        self.outside()?;
        // A clear of the whole depth buffer as an object's first use needs
        // none of its depth texture's contents (`fbo::Context::take_depth`).
        let s = &self.state;
        self.fbo.depth_cleared = mask.depth && s.depth_write && !s.scissor_test;
        let r = self.ensure_draw();
        self.fbo.depth_cleared = false;
        r?;
        let rect = self.scissored_bounds();
        if mask.accum && self.fb.has_accum() {
            self.finish_scene();
            let color = self.state.clear_accum;
            if let Some(a) = self.fb.accum_mut_or_none() {
                a.clear(rect, color);
            }
        }
        let s = &self.state;
        let mut clear = Clear::new(rect);
        if mask.color {
            clear = clear.color(&self.fb, s.clear_color, s.color_mask);
        }
        if mask.depth && s.depth_write {
            clear = clear.depth(&self.fb, s.clear_depth);
        }
        if mask.stencil {
            clear = clear.stencil(&self.fb, s.clear_stencil as u8, s.stencil_write_mask as u8);
        }
        // Every sample's depth, or stencil, the same again.
        if mask.depth && s.depth_write {
            self.samples_same[0] = Some(rect);
        }
        if mask.stencil && s.stencil_write_mask & 0xff == 0xff {
            self.samples_same[1] = Some(rect);
        }
        self.scene.clear(&self.fb, clear);
        // Shared, the scene's clears clear every sample.
        if !self.shared {
            for (lane, fb) in self.lanes.iter_mut().zip(&self.fb.samples) {
                lane.scene.clear(fb, clear);
            }
        }
        Ok(())
    }

    /// `glViewport`; sizes above the maximum are clamped, negative ones rejected.
    pub fn viewport(&mut self, x: i32, y: i32, width: i32, height: i32) -> GlResult {
        self.require(width >= 0 && height >= 0)?;
        let r = WindowRect {
            x,
            y,
            width: width.min(MAX_VIEWPORT),
            height: height.min(MAX_VIEWPORT),
        };
        self.set(|s| s.viewport = r)
    }

    /// `glDepthRange`, clamped to `[0, 1]`.
    pub fn depth_range(&mut self, near: f64, far: f64) -> GlResult {
        let c = |v: f64| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        self.set(|s| s.depth_range = (c(near), c(far)))
    }

    pub fn scissor(&mut self, x: i32, y: i32, width: i32, height: i32) -> GlResult {
        self.require(width >= 0 && height >= 0)?;
        self.set(|s| s.scissor = WindowRect { x, y, width, height })
    }

    // ----- matrices -----

    pub fn matrix_mode(&mut self, mode: MatrixMode) -> GlResult {
        self.outside()?;
        self.matrix_mode = mode;
        Ok(())
    }

    fn stack(&mut self) -> &mut MatrixStack {
        let unit = self.active_texture_unit();
        match self.matrix_mode {
            MatrixMode::Modelview => &mut self.modelview,
            MatrixMode::Projection => &mut self.projection,
            MatrixMode::Texture => self.tex_units.get_mut().matrix_stack_mut(unit),
        }
    }

    /// `mode`'s stack; `Texture` is the active unit's.
    fn stack_of(&self, mode: MatrixMode) -> &MatrixStack {
        match mode {
            MatrixMode::Modelview => &self.modelview,
            MatrixMode::Projection => &self.projection,
            MatrixMode::Texture => self.tex_units.matrix_stack(self.active_texture_unit()),
        }
    }

    /// The top of `mode`'s stack (`Texture`: the active unit's).
    pub fn matrix(&self, mode: MatrixMode) -> Mat4 {
        *self.stack_of(mode).top()
    }

    /// The depth of `mode`'s stack (`Texture`: the active unit's).
    pub fn matrix_depth(&self, mode: MatrixMode) -> usize {
        self.stack_of(mode).depth()
    }

    pub fn push_matrix(&mut self) -> GlResult {
        self.outside()?;
        let r = self.stack().push();
        self.record(r)
    }

    pub fn pop_matrix(&mut self) -> GlResult {
        self.outside()?;
        let r = self.stack().pop();
        self.record(r)
    }

    pub fn load_identity(&mut self) -> GlResult {
        self.load_matrix(&Mat4::IDENTITY)
    }

    pub fn load_matrix(&mut self, m: &Mat4) -> GlResult {
        self.outside()?;
        *self.stack().top_mut() = *m;
        Ok(())
    }

    pub fn mult_matrix(&mut self, m: &Mat4) -> GlResult {
        self.outside()?;
        self.stack().mult(m);
        Ok(())
    }

    pub fn translate(&mut self, x: f32, y: f32, z: f32) -> GlResult {
        self.mult_matrix(&Mat4::from_translation(Vec3::new(x, y, z)))
    }

    pub fn scale(&mut self, x: f32, y: f32, z: f32) -> GlResult {
        self.mult_matrix(&Mat4::from_scale(Vec3::new(x, y, z)))
    }

    /// `glRotate`: `angle` in degrees about the axis `(x, y, z)`.
    pub fn rotate(&mut self, angle: f32, x: f32, y: f32, z: f32) -> GlResult {
        self.mult_matrix(&matrix::rotation(angle, x, y, z))
    }

    pub fn frustum(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult {
        self.mult_checked(matrix::frustum(l, r, b, t, n, f))
    }

    pub fn ortho(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult {
        self.mult_checked(matrix::ortho(l, r, b, t, n, f))
    }

    /// Multiplies by a matrix a constructor built, or records its error.
    fn mult_checked(&mut self, m: GlResult<Mat4>) -> GlResult {
        self.outside()?;
        let m = self.record(m)?;
        self.stack().mult(&m);
        Ok(())
    }

    // ----- rasterization state -----

    pub fn shade_model(&mut self, model: ShadeModel) -> GlResult {
        self.set(|s| s.shade_model = model)
    }

    pub fn front_face(&mut self, dir: FrontFace) -> GlResult {
        self.set(|s| s.front_face = dir)
    }

    pub fn cull_face(&mut self, face: Face) -> GlResult {
        self.set(|s| s.cull_face = face)
    }

    pub fn polygon_mode(&mut self, face: Face, mode: PolygonMode) -> GlResult {
        self.set(|s| {
            if face != Face::Back {
                s.polygon_mode_front = mode;
            }
            if face != Face::Front {
                s.polygon_mode_back = mode;
            }
        })
    }

    pub fn polygon_offset(&mut self, factor: f32, units: f32) -> GlResult {
        self.set(|s| (s.offset_factor, s.offset_units) = (factor, units))
    }

    /// `glPointSize`; `InvalidValue` unless positive.
    /// GL 1.4's `glPointParameter`: the size bounds, fade threshold and
    /// distance attenuation. `GL_INVALID_VALUE` for a negative bound or
    /// threshold.
    pub fn point_parameters(&mut self, params: crate::state::PointParams) -> GlResult {
        let p = params;
        self.require(p.size_min >= 0.0 && p.size_max >= 0.0 && p.fade_threshold >= 0.0)?;
        self.set(|s| s.point_params = p)
    }

    pub fn point_size(&mut self, size: f32) -> GlResult {
        self.require(size > 0.0)?;
        self.set(|s| s.point_size = size)
    }

    /// `glLineWidth`; `InvalidValue` unless positive.
    pub fn line_width(&mut self, width: f32) -> GlResult {
        self.require(width > 0.0)?;
        self.set(|s| s.line_width = width)
    }

    /// `glLineStipple`: `factor` clamped to `[1, 256]`.
    pub fn line_stipple(&mut self, factor: i32, pattern: u16) -> GlResult {
        self.set(|s| (s.line_stipple_factor, s.line_stipple_pattern) = (factor.clamp(1, 256), pattern))
    }

    /// `glPolygonStipple`, the pattern unpacked: row `i` (window `y mod 32 = i`)
    /// with column 0 in bit 31 ([`crate::raster::stipple::unpack`] reads GL's
    /// bitmap layout).
    pub fn polygon_stipple(&mut self, rows: [u32; 32]) -> GlResult {
        self.set(|s| s.polygon_stipple_pattern = rows)
    }

    // ----- per-fragment state -----

    /// `glAlphaFunc`; the reference is clamped to `[0, 1]`.
    pub fn alpha_func(&mut self, func: CompareFunc, reference: f32) -> GlResult {
        let r = if reference.is_nan() {
            0.0
        } else {
            reference.clamp(0.0, 1.0)
        };
        self.set(|s| (s.alpha_func, s.alpha_ref) = (func, r))
    }

    pub fn stencil_func(&mut self, func: CompareFunc, reference: i32, mask: u32) -> GlResult {
        self.set(|s| (s.stencil_func, s.stencil_ref, s.stencil_value_mask) = (func, reference, mask))
    }

    pub fn stencil_op(&mut self, fail: StencilOp, zfail: StencilOp, zpass: StencilOp) -> GlResult {
        self.set(|s| (s.stencil_fail, s.stencil_zfail, s.stencil_zpass) = (fail, zfail, zpass))
    }

    pub fn stencil_mask(&mut self, mask: u32) -> GlResult {
        self.set(|s| s.stencil_write_mask = mask)
    }

    pub fn depth_func(&mut self, func: CompareFunc) -> GlResult {
        self.set(|s| s.depth_func = func)
    }

    pub fn depth_mask(&mut self, write: bool) -> GlResult {
        self.set(|s| s.depth_write = write)
    }

    /// `glBlendFunc`; `SrcAlphaSaturate` is a source factor only (`InvalidEnum` as destination).
    pub fn blend_func(&mut self, src: BlendFactor, dst: BlendFactor) -> GlResult {
        self.blend_func_separate(src, dst, src, dst)
    }

    pub fn blend_func_separate(
        &mut self,
        src_rgb: BlendFactor,
        dst_rgb: BlendFactor,
        src_alpha: BlendFactor,
        dst_alpha: BlendFactor,
    ) -> GlResult {
        self.outside()?;
        if !crate::state::valid_dst_factor(dst_rgb) || !crate::state::valid_dst_factor(dst_alpha) {
            return self.record(Err(GlError::InvalidEnum));
        }
        let b = &mut self.state.get_mut().blend_func;
        (b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha) = (src_rgb, dst_rgb, src_alpha, dst_alpha);
        Ok(())
    }

    pub fn blend_equation(&mut self, eq: BlendEquation) -> GlResult {
        self.blend_equation_separate(eq, eq)
    }

    pub fn blend_equation_separate(&mut self, rgb: BlendEquation, alpha: BlendEquation) -> GlResult {
        self.set(|s| (s.blend_func.eq_rgb, s.blend_func.eq_alpha) = (rgb, alpha))
    }

    /// `glBlendColor`, clamped to `[0, 1]`.
    pub fn blend_color(&mut self, r: f32, g: f32, b: f32, a: f32) -> GlResult {
        self.set(|s| s.blend_color = [r, g, b, a].map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) }))
    }

    /// The blend factors and equations in force.
    pub fn blend_state(&self) -> BlendKey {
        self.state.blend_func
    }

    pub fn logic_op(&mut self, op: LogicOp) -> GlResult {
        self.set(|s| s.logic_op = op)
    }

    pub fn color_mask(&mut self, r: bool, g: bool, b: bool, a: bool) -> GlResult {
        self.set(|s| s.color_mask = ColorMask { r, g, b, a })
    }

    // ----- lighting and clip planes -----

    /// `glLight` on light `index` (`InvalidEnum` from 8 on); positions and
    /// spot directions are transformed by the modelview in force.
    pub fn light(&mut self, index: u32, param: LightParam) -> GlResult {
        self.outside()?;
        let mv = *self.modelview.top();
        let r = self.state.get_mut().lighting.set_light(index, param, &mv);
        self.record(r)
    }

    /// `glGetLight`: positions and directions in eye coordinates.
    pub fn get_light(&mut self, index: u32, name: LightParamName) -> GlResult<LightParam> {
        self.outside()?;
        let r = self.state.lighting.light(index, name);
        self.record(r)
    }

    pub fn light_model(&mut self, param: LightModelParam) -> GlResult {
        self.set(|s| s.lighting.set_model(param))
    }

    /// `glMaterial`, also between `begin` and `end`, where it sets the
    /// material of the vertices that follow, as Mesa's vertex attributes do.
    pub fn material(&mut self, face: Face, param: MaterialParam) -> GlResult {
        let before = self.state.lighting.materials;
        let r = self.state.get_mut().lighting.set_material(face, param);
        self.record(r)?;
        let after = self.state.lighting.materials;
        if let Some(b) = &mut self.begun {
            if after != before {
                if b.materials.is_empty() {
                    b.materials.push(before);
                }
                // A primitive with more distinct materials than u16 indices
                // keeps the last one for the rest.
                if b.materials.len() <= usize::from(u16::MAX) {
                    b.materials.push(after);
                }
                b.shininess_varies |= matches!(param, MaterialParam::Shininess(_));
            }
        }
        Ok(())
    }

    /// The lighting of each material in `materials` (see [`Begun`]), for
    /// the draw about to happen.
    fn vertex_materials(&self, materials: &[[Material; 2]], shininess_varies: bool) -> Vec<LightSetup> {
        if materials.is_empty() || !self.state.lighting.enabled {
            return Vec::new();
        }
        let eye_coords = self.tex_units.need_eye_coords(self.draw_plan().1.tex);
        let base = LightSetup::with_eye_coords(&self.state.lighting, self.modelview.top(), eye_coords);
        materials
            .iter()
            .map(|m| base.with_materials(&self.state.lighting, m, shininess_varies))
            .collect()
    }

    /// `glGetMaterial` of `Front` or `Back`.
    pub fn get_material(&mut self, face: Face, name: MaterialParamName) -> GlResult<MaterialParam> {
        self.outside()?;
        let r = self.state.lighting.material(face, name);
        self.record(r)
    }

    /// `glColorMaterial`; with `ColorMaterial` on, the material follows the
    /// current colour at once.
    pub fn color_material(&mut self, face: Face, mode: ColorMaterialMode) -> GlResult {
        let color = self.current.color;
        self.set(|s| {
            (s.lighting.color_material_face, s.lighting.color_material_mode) = (face, mode);
            s.lighting.track_color(color);
        })
    }

    /// Replaces the whole lighting and clip plane state, values as stored
    /// (eye coordinates): how `glPopAttrib` restores it.
    pub fn restore_lighting(&mut self, lighting: crate::lighting::LightingState) -> GlResult {
        self.set(|s| s.lighting = lighting)
    }

    /// `glClipPlane`: `plane` in object coordinates, kept in eye coordinates.
    pub fn clip_plane(&mut self, index: u32, plane: [f64; 4]) -> GlResult {
        self.outside()?;
        let mv = *self.modelview.top();
        let r = self.state.get_mut().lighting.set_clip_plane(index, plane, &mv);
        self.record(r)
    }

    /// `glGetClipPlane`: the plane in eye coordinates.
    pub fn get_clip_plane(&mut self, index: u32) -> GlResult<[f64; 4]> {
        self.outside()?;
        let r = self
            .state
            .lighting
            .clip_planes
            .get(index as usize)
            .copied()
            .ok_or(GlError::InvalidEnum);
        self.record(r)
    }

    // ----- immediate mode -----

    /// `glBegin`; `InvalidOperation` when already inside `begin`.
    pub fn begin(&mut self, mode: PrimitiveMode) -> GlResult {
        if self.begun.is_some() {
            return self.record(Err(GlError::InvalidOperation));
        }
        self.format.begin();
        // The storage of the last primitive, emptied: no allocation per glBegin.
        let (verts, materials, tex) = std::mem::take(&mut self.spare);
        self.begun = Some(Begun {
            mode,
            verts,
            materials,
            shininess_varies: false,
            tex,
            tex_units: self.stored_tex_units(),
        });
        Ok(())
    }

    /// `glEnd`: draws the vertices given since `begin`.
    pub fn end(&mut self) -> GlResult {
        let Some(b) = self.begun.take() else {
            return self.record(Err(GlError::InvalidOperation));
        };
        self.format.end(b.verts.len());
        let current = self.current.tex_coords;
        let tex = |i: usize, u: usize| b.tex.get(i).map_or(current[u], |t| t[u]);
        let r = self.draw_begun(b.mode, &b.verts, (&b.materials, b.shininess_varies), &tex, false);
        let Begun {
            mut verts,
            mut materials,
            mut tex,
            ..
        } = b;
        verts.clear();
        materials.clear();
        tex.clear();
        self.spare = (verts, materials, tex);
        r
    }

    /// The draw at `end` of `verts` (texture coordinates `tex(i, unit)`),
    /// with the per-vertex materials `glMaterial` gave between; `indexed`
    /// for a display list's run, which llvmpipe draws as indexed vertices.
    fn draw_begun(
        &mut self,
        mode: PrimitiveMode,
        verts: &[InVertex],
        (materials, shininess_varies): (&[[Material; 2]], bool),
        tex: &dyn Fn(usize, usize) -> Vec4,
        indexed: bool,
    ) -> GlResult {
        let varying = Varying {
            color: self.format.has(immediate::COLOR),
            secondary: self.format.has(immediate::SECONDARY),
        };
        let source = if indexed {
            DrawSource::Elements
        } else {
            DrawSource::Arrays {
                per_vertex_color: varying.color,
            }
        };
        let vertex_materials = self.vertex_materials(materials, shininess_varies);
        self.draw_with(
            (mode, source),
            verts.len(),
            (Vertices::Slice(verts), tex),
            &vertex_materials,
            varying,
        )
    }

    /// A display list's `glBegin` … `glEnd` run: the same as its calls
    /// (vertices, current attributes, vertex format, errors), drawn from
    /// its arrays with no call per vertex. Between `begin` and `end`, or for
    /// a run without its `glEnd`, it makes the calls one by one.
    pub fn draw_run(&mut self, run: &ImmediateRun) -> GlResult {
        if self.begun.is_some() || !run.ended() {
            return run.replay(self);
        }
        let before = self.current;
        let mut verts = std::mem::take(&mut self.spare.0);
        // A long run of filled triangles or quads rendered (not selected or
        // fed back) leaves out its chunks wholly outside the view volume,
        // whose primitives would make nothing (`ImmediateRun::visible_chunks`).
        let mut kept = Vec::new();
        let cull = self.render_mode.mode == crate::select::RenderMode::Render
            && [true, false]
                .iter()
                .all(|&front| self.state.polygon_mode(front) == crate::state::PolygonMode::Fill)
            && run.visible_chunks(&(*self.projection.top() * *self.modelview.top()), &mut kept);
        if cull {
            run.fill_chunks(&before, &kept, &mut verts);
        } else {
            run.fill(&before, &mut verts);
        }
        // The run's vertex `i` of `verts`'s vertex `k`.
        let chunk = crate::immediate::CULL_CHUNK;
        let index = |k: usize| match cull {
            true => kept.get(k / chunk).map_or(k, |&c| c as usize * chunk + k % chunk),
            false => k,
        };
        self.format.run(run.color_at(), run.len());
        run.apply_last(&mut self.current);
        if run.color_at().is_some() && self.state.lighting.color_material {
            self.track_color_material();
        }
        let units = self.stored_tex_units();
        let current = self.current.tex_coords;
        let before0 = before.tex_coords[0];
        let tex = |i: usize, u: usize| {
            if units == 0 || u != 0 {
                current[u]
            } else {
                run.tex_at(index(i)).unwrap_or(before0)
            }
        };
        // Mesa compiles a list's glBegin/glEnd into indexed vertices
        // (`vbo/vbo_save_api.c`, `compile_vertex_list`) and replays them on
        // the glDrawElements path: quads split v1-v3 (docs/llvmpipe-facts.md
        // §12, §37).
        let r = self.draw_begun(run.mode(), &verts, (&[], false), &tex, true);
        verts.clear();
        self.spare.0 = verts;
        r
    }

    /// `glVertex4f`: outside `begin`/`end` it is ignored, as in GL.
    #[inline]
    pub fn vertex4(&mut self, x: f32, y: f32, z: f32, w: f32) {
        if let Some(b) = &mut self.begun {
            // Written straight into the buffer when it has room (the
            // common case, where the compiler then sees no call to grow it
            // and reads the current attributes into the vertex in place:
            // read before a possible call, they went through the stack).
            let c = &self.current;
            let material = b.materials.len().saturating_sub(1) as u16;
            let pos = Vec4::new(x, y, z, w);
            if b.verts.len() < b.verts.capacity() {
                b.verts.push(c.vertex(pos, material));
            } else {
                push_growing(&mut b.verts, c.vertex(pos, material));
            }
            self.format.vertex();
            if b.tex_units != 0 {
                b.tex.push(self.current.tex_coords);
            }
        }
    }

    #[inline]
    pub fn vertex3(&mut self, x: f32, y: f32, z: f32) {
        self.vertex4(x, y, z, 1.0)
    }

    #[inline]
    pub fn vertex2(&mut self, x: f32, y: f32) {
        self.vertex4(x, y, 0.0, 1.0)
    }

    #[inline]
    pub fn color4(&mut self, r: f32, g: f32, b: f32, a: f32) {
        self.current.color = Vec4::new(r, g, b, a);
        // (Checked here so that the call, and its loop, stay out of the
        // inlined attribute call while `GL_COLOR_MATERIAL` is off.)
        if self.state.lighting.color_material {
            self.track_color_material();
        }
        self.format.attrib(immediate::COLOR, self.begun.is_some());
    }

    /// `GL_COLOR_MATERIAL`'s materials follow the current colour.
    #[cold]
    #[inline(never)]
    fn track_color_material(&mut self) {
        self.state.get_mut().lighting.track_color(self.current.color);
    }

    #[inline]
    pub fn color3(&mut self, r: f32, g: f32, b: f32) {
        self.color4(r, g, b, 1.0)
    }

    /// `glNormal3f`: kept as current state for lighting.
    #[inline]
    pub fn normal3(&mut self, x: f32, y: f32, z: f32) {
        self.current.normal = Vec3A::new(x, y, z);
    }

    /// `glIndexf`: the current colour index, kept for `GL_CURRENT_INDEX`
    /// (an RGBA context draws nothing with it).
    #[inline]
    pub fn index(&mut self, c: f32) {
        self.current.index = c;
    }

    /// `glEdgeFlag`: whether the edges that start at the next vertices are
    /// boundary edges (polygon mode `Line`/`Point` draws only those).
    #[inline]
    pub fn edge_flag(&mut self, flag: bool) {
        self.current.edge_flag = flag;
    }

    /// `glSecondaryColor3f` (GL 1.4): the current secondary colour, alpha 1.
    #[inline]
    pub fn secondary_color3(&mut self, r: f32, g: f32, b: f32) {
        self.current.secondary = Vec4::new(r, g, b, 1.0);
        self.format.attrib(immediate::SECONDARY, self.begun.is_some());
    }

    /// `glFogCoordf` (GL 1.4): the current fog coordinate.
    #[inline]
    pub fn fog_coord(&mut self, c: f32) {
        self.current.fog_coord = c;
    }

    /// `glFog*`: one fog parameter; a negative density is `InvalidValue`.
    pub fn fog(&mut self, p: FogParam) -> GlResult {
        self.outside()?;
        let mut fog = self.state.fog;
        self.record(fog.set(p))?;
        self.state.get_mut().fog = fog;
        Ok(())
    }

    /// The fog state (`glGet` of `GL_FOG_*`).
    pub fn fog_state(&self) -> &FogState {
        &self.state.fog
    }

    /// `glTexCoord4f`: unit 0's current texture coordinates.
    pub fn tex_coord4(&mut self, s: f32, t: f32, r: f32, q: f32) {
        self.tex_coord([s, t, r, q]);
    }

    pub fn tex_coord2(&mut self, s: f32, t: f32) {
        self.tex_coord4(s, t, 0.0, 1.0)
    }

    // ----- vertex arrays -----

    /// `glDrawArrays`: vertices `first..first + count` of `arrays`.
    pub fn draw_arrays(
        &mut self,
        mode: PrimitiveMode,
        first: usize,
        count: usize,
        arrays: &VertexArrays<'_>,
    ) -> GlResult {
        self.outside()?;
        let len = self.record(arrays.check())?;
        let end = first.checked_add(count).filter(|&e| e <= len);
        self.require(end.is_some())?;
        let current = self.current;
        let varying = Varying::of(arrays);
        let source = DrawSource::Arrays {
            per_vertex_color: varying.color,
        };
        let tex = |i: usize, u: usize| fetch_tex(arrays, first + i, u, &current);
        let fetch: Fetch<'_> = (Vertices::Fetch(&|i| fetch(arrays, first + i, &current)), &tex);
        self.draw_with((mode, source), count, fetch, &[], varying)
    }

    /// `glDrawElements`: the vertices of `arrays` that `indices` name, in order.
    /// An index past the end of an array is `InvalidValue` (GL leaves it undefined).
    pub fn draw_elements(&mut self, mode: PrimitiveMode, indices: Indices<'_>, arrays: &VertexArrays<'_>) -> GlResult {
        self.outside()?;
        let len = self.record(arrays.check())?;
        self.require(indices.iter().all(|i| i < len))?;
        let current = self.current;
        let source = (mode, DrawSource::Elements);
        let tex = |k: usize, u: usize| fetch_tex(arrays, indices.get(k), u, &current);
        let fetch: Fetch<'_> = (Vertices::Fetch(&|k| fetch(arrays, indices.get(k), &current)), &tex);
        self.draw_with(source, indices.len(), fetch, &[], Varying::of(arrays))
    }

    // ----- drawing -----

    /// The fragment key and the varying layout a draw made now would use,
    /// both decided from the current state: the key's shading stage
    /// interpolates what the layout carries. (The draw itself may then make
    /// colours that are not per vertex constant, `uniform_colors`, §20.)
    pub fn draw_plan(&self) -> (FragmentKey, VaryingLayout) {
        let (key, layout, _) = self.draw_plan_textured();
        (key, layout)
    }

    /// [`Context::draw_plan`] with the textures the draw samples: the units
    /// with an enabled target whose texture is complete, when a stage reads
    /// the fragment colour.
    fn draw_plan_textured(&self) -> (FragmentKey, VaryingLayout, TexturePlan<'_>) {
        let textures = (&*self.tex_units, &*self.textures);
        plan(&self.state, &self.fb, self.ordered_dither, textures)
    }

    /// Draws `count` vertices with the per-vertex materials of `begin`/`end`
    /// (none for arrays), the colours `varying` says vary per vertex.
    fn draw_with(
        &mut self,
        mode: (PrimitiveMode, DrawSource),
        count: usize,
        fetch: Fetch<'_>,
        vertex_materials: &[LightSetup],
        varying: Varying,
    ) -> GlResult {
        self.ensure_draw()?;
        if self.fbo.draw != 0 {
            self.sync_sampled();
        }
        // GL_MULTISAMPLE off in a multisampled framebuffer: llvmpipe tests
        // and writes depth and stencil in sample 0 only (`lp_state_fs.c`,
        // the depth pointer not moved per sample; docs/llvmpipe-facts.md §29).
        // The draw runs at once with samples 1.. given sample 0's depth and
        // stencil, and theirs put back after it (`Context::one_sample_tests`):
        // this state alone pays for it, and only while the samples' depth
        // and stencil may differ (MuJoCo's depth mode clears and then draws
        // everything with GL_MULTISAMPLE off: no copies; 12x faster).
        let multisampled = self.render_mode.mode == crate::select::RenderMode::Render && self.fb.samples() > 1;
        if multisampled && self.state.multisample.enabled {
            self.samples_same = [None; 2];
        }
        let one_sample = multisampled && !self.state.multisample.enabled && !self.samples_alike_for(mode.0);
        let saved = if one_sample {
            let r = self.fb.bounds();
            self.one_sample_tests(Some(r))
        } else {
            None
        };
        let r = self.draw_planned(mode, count, fetch, vertex_materials, varying);
        if saved.is_some() {
            self.end_one_sample_tests(saved);
        }
        r
    }

    /// Whether a draw of `mode` with `GL_MULTISAMPLE` off finds every
    /// sample's depth and stencil alike wherever it can write: filled
    /// polygons stay inside the viewport (and the scissor box), which must
    /// lie where a clear made the samples equal.
    fn samples_alike_for(&self, mode: PrimitiveMode) -> bool {
        use PrimitiveMode::*;
        let s = &self.state;
        let filled = matches!(
            mode,
            Triangles | TriangleStrip | TriangleFan | Quads | QuadStrip | Polygon
        ) && s.polygon_mode(true) == crate::state::PolygonMode::Fill
            && s.polygon_mode(false) == crate::state::PolygonMode::Fill;
        if !filled {
            return false;
        }
        let v = s.viewport;
        let reach = self
            .fb
            .clip_rect(i64::from(v.x), i64::from(v.y), i64::from(v.width), i64::from(v.height))
            .intersect(self.scissored_bounds());
        // Only the buffers a test reads matter (`one_sample_tests` copies none without one).
        let tested = [s.depth_test, s.stencil_test && self.fb.has_stencil()];
        reach.is_empty()
            || tested
                .iter()
                .zip(self.samples_same)
                .all(|(&t, same)| !t || same.is_some_and(|r| r.intersect(reach) == reach))
    }

    /// [`Context::draw_with`] once the framebuffer is ready.
    fn draw_planned(
        &mut self,
        mode: (PrimitiveMode, DrawSource),
        count: usize,
        (fetch, tex): Fetch<'_>,
        vertex_materials: &[LightSetup],
        varying: Varying,
    ) -> GlResult {
        let made_of = (
            self.state.generation(),
            self.tex_units.generation(),
            self.textures.generation(),
            (*self.fb.desc(), self.fb.color_enabled()),
            self.ordered_dither,
        );
        let (mut key, mut layout, textures, uniforms) = match self.plan_cache {
            Some(c) if c.made_of == made_of => (c.key, c.layout, TexturePlan::default(), c.uniforms),
            _ => {
                let textures = (&*self.tex_units, &*self.textures);
                let (key, layout, textures) = plan(&self.state, &self.fb, self.ordered_dither, textures);
                let uniforms = self.state.fragment_uniforms();
                self.plan_cache = (textures.mask == 0).then_some(CachedPlan {
                    made_of,
                    key,
                    layout,
                    uniforms,
                });
                (key, layout, textures, uniforms)
            }
        };
        // Unlit colours that do not vary are llvmpipe's uniforms (§20): constant
        // planes of the vertices' (equal, clamped) values, read as flat colours.
        // A constant colour summed with a varying secondary one (or the reverse)
        // stays interpolated: the key has one flat flag for both.
        if self.render_mode.mode == crate::select::RenderMode::Feedback {
            // Mesa's fixed-function vertex program writes the colour and unit
            // 0's coordinates in feedback mode (`ffvertex_prog.c`).
            layout.color = true;
            layout.tex |= 1;
        }
        let varies = varying.color || (layout.secondary && varying.secondary);
        let uniform = !self.state.lighting.enabled && !varies;
        if uniform && layout.color {
            layout.uniform_colors = true;
            if let Some(shade) = key.shade.as_mut() {
                shade.flat = true;
            }
        }
        // A multisampled draw: the scene records it for every sample when
        // they share its shading (`multisample::shared_halves`), else each
        // sample's lane records it.
        let multisampled = self.render_mode.mode == crate::select::RenderMode::Render && !self.fb.samples.is_empty();
        let share = multisampled
            && self.msaa_share
            && self.fb.samples() == crate::multisample::MAX_SAMPLES
            && self.state.multisample.enabled
            && !self.state.polygon_stipple
            && crate::multisample::shares_shading(&key);
        if multisampled && self.shared != share {
            // (`share_samples`, with the draw's textures borrowed.)
            let r = Self::finish_fields(
                (&mut self.fb, &mut self.scene, &mut self.background),
                &mut self.lanes,
                self.threads,
                self.shared,
            );
            if r.is_err() {
                self.error.get_or_insert(GlError::InvalidOperation);
            }
            self.shared = share;
        }
        let reads_depth = key.depth.is_some();
        let mv = self.modelview.top();
        let mut vertex_stage = VertexStage::new(*self.projection.top() * *mv, layout);
        if self.state.fog.coord_src == FogCoordSrc::FragmentDepth {
            vertex_stage.fog = FogSource::EyeDepth { row: mv.row(2) };
        }
        let lit = layout.color || layout.secondary;
        let lighting = &self.state.lighting;
        let eye_coords = self.tex_units.need_eye_coords(layout.tex);
        if lighting.enabled && lit {
            vertex_stage.lighting = Some(LightSetup::with_eye_coords(lighting, mv, eye_coords));
            vertex_stage.vertex_materials = vertex_materials;
        }
        let tex_coords = TexCoordStage::new(&self.tex_units, &layout, mv, lighting);
        vertex_stage.tex_coords = tex_coords.as_ref().map(|t| (t, TexFetch(tex)));
        let mut geometry = Geometry::new(&self.state, &self.fb, reads_depth, layout);
        geometry.set_user_planes(self.projection.top());
        geometry.set_point_projection(self.projection.top());
        // The framebuffer may be hollow (its buffers with a background
        // flush): the key is checked against its formats.
        let fb = &self.fb;
        if key.validate().is_err()
            || (key.color_format, key.depth_format, key.stencil_buffer)
                != (fb.color_format(), fb.depth_format(), fb.has_stencil())
        {
            return self.record(Err(GlError::InvalidOperation));
        }
        if self.render_mode.mode != crate::select::RenderMode::Render {
            // Select or feedback: the primitives are recorded, not rasterized.
            geometry.recording = true;
            let current = (self.current.color, self.current.tex_coords[0]);
            let mut sink = self.render_mode.sink(layout, current.0, current.1);
            geometry.draw(&vertex_stage, mode, count, fetch, &mut sink, &mut self.window);
            return Ok(());
        }
        // An active occlusion query: the draw's fragments are counted into its counter.
        let samples = self.queries.counter();
        key.count = samples.is_some();
        let specialist = match self.backend {
            Backend::Jit => self.specialists.get(&key).cloned(),
            Backend::Interpreter => None,
        };
        let state = DrawState {
            key,
            uniforms,
            specialist,
            textures: textures.share(),
            samples,
            polygon_stipple: self
                .state
                .polygon_stipple
                .then(|| Box::new(self.state.polygon_stipple_pattern)),
            shades_samples: false,
        };
        if !self.fb.samples.is_empty() {
            // A multisampled framebuffer: the geometry runs once, each
            // primitive is recorded into the scene of each sample that
            // `glSampleCoverage` keeps, covered at the sample when
            // `GL_MULTISAMPLE` is on (at the pixel centre when off).
            let ms = self.state.multisample;
            let n = self.fb.samples();
            let mask = match (ms.enabled, ms.coverage) {
                (true, true) => crate::multisample::sample_coverage_mask(ms.coverage_value, ms.coverage_invert, n),
                _ => u32::MAX,
            };
            let window = self.fb.window_samples;
            let at = |s: usize| ms.enabled.then(|| crate::multisample::SampleAt::of_4x_in(s, window));
            if share {
                let (backend, specialists) = (self.backend, &mut self.specialists);
                let halves = crate::multisample::shared_halves(&state, |k| match backend {
                    Backend::Jit => specialists.get(k).cloned(),
                    Backend::Interpreter => None,
                });
                if let Some((shading, ops)) = halves {
                    let at = std::array::from_fn(|s| crate::multisample::SampleAt::of_4x_in(s, window));
                    let binner = self
                        .scene
                        .draw_shared(&mut self.fb, &mut self.background, self.threads, shading, ops);
                    let mut fan = crate::multisample::SharedFan {
                        binner,
                        at,
                        mask: mask & 0xf,
                    };
                    geometry.draw(&vertex_stage, mode, count, fetch, &mut fan, &mut self.window);
                    let r = fan.finish();
                    return self.record(r.map_err(|_| GlError::InvalidOperation));
                }
            }
            let mut samples = std::mem::take(&mut self.fb.samples);
            let mut fan = crate::multisample::Fan::default();
            // Alpha to coverage: each sample's key has its own threshold.
            let a2c = state.key.shade.is_some_and(|s| s.coverage.quarters.is_some());
            let (backend, specialists) = (self.backend, &mut self.specialists);
            let mut sample_state = |s: usize| {
                let mut st = state.clone();
                if let Some(shade) = st.key.shade.as_mut().filter(|_| a2c) {
                    shade.coverage.quarters = Some(s as u8);
                    st.specialist = match backend {
                        Backend::Jit => specialists.get(&st.key).cloned(),
                        Backend::Interpreter => None,
                    };
                }
                st
            };
            if mask & 1 != 0 {
                let b = self
                    .scene
                    .draw(&mut self.fb, &mut self.background, self.threads, sample_state(0));
                fan.lanes.push((b, at(0)));
            }
            for (s, (lane, fb)) in self.lanes.iter_mut().zip(&mut samples).enumerate() {
                if mask >> (s + 1) & 1 != 0 {
                    let b = lane
                        .scene
                        .draw(fb, &mut lane.background, self.threads, sample_state(s + 1));
                    fan.lanes.push((b, at(s + 1)));
                }
            }
            geometry.draw(&vertex_stage, mode, count, fetch, &mut fan, &mut self.window);
            let r = fan.finish();
            self.fb.samples = samples;
            return self.record(r.map_err(|_| GlError::InvalidOperation));
        }
        let mut binner = self.scene.draw(&mut self.fb, &mut self.background, self.threads, state);
        let s = &*self.state;
        if s.line_stipple && s.line_stipple_pattern != 0xFFFF {
            // Mesa's state tracker leaves an all-ones pattern out (`st_atom_rasterizer.c`).
            let lines = mode.0 == PrimitiveMode::Lines;
            let mut sink = LineStipple::new(&mut binner, s.line_stipple_factor, s.line_stipple_pattern, lines);
            geometry.draw(&vertex_stage, mode, count, fetch, &mut sink, &mut self.window);
        } else {
            geometry.draw(&vertex_stage, mode, count, fetch, &mut binner, &mut self.window);
        }
        let r = binner.finish();
        self.record(r.map_err(|_| GlError::InvalidOperation))
    }

    /// `glFlush`/`glFinish`: rasterizes every draw recorded so far. Like
    /// Mesa's flush of the vertices it buffers, it ends the immediate-mode
    /// vertex format (`docs/llvmpipe-facts.md` §20).
    pub fn flush(&mut self) -> GlResult {
        self.outside()?;
        self.finish_scene();
        Ok(())
    }

    /// `glAccum`: `InvalidOperation` without an accumulation buffer (see
    /// [`crate::accum`] for what each operation does).
    pub fn accum(&mut self, op: AccumOp, value: f32) -> GlResult {
        self.outside()?;
        self.acquire_deferred();
        if !self.fb.has_accum() {
            return self.record(Err(GlError::InvalidOperation));
        }
        self.finish_scene();
        let rect = self.scissored_bounds();
        let mask = self.state.color_mask;
        crate::accum::apply(&mut self.fb, op, value, rect, mask);
        Ok(())
    }

    // ----- reading -----

    /// `glReadPixels` into bytes, rows bottom-up; a multisampled framebuffer
    /// (a window's) is read resolved ([`Framebuffer::resolve`]).
    pub fn read_pixels(&mut self, x: i32, y: i32, w: i32, h: i32, format: ReadFormat) -> GlResult<Vec<u8>> {
        let r = self.with_read_framebuffer(true, |fb| match fb.samples() {
            1 => fb.read_pixels(x, y, w, h, format),
            _ => fb.resolve().and_then(|fb| fb.read_pixels(x, y, w, h, format)),
        })?;
        let r = r.map(|mut bytes| {
            if !self.pixel.is_identity() {
                self.pixel.transfer_read(&mut bytes, format);
            }
            bytes
        });
        self.record(r)
    }

    /// `glReadPixels` with `GL_FLOAT`, rows bottom-up (resolved, as [`Context::read_pixels`]).
    pub fn read_pixels_f32(&mut self, x: i32, y: i32, w: i32, h: i32) -> GlResult<Vec<[f32; 4]>> {
        let r = self.with_read_framebuffer(true, |fb| match fb.samples() {
            1 => fb.read_pixels_f32(x, y, w, h),
            _ => fb.resolve().and_then(|fb| fb.read_pixels_f32(x, y, w, h)),
        })?;
        let r = r.map(|mut px| {
            if !self.pixel.is_identity() {
                px.iter_mut().for_each(|c| *c = self.pixel.cpu_colour(*c));
            }
            px
        });
        self.record(r)
    }

    /// `glSampleCoverage`: the value is clamped to `[0, 1]` (NaN reads as 0).
    pub fn sample_coverage(&mut self, value: f32, invert: bool) -> GlResult {
        let value = if value.is_nan() { 0.0 } else { value.clamp(0.0, 1.0) };
        self.set(|s| {
            s.multisample.coverage_value = value;
            s.multisample.coverage_invert = invert;
        })
    }

    /// `GL_SAMPLES`: samples a pixel of the framebuffer (1 when single-sampled;
    /// GL reports 0 then, and `GL_SAMPLE_BUFFERS` 0).
    pub fn samples(&self) -> u32 {
        // An object waiting for its first use: its depth texture (one
        // sample) makes it single-sampled.
        if self.fbo.deferred {
            return 1;
        }
        self.fb.samples()
    }

    // ----- selection and feedback (select.rs) -----

    /// The units whose coordinates `begin`/`end` keeps per vertex: the
    /// enabled ones, and unit 0 in feedback mode (which writes them).
    fn stored_tex_units(&self) -> u8 {
        let feedback = self.render_mode.mode == crate::select::RenderMode::Feedback;
        self.tex_units.enabled_mask() | u8::from(feedback)
    }

    /// `glRenderMode`: the hits or values of the mode left (−1 on
    /// overflow) and what it wrote into its buffer.
    pub fn render_mode(&mut self, mode: crate::select::RenderMode) -> GlResult<(i32, crate::select::ModeOutput)> {
        self.outside()?;
        let (r, output, error) = self.render_mode.set_mode(mode);
        if let Some(e) = error {
            self.record_error(e);
        }
        Ok((r, output))
    }

    /// Render mode, selection and feedback state (`GL_RENDER_MODE`, the buffers).
    pub fn render_mode_state(&self) -> &crate::select::RenderModeState {
        &self.render_mode
    }

    /// `glSelectBuffer` of `size` values (the values land in
    /// [`Context::render_mode_state`]'s `select.buffer`).
    pub fn select_buffer(&mut self, size: i32) -> GlResult {
        self.outside()?;
        let r = self.render_mode.select_buffer(size);
        self.record(r)
    }

    /// `glFeedbackBuffer` of `size` values of type `ty`.
    pub fn feedback_buffer(&mut self, size: i32, ty: crate::select::FeedbackType) -> GlResult {
        self.outside()?;
        let r = self.render_mode.feedback_buffer(size, ty);
        self.record(r)
    }

    /// `glInitNames`.
    pub fn init_names(&mut self) -> GlResult {
        self.outside()?;
        self.render_mode.init_names();
        Ok(())
    }

    /// `glLoadName`.
    pub fn load_name(&mut self, name: u32) -> GlResult {
        self.outside()?;
        let r = self.render_mode.load_name(name);
        self.record(r)
    }

    /// `glPushName`.
    pub fn push_name(&mut self, name: u32) -> GlResult {
        self.outside()?;
        let r = self.render_mode.push_name(name);
        self.record(r)
    }

    /// `glPopName`.
    pub fn pop_name(&mut self) -> GlResult {
        self.outside()?;
        let r = self.render_mode.pop_name();
        self.record(r)
    }

    /// `glPassThrough`.
    pub fn pass_through(&mut self, token: f32) -> GlResult {
        self.outside()?;
        self.render_mode.pass_through(token);
        Ok(())
    }
}
