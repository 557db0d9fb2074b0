//! Deferred, binned rendering: a draw is transformed, clipped and culled at
//! once (so its GL errors and the state it reads are the call's), and its
//! primitives are recorded with what their fragments run with, and binned
//! into 64×64 tiles. A flush rasterizes the tiles: each row of tiles (a band
//! of 64 framebuffer rows) is owned by one thread for the whole flush and
//! runs its tiles left to right, each tile its commands in the order they
//! were recorded, so the bytes are the same for any number of threads.
//! Clears are recorded per tile too and run as part of the tile's work,
//! while its pixels are in cache.
//!
//! A triangle is set up when it is recorded (its coverage, box and
//! attribute planes, once, however many tiles it touches; one with no pixel
//! inside is dropped there) and written as one record of 32-bit words, the
//! records one after the other in the order recorded: its class (the draw,
//! what the flush reads of its parameters and the slots of its planes, kept
//! once for all the triangles that share them, [`Class`]), its coverage
//! ([`Prepared::encode`]: the box as four u16, a mask or the vertices) and
//! its planes, 12 bytes each. A lit triangle of a pixel or two is 84 or 92
//! bytes (it was 240: a 64-byte entry, an 80-byte set-up and six 16-byte
//! planes, each in its own array), and a strip's triangles are read back in
//! one pass, in the order written, which the hardware prefetches. `fill.c
//! lit16` (1.6 M triangles of about 0.7 pixels), one thread: 2437 M → 2499 M
//! instructions a frame (callgrind: decoding and appending the record cost
//! more than they save) but 271 → 233 ms (the fastest of 5 interleaved runs
//! each, a loaded machine): the flush stalled reading back the scene. Within
//! a tile the coverage is cut to the tile and the planes copied to the
//! fragment stage. Lines and points are
//! recorded with their vertices and rasterized by the row rasterizer with
//! their bounds cut to the tile. Either way coverage decides each pixel on
//! its own, so the pixels are those of the whole primitive at once.
//!
//! A multisampled draw whose samples share their shading
//! ([`Scene::draw_shared`], `multisample.rs`) records each triangle once
//! for the four samples: a word naming the samples with a pixel inside,
//! then each one's record as above (its coverage at the sample, its planes
//! with depth moved to the sample), binned once ([`GROUP`]). Such a scene
//! is flushed with every sample's buffers (its clears clear them all), and
//! a tile runs the triangle's shading half once, into a band's RGBA8 and
//! stencil target, over the union of the samples' coverage, and its
//! per-sample half into each sample's band ([`Scene::run_group`]).

use super::background::Background;
use super::stipple::PolygonStipple;
use super::triangle::{plane_swap, setup_planes, Plane, Prepared};
use super::{reach_box, Edges, PrimSink, RasterParams, RasterVertex, Rasterize, SpanSink};
use crate::fragment::{DrawStage, FragmentStage};
use crate::framebuffer::{Clear, Framebuffer, Rect};
use crate::geometry::varying::{Varyings, MAX_VARYINGS};
use crate::texture::unit::{SharedPlan, TexturePlan};
use softgl_jit::shade::{slot, PLANES};
use softgl_jit::texture::TextureSet;
use softgl_jit::{
    ColorFormat, CompareFunc, DepthFormat, DepthTarget, DrawTextures, FragmentError, FragmentKey, FragmentSpan,
    FragmentUniforms, Planes, Specialist, StencilOp, Target, SPAN_MAX,
};
use std::cell::OnceCell;
use std::collections::HashSet;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, PoisonError};
use wide::u8x16;

/// Side of a tile, in pixels.
pub const TILE: u32 = 64;

/// A scene is flushed past this many bytes, in the background
/// (`raster/background.rs`): the caller records the next scene meanwhile,
/// so a context holds two scenes at most, 32 MiB between them, and a frame
/// of any number of primitives runs in bounded memory. Measured with
/// `fill.c lit16` (1.6 M tiny lit triangles, ~300 bytes of scene each then),
/// medians of 3 interleaved runs, llvmpipe alongside: one thread 124-128
/// ms a frame at 8 and 16 MiB, 128-163 at 32, 134-141 at 64 (llvmpipe
/// 147-167); two threads 122-138 at 16, 124-126 at 32, 131 at 64 (llvmpipe
/// 125-131). Flushed at once on one thread, the scene was best at 8 MiB
/// (191 ms at 64, 173 at 8: read back while still in the cache).
pub const SCENE_BOUND: usize = 16 << 20;

/// A scene is flushed when the texels its draws hold pass this many bytes
/// (each image counted once), as llvmpipe flushes a scene referencing more
/// than `LP_SCENE_MAX_RESOURCE_SIZE` of textures (64 MiB, `lp_scene.h`):
/// a client that uploads, draws with and deletes a new texture each frame
/// without a flush would otherwise pile up every frame's texels (piglit's
/// streaming-texture-leak: 20 GB). As there (`lp_scene_add_resource_reference`),
/// only an image new to a scene that already held draws flushes it: the
/// draw that begins a scene keeps its textures whatever their size. Checked
/// after every primitive instead, a draw whose own textures pass the bound
/// (MuJoCo's light passes: a 4096² depth texture, 64 MiB as f32, and the
/// floor's) flushed the scene after each of its primitives: 9018
/// background flushes in a 320×240 Renderer's set-up and three frames, each
/// waking a pool thread (~12% of the frame in futex and wake-up, `perf`).
pub const TEXTURE_BOUND: usize = 64 << 20;

/// Bin entries with this bit are clears (an index into `clears`); with
/// [`TRI`], triangles (the word of their record in `records`); the others
/// lines and points (an index into `prims`).
const CLEAR: u32 = 1 << 31;
const TRI: u32 = 1 << 30;
/// With [`TRI`]: a triangle of a multisampled draw whose samples share
/// its shading ([`Binner::triangle_shared`]): its word in `records` holds
/// the samples recorded (a bit each), and their records follow.
const GROUP: u32 = 1 << 29;

/// The largest bound a scene is flushed past, so that an index or a word
/// offset in a bin entry or a record's class fits in 30 bits.
const MOST_BYTES: usize = 1 << 30;

/// What a draw's fragments run with.
#[derive(Clone, Debug)]
pub struct DrawState {
    pub key: FragmentKey,
    pub uniforms: FragmentUniforms,
    /// `None`: the interpreter runs the key.
    pub specialist: Option<Arc<Specialist>>,
    pub textures: SharedPlan,
    /// The active occlusion query's counter (with `key.count`): each band
    /// adds the fragments it counted to it.
    pub samples: Option<Arc<AtomicU64>>,
    /// The polygon stipple its triangles are masked with, when enabled.
    pub polygon_stipple: Option<Box<[u32; 32]>>,
    /// The shading half of a multisampled draw whose samples share it
    /// ([`Scene::draw_shared`]): its key writes a band's shading target
    /// (RGBA8 and a stencil marking the fragments the alpha test kept);
    /// the draw after it in the scene is the per-sample half.
    pub shades_samples: bool,
}

/// A recorded vertex's window position, depth and 1/w; its varyings (the
/// layout's, no more) are in [`Scene::vary`].
#[derive(Clone, Copy, Debug)]
struct Vert {
    x: f32,
    y: f32,
    y_down: f32,
    inv_w: f32,
    z: f64,
}

#[derive(Clone, Copy, Debug)]
enum Kind {
    Line {
        width: f32,
    },
    Point {
        size: f32,
    },
    /// A bitmap at the vertex (the raster position): `Scene::bitmaps[index]`.
    Bitmap {
        index: u32,
    },
    /// A pixel rectangle: `Scene::images[index]`.
    Image {
        index: u32,
    },
}

impl Kind {
    fn vertices(self) -> usize {
        match self {
            Kind::Line { .. } => 2,
            Kind::Point { .. } | Kind::Bitmap { .. } | Kind::Image { .. } => 1,
        }
    }
}

impl DrawState {
    /// Whether `other`'s fragments run exactly as this draw's: the same key,
    /// uniforms and specialist, and no textures (textured draws are not
    /// compared: their texels may differ).
    fn same_as(&self, other: &DrawState) -> bool {
        self.key == other.key
            && self.uniforms == other.uniforms
            && match (&self.specialist, &other.specialist) {
                (Some(a), Some(b)) => Arc::ptr_eq(a, b),
                (None, None) => true,
                _ => false,
            }
            && self.textures.is_empty()
            && other.textures.is_empty()
            && match (&self.samples, &other.samples) {
                (Some(a), Some(b)) => Arc::ptr_eq(a, b),
                (None, None) => true,
                _ => false,
            }
            && self.polygon_stipple == other.polygon_stipple
            && !self.shades_samples
            && !other.shades_samples
    }
}

/// A recorded line or point: 64 bytes and its vertices as the geometry
/// stage handed them over (24 bytes and 4 per varying of the layout each,
/// where a copy of its `RasterVertex`es is 224 bytes each: copying those
/// was a fifth of the 1.6 M-triangle lit frame, `perf`).
#[derive(Clone, Copy, Debug)]
struct Binned {
    draw: u32,
    kind: Kind,
    /// Its first vertex in `verts`.
    first: u32,
    /// Where its varyings start in `vary`: `n` (the layout's length) for
    /// each vertex, then `n` flat ones when `flat`.
    vary: u32,
    flat: bool,
    params: RasterParams,
}

/// What the triangles of a draw share while the parameters a flush reads
/// stay the same (the height, the depth format, the layout: see
/// [`Scene::class`]): the draw, the parameters and the slots of their
/// planes (the same for each: `setup_planes` puts the layout's slots, in
/// its order), recorded once, not per triangle.
#[derive(Clone, Copy, Debug)]
struct Class {
    draw: u32,
    params: RasterParams,
    /// The slots of a triangle's planes, `slots[..n]`, in its record's order.
    slots: [u8; PLANES],
    n: u8,
}

/// The most words of a triangle's record: its class and tag, its coverage
/// ([`Prepared::encode`]) and three a plane.
const RECORD: usize = 1 + Prepared::WORDS + 3 * PLANES;

/// Words of a record appended in one fixed-size copy ([`Scene::append`]).
const COPY: usize = 24;

/// Writes a triangle's recorded planes (`planes`: three words a plane,
/// `a0`, `dadx`, `dady`) into their slots of `to`, each coefficient in
/// four lanes (as the specialists load them), inlined with `with_planes`
/// and the sink's `planes_mut` into the tile loop. Not copying them at all
/// needs the specialists to read the recorded planes and splat them
/// themselves.
#[inline(always)]
fn copy_planes(to: &mut Planes, slots: &[u8], planes: &[u32]) {
    let (planes, _) = planes.as_chunks::<3>();
    for (&k, &[a0, dadx, dady]) in slots.iter().zip(planes) {
        if let Some(c) = to.coeffs.get_mut(usize::from(k)) {
            let (a0, dadx, dady) = (f32::from_bits(a0), f32::from_bits(dadx), f32::from_bits(dady));
            *c = [[a0; 4], [dadx; 4], [dady; 4]];
        }
    }
}

/// A band's room to rebuild a primitive's vertices in (reused: no 700
/// bytes zeroed and copied per primitive and tile).
struct Scratch {
    v: [RasterVertex; 3],
    flat: Varyings,
}

impl Default for Scratch {
    fn default() -> Self {
        let v = RasterVertex {
            x: 0.0,
            y: 0.0,
            y_down: 0.0,
            z: 0.0,
            inv_w: 1.0,
            v: [0.0; MAX_VARYINGS],
        };
        Scratch {
            v: [v; 3],
            flat: [0.0; MAX_VARYINGS],
        }
    }
}

/// The draws, primitives and clears recorded since the last flush, binned.
#[derive(Debug, Default)]
pub struct Scene {
    width: u32,
    height: u32,
    tiles_x: u32,
    draws: Vec<DrawState>,
    prims: Vec<Binned>,
    /// The triangles' records, one after the other in the order recorded
    /// (a strip's are read in that order too: the hardware prefetches
    /// them): word 0 its class (the low 30 bits, into `classes`) and the
    /// tag of its coverage (the top 2), then its coverage
    /// ([`Prepared::encode`]), then its planes, three words each, in the
    /// order of the class's slots.
    records: Vec<u32>,
    /// The words of `records` in use: past them the vector holds room
    /// (zeros, or an earlier scene's words, never read), so that a record
    /// is appended as one copy of [`COPY`] words whatever its length.
    used: usize,
    classes: Vec<Class>,
    /// The class of the last triangle recorded.
    class: Option<u32>,
    triangles: usize,
    /// Where a triangle's record is made before it is appended.
    record: Record,
    verts: Vec<Vert>,
    /// The varyings of `verts` and of flat primitives, the layout's slots only.
    vary: Vec<f32>,
    clears: Vec<Clear>,
    /// The bitmaps recorded (`Kind::Bitmap`).
    bitmaps: Vec<crate::pixel_rect::PlacedBitmap>,
    /// The pixel rectangles recorded (`Kind::Image`).
    images: Vec<crate::pixel_rect::PlacedImage>,
    /// Bitmaps merged as Mesa's bitmap cache merges them, not recorded yet
    /// ([`Scene::bitmap`]): recorded before anything else is.
    pending: Option<Box<PendingBitmap>>,
    /// Per tile, row by row from the bottom: entries into `prims`, or into
    /// `clears` with [`CLEAR`] set, in the order recorded.
    bins: Vec<Vec<u32>>,
    bytes: usize,
    /// The texel images the draws hold (by address) and their bytes.
    textures: HashSet<usize>,
    texture_bytes: usize,
    /// An image new to the scene took `texture_bytes` past [`TEXTURE_BOUND`]
    /// after the scene held draws: flush ([`Scene::hold_textures`]).
    textures_full: bool,
    /// See [`Scene::bound`].
    bound: usize,
    peak: usize,
    flushes: u64,
}

impl Scene {
    /// Whether nothing waits to be drawn.
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty() && self.triangles == 0 && self.clears.is_empty() && self.pending.is_none()
    }

    /// Bytes held (primitives, bin entries, draws): the scene is flushed past [`Scene::bound`].
    pub fn bytes(&self) -> usize {
        self.bytes
    }

    /// Primitives recorded since the last flush.
    pub fn primitives(&self) -> usize {
        self.prims.len() + self.triangles
    }

    /// Makes the (empty) scene's tiles cover a `width`×`height` framebuffer.
    fn fit(&mut self, width: u32, height: u32) {
        if (self.width, self.height) != (width, height) || self.bins.is_empty() {
            debug_assert!(self.is_empty(), "a scene is flushed before its framebuffer changes");
            self.width = width;
            self.height = height;
            self.tiles_x = width.div_ceil(TILE).max(1);
            let tiles = self.tiles_x as usize * height.div_ceil(TILE).max(1) as usize;
            // The bins keep their room across sizes (the tiles past this
            // size's stay empty): MuJoCo's frame draws into its 640×480
            // object and its 4096² shadow map in turn, and the map's 4096
            // bins were made again and grown push by push at every pass
            // (`bin_tiles`' `grow_one`, 4.8 M instructions a 320×240 frame).
            for b in &mut self.bins {
                b.clear();
            }
            if self.bins.len() < tiles {
                self.bins.resize_with(tiles, Vec::new);
            }
        }
    }

    /// The tiles `r` touches, as index ranges of columns and rows.
    fn tiles_of(&self, r: Rect) -> (std::ops::Range<u32>, std::ops::Range<u32>) {
        (r.x0 / TILE..r.x1.div_ceil(TILE), r.y0 / TILE..r.y1.div_ceil(TILE))
    }

    /// Bins `entry` into the tiles `r` touches: one tile (most primitives of
    /// a frame of small ones) inline, without the ranges.
    #[inline(always)]
    fn bin(&mut self, r: Rect, entry: u32) {
        let (tx, ty) = (r.x0 / TILE, r.y0 / TILE);
        if r.x1 > r.x0 && r.y1 > r.y0 && (r.x1 - 1) / TILE == tx && (r.y1 - 1) / TILE == ty {
            if let Some(bin) = self.bins.get_mut((ty * self.tiles_x + tx) as usize) {
                bin.push(entry);
                self.bytes += 4;
            }
            return;
        }
        self.bin_tiles(r, entry);
    }

    #[inline(never)]
    fn bin_tiles(&mut self, r: Rect, entry: u32) {
        let (xs, ys) = self.tiles_of(r);
        for ty in ys {
            for tx in xs.clone() {
                self.bins[(ty * self.tiles_x + tx) as usize].push(entry);
                self.bytes += 4;
            }
        }
    }

    /// Records a clear of `fb` (whose size the scene takes).
    pub fn clear(&mut self, fb: &Framebuffer, clear: Clear) {
        self.fit(fb.width(), fb.height());
        self.settle();
        if clear.is_empty() {
            return;
        }
        let entry = CLEAR | self.clears.len() as u32;
        self.clears.push(clear);
        self.bytes += std::mem::size_of::<Clear>();
        self.bin(clear.rect, entry);
    }

    /// Starts recording a draw into `fb` (whose size the scene takes): the
    /// primitives the returned sink receives run with `state`. Past
    /// [`Scene::bound`] bytes the sink flushes the scene into `fb` on
    /// `threads` threads, mid-draw if need be.
    pub fn draw<'s>(
        &'s mut self,
        fb: &'s mut Framebuffer,
        background: &'s mut Background,
        threads: usize,
        state: DrawState,
    ) -> Binner<'s> {
        self.fit(fb.width(), fb.height());
        self.settle();
        Binner {
            scene: self,
            fb,
            background,
            threads,
            state,
            ops: None,
            draw: None,
            error: None,
        }
    }

    /// Starts recording a draw into every sample of the multisampled `fb`
    /// (its samples inside it, as the scene's flush writes them all) whose
    /// samples share its shading: `shade` (a key of
    /// [`DrawState::shades_samples`]) runs once for the pixels any sample
    /// covers, `ops` (a key taking colours from the span) once for each
    /// sample with that sample's coverage and depth, on the fragments the
    /// shading kept. The triangles go to [`Binner::triangle_shared`].
    pub(crate) fn draw_shared<'s>(
        &'s mut self,
        fb: &'s mut Framebuffer,
        background: &'s mut Background,
        threads: usize,
        shade: DrawState,
        ops: DrawState,
    ) -> Binner<'s> {
        let mut b = self.draw(fb, background, threads, shade);
        b.ops = Some(ops);
        b
    }

    /// Bytes past which a draw flushes (unless set: [`SCENE_BOUND`]).
    pub fn bound(&self) -> usize {
        match self.bound {
            0 => SCENE_BOUND,
            set => set,
        }
    }

    /// Sets the bytes past which a draw flushes (0: [`Self::bound`]'s
    /// default), at most `MOST_BYTES` (1 GiB), so that the checked-per-
    /// primitive bound needs no clamp.
    pub fn set_bound(&mut self, bytes: usize) {
        self.bound = bytes.min(MOST_BYTES);
    }

    /// The most bytes held at once since the scene was made, and the flushes run.
    pub fn peak(&self) -> (usize, u64) {
        (self.peak, self.flushes)
    }

    /// Puts `spare` (an emptied scene) in this one's place to record into,
    /// with this one's size, bound and counters (the flush to come counted),
    /// and returns this one, to be flushed on another thread.
    pub(crate) fn swap_out(&mut self, mut spare: Scene) -> Scene {
        self.settle();
        spare.fit(self.width, self.height);
        spare.bound = self.bound;
        spare.peak = self.peak.max(self.bytes);
        spare.flushes = self.flushes + 1;
        std::mem::replace(self, spare)
    }

    /// Runs every tile into `fb` on `threads` threads and empties the scene.
    /// Returns the first error of a fragment stage (in tile order).
    pub fn flush(&mut self, fb: &mut Framebuffer, threads: usize) -> Result<(), FragmentError> {
        self.flush_helped(fb, threads, None)
    }

    /// [`Scene::flush`] on a pool thread in the background
    /// (`raster/background.rs`): the bands run on `threads - 1` threads
    /// (this one among them) until `help` is set (the caller waits for the
    /// flush), then on `threads`.
    pub(crate) fn flush_helped(
        &mut self,
        fb: &mut Framebuffer,
        threads: usize,
        help: Option<&AtomicBool>,
    ) -> Result<(), FragmentError> {
        self.settle();
        if self.is_empty() {
            return Ok(());
        }
        let r = self.run(fb, threads, help);
        self.peak = self.peak.max(self.bytes);
        self.flushes += 1;
        self.draws.clear();
        self.textures.clear();
        self.texture_bytes = 0;
        self.textures_full = false;
        self.prims.clear();
        self.used = 0;
        self.classes.clear();
        self.class = None;
        self.triangles = 0;
        self.verts.clear();
        self.vary.clear();
        self.clears.clear();
        self.bitmaps.clear();
        self.images.clear();
        // This size's tiles (those past it are empty: `fit`).
        let tiles = self.tiles_x as usize * self.height.div_ceil(TILE).max(1) as usize;
        for b in self.bins.iter_mut().take(tiles) {
            b.clear();
        }
        self.bytes = 0;
        r
    }

    /// [`Scene::flush`]es each scene into its framebuffer, all at once on
    /// `threads` threads (each scene's bands too): the four scenes of a 4×
    /// multisampled framebuffer (one a sample, `multisample.rs`), flushed
    /// one after the other, each ended on the slowest of its few bands
    /// (a 320×240 frame has four) while the other thread waited. The
    /// first error, in `jobs`' order.
    pub fn flush_all(jobs: Vec<(&mut Scene, &mut Framebuffer)>, threads: usize) -> Result<(), FragmentError> {
        let busy = jobs.iter().filter(|(s, _)| !s.is_empty()).count();
        let results = if threads <= 1 || busy <= 1 {
            jobs.into_iter().map(|(s, fb)| s.flush(fb, threads)).collect()
        } else {
            super::pool::run(threads, jobs, |(s, fb)| s.flush(fb, threads))
        };
        results.into_iter().fold(Ok(()), Result::and)
    }

    /// Runs the tiles into `fb`, and into its other samples when it has
    /// them (a scene of draws sharing their samples' shading, recorded with
    /// [`Scene::draw_shared`]: its clears clear every sample).
    fn run(&self, fb: &mut Framebuffer, threads: usize, help: Option<&AtomicBool>) -> Result<(), FragmentError> {
        let mut more = std::mem::take(&mut fb.samples);
        let r = self.run_samples(fb, &mut more, threads, help);
        fb.samples = more;
        r
    }

    fn run_samples(
        &self,
        fb: &mut Framebuffer,
        more: &mut [Framebuffer],
        threads: usize,
        help: Option<&AtomicBool>,
    ) -> Result<(), FragmentError> {
        debug_assert_eq!((fb.width(), fb.height()), (self.width, self.height));
        let plans: Vec<TexturePlan<'_>> = self.draws.iter().map(|d| d.textures.plan()).collect();
        let sets: Vec<TextureSet<'_>> = plans.iter().map(TexturePlan::set).collect();
        let target = fb.target();
        // What a shared draw's shading half is checked against: a band's
        // shading target has these formats (`SharedShade`).
        let (mut probe_color, mut probe_stencil) = ([0u8; 4], [0u8; 1]);
        let probe = Target::new(
            1,
            1,
            ColorFormat::Rgba8,
            &mut probe_color,
            4,
            None,
            Some(&mut probe_stencil),
        );
        // Each draw's stages are checked and set up once for all its tiles.
        let stages: Vec<Result<DrawStage<'_>, FragmentError>> = self
            .draws
            .iter()
            .zip(&sets)
            .map(|(d, set)| {
                let against = match (&probe, d.shades_samples) {
                    (Ok(p), true) => p,
                    _ => &target,
                };
                DrawStage::new(&d.key, &d.uniforms, set, d.specialist.as_deref(), against)
                    .map(|s| s.counting_into(d.samples.as_deref()))
            })
            .collect();
        // Only the bands with work run (an empty band has nothing to draw or
        // report), and on the calling thread when there is one: a scene of a
        // few primitives (a state change's flush) then wakes no pool thread
        // for nothing.
        let tiles_x = self.tiles_x as usize;
        let busy = |ty: usize| {
            let row = self.bins.get(ty * tiles_x..(ty + 1) * tiles_x);
            row.is_some_and(|r| r.iter().any(|b| !b.is_empty()))
        };
        // Each band with the same rows of every sample (sample 0 first).
        let mut lists: Vec<std::vec::IntoIter<Target<'_>>> = std::iter::once(target)
            .chain(more.iter_mut().map(Framebuffer::target))
            .map(|t| t.into_bands(TILE).into_iter())
            .collect();
        let n = lists.first().map_or(0, ExactSizeIterator::len);
        let bands: Vec<(usize, Vec<Target<'_>>)> = (0..n)
            .map(|ty| (ty, lists.iter_mut().filter_map(Iterator::next).collect()))
            .filter(|(ty, _)| busy(*ty))
            .collect();
        let run_band = |(ty, mut band): (usize, Vec<Target<'_>>)| self.run_band(ty as u32, &mut band, &stages);
        if let Some(help) = help.filter(|_| threads > 1 && bands.len() > 1) {
            return helped(threads, bands, help, run_band);
        }
        let results: Vec<Result<(), FragmentError>> = if threads <= 1 || bands.len() <= 1 {
            bands.into_iter().map(run_band).collect()
        } else {
            super::pool::run(threads, bands, run_band)
        };
        results.into_iter().collect()
    }

    /// Rasterizes the triangle recorded at `records[at]`, whose first
    /// word is `w0` and class `class`, inside `tile` into `sink`.
    #[inline(always)]
    fn cover<S: SpanSink>(&self, at: usize, w0: u32, class: &Class, tile: Rect, sink: &mut S) {
        let Some(words) = self.records.get(at + 1..) else {
            return;
        };
        let Some((prep, n)) = Prepared::decode(w0 >> 30, words) else {
            return;
        };
        let planes = words.get(n..n + 3 * usize::from(class.n)).unwrap_or(&[]);
        let slots = &class.slots[..usize::from(class.n)];
        // The box is within the bounds already.
        prep.cover(tile, class.params.height, sink, |to| {
            copy_planes(to, slots, planes);
            match class.params.depth {
                Some(f @ DepthFormat::D32) => planes.last_chunk::<3>().map(|&[a0, dadx, dady]| {
                    let plane = Plane {
                        a0: f32::from_bits(a0),
                        dadx: f32::from_bits(dadx),
                        dady: f32::from_bits(dady),
                    };
                    (f, plane)
                }),
                _ => None,
            }
        });
    }

    /// [`Scene::cover`] through a polygon stipple's mask (out of line: the
    /// tile loop's unstippled path stays as it was).
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn cover_stippled<S: SpanSink>(
        &self,
        at: usize,
        w0: u32,
        class: &Class,
        tile: Rect,
        sink: &mut S,
        rows: &[u32; 32],
        scratch: &mut FragmentSpan,
    ) {
        let sink = &mut PolygonStipple {
            inner: sink,
            rows,
            scratch,
        };
        self.cover(at, w0, class, tile, sink)
    }

    /// Rasterizes line or point `p`'s pixels inside `tile` into `sink`,
    /// rebuilding its vertices in `scratch`.
    fn rasterize<S: SpanSink>(&self, p: &Binned, tile: Rect, scratch: &mut Scratch, sink: &mut S) {
        let params = RasterParams {
            bounds: p.params.bounds.intersect(tile),
            ..p.params
        };
        let flat = self.rebuild(p, scratch);
        let (v, f) = (&scratch.v, flat.then_some(&scratch.flat));
        let sink = &mut Rasterize(sink);
        match p.kind {
            Kind::Line { width } => sink.line(&v[0], &v[1], width, f, &params),
            Kind::Point { size } => sink.point(&v[0], size, &params),
            Kind::Bitmap { index } => {
                if let Some(b) = self.bitmaps.get(index as usize) {
                    super::pixels::bitmap(&v[0], b, &params, sink.0)
                }
            }
            Kind::Image { index } => {
                if let Some(img) = self.images.get(index as usize) {
                    super::pixels::image(img, &params, sink.0)
                }
            }
        }
    }

    /// Writes `p`'s vertices (and flat varyings; returns whether it has
    /// them) into `out` as the geometry stage handed them over. Only the
    /// layout's slots are written: the rasterizer reads no others.
    fn rebuild(&self, p: &Binned, out: &mut Scratch) -> bool {
        let n = p.params.layout.len();
        let (first, vary) = (p.first as usize, p.vary as usize);
        let k = p.kind.vertices();
        for (i, (q, o)) in self.verts[first..first + k].iter().zip(&mut out.v).enumerate() {
            (o.x, o.y, o.y_down, o.z, o.inv_w) = (q.x, q.y, q.y_down, q.z, q.inv_w);
            o.v[..n].copy_from_slice(&self.vary[vary + i * n..][..n]);
        }
        if p.flat {
            out.flat[..n].copy_from_slice(&self.vary[vary + k * n..][..n]);
        }
        p.flat
    }

    /// Reads what the primitives of `bin` recorded (their records, or
    /// their entries) once before they run, in a loop whose loads do not
    /// wait for one another: the scene is read in the bins' order, not the
    /// recorded one, so a tile of small triangles from all over a frame
    /// missed the cache several times a triangle, one miss after the other
    /// (`perf`, `thrash`: 96% of `with_planes`' cycles on the planes' first
    /// load). A few instructions an entry; `black_box` keeps the loads.
    fn warm(&self, bin: &[u32]) {
        let mut last = u32::MAX;
        for &e in bin {
            if e & CLEAR != 0 {
                continue;
            }
            if e & TRI != 0 {
                // A record starting at most 64 words after the previous
                // one is read after it too, which the hardware prefetches
                // (a strip's triangles, `lit16`).
                let near = e.wrapping_sub(last) <= 64;
                last = e;
                if near {
                    continue;
                }
                // A lit triangle's record (about 90 bytes) may straddle
                // three cache lines.
                let at = (e & !TRI) as usize;
                std::hint::black_box([at, at + 15, at + 22].map(|i| self.records.get(i).copied()));
            } else if let Some(p) = self.prims.get(e as usize) {
                std::hint::black_box(*p);
            }
        }
    }

    /// Runs the tiles of row `ty` into `bands`, its rows of the framebuffer
    /// (of each sample, sample 0 first, when the scene's draws share their
    /// samples' shading), on one fragment stage a sample whose batches go
    /// on across tiles while the draw stays the same.
    fn run_band(
        &self,
        ty: u32,
        bands: &mut [Target<'_>],
        stages: &[Result<DrawStage<'_>, FragmentError>],
    ) -> Result<(), FragmentError> {
        let Some((band, others)) = bands.split_first_mut() else {
            return Ok(());
        };
        let mut scratch = Box::<Scratch>::default();
        // What each draw's specialist reads of its textures, made when the
        // band first runs the draw.
        let views: Vec<OnceCell<DrawTextures<'_>>> = std::iter::repeat_with(OnceCell::new).take(stages.len()).collect();
        // Shared shading: a target of the band's rows to shade into, and a
        // stage on it (only when the scene has such draws).
        let shared = !others.is_empty() && self.draws.iter().any(|d| d.shades_samples);
        let (width, height, rows) = (band.width(), band.height(), band.rows());
        let mut shade_mem = SharedShade::new(shared, width, rows.len());
        let mut work = shared.then(|| {
            let mut w = GroupWork::boxed();
            w.probes = vec![Probe::default(); self.draws.len()];
            w
        });
        let mut shade_target = shade_mem.target((width, height), (rows.start, rows.end - rows.start));
        let mut shade_stage = shade_target.as_mut().map(FragmentStage::new);
        let mut others: Vec<FragmentStage<'_, '_>> = others.iter_mut().map(FragmentStage::new).collect();
        let mut stage = FragmentStage::new(band);
        let mut stipple_span = FragmentSpan::new(0, 0);
        for tx in 0..self.tiles_x {
            let tile = Rect {
                x0: tx * TILE,
                y0: ty * TILE,
                x1: ((tx + 1) * TILE).min(self.width),
                y1: ((ty + 1) * TILE).min(self.height),
            };
            let bin = &self.bins[(ty * self.tiles_x + tx) as usize];
            self.warm(bin);
            // The draw the stage runs (set again at each tile and after a
            // clear: a no-op while it stays the same), and whether its
            // stage was made.
            let (mut current, mut ok) = (usize::MAX, false);
            // The draw's polygon stipple, if any: its triangles' spans are masked.
            let mut stipple: Option<&[u32; 32]> = None;
            for &e in bin {
                if e & CLEAR != 0 {
                    if let Some(c) = self.clears.get((e & !CLEAR) as usize) {
                        stage.clear(c, tile);
                        for o in &mut others {
                            o.clear(c, tile);
                        }
                    }
                    current = usize::MAX;
                    continue;
                }
                if e & GROUP != 0 {
                    let at = (e & !(TRI | GROUP)) as usize;
                    let Some(class) = self
                        .records
                        .get(at + 1)
                        .and_then(|&w0| self.classes.get((w0 & !(3 << 30)) as usize))
                    else {
                        continue;
                    };
                    let d = class.draw as usize;
                    let (Some(shade), Some(work)) = (shade_stage.as_mut(), work.as_mut()) else {
                        continue;
                    };
                    if d != current {
                        current = d;
                        ok = match (stages.get(d), stages.get(d + 1)) {
                            (Some(Ok(sd)), Some(Ok(od))) => {
                                let sv = views[d].get_or_init(|| {
                                    sd.specialist()
                                        .map_or(DrawTextures::None, |s| s.texture_view(sd.textures()))
                                });
                                let ov = views[d + 1].get_or_init(|| {
                                    od.specialist()
                                        .map_or(DrawTextures::None, |s| s.texture_view(od.textures()))
                                });
                                shade.set_draw(sd, sv);
                                stage.set_draw(od, ov);
                                for o in &mut others {
                                    o.set_draw(od, ov);
                                }
                                true
                            }
                            (Some(Err(e)), _) | (_, Some(Err(e))) => {
                                stage.fail(*e);
                                false
                            }
                            _ => false,
                        };
                    }
                    if ok {
                        self.run_group(at, class, tile, shade, &mut stage, &mut others, work);
                    }
                    continue;
                }
                let (d, tri) = if e & TRI != 0 {
                    let at = (e & !TRI) as usize;
                    let Some(&w0) = self.records.get(at) else { continue };
                    let Some(class) = self.classes.get((w0 & !(3 << 30)) as usize) else {
                        continue;
                    };
                    (class.draw as usize, Some((at, w0, class)))
                } else {
                    let Some(p) = self.prims.get(e as usize) else { continue };
                    (p.draw as usize, None)
                };
                if d != current {
                    current = d;
                    stipple = self.draws.get(d).and_then(|d| d.polygon_stipple.as_deref());
                    ok = match stages.get(d) {
                        Some(Ok(draw)) => {
                            let view = views[d].get_or_init(|| {
                                draw.specialist()
                                    .map_or(DrawTextures::None, |s| s.texture_view(draw.textures()))
                            });
                            stage.set_draw(draw, view);
                            true
                        }
                        Some(Err(e)) => {
                            stage.fail(*e);
                            false
                        }
                        None => false,
                    };
                }
                if !ok {
                    continue;
                }
                match tri {
                    Some((at, w0, class)) => match stipple {
                        None => self.cover(at, w0, class, tile, &mut stage),
                        Some(rows) => self.cover_stippled(at, w0, class, tile, &mut stage, rows, &mut stipple_span),
                    },
                    None => {
                        let p = &self.prims[e as usize];
                        if let Kind::Image { index } = p.kind {
                            if let Some(img) = self.images.get(index as usize) {
                                if matches!(img.pixels, crate::pixel_rect::RectPixels::Stencil { .. }) {
                                    let bounds = p.params.bounds.intersect(tile);
                                    stage.direct(|t| super::pixels::write_stencil(img, bounds, t));
                                    continue;
                                }
                            }
                        }
                        self.rasterize(p, tile, &mut scratch, &mut stage)
                    }
                }
            }
        }
        let mut r = stage.finish();
        for o in others {
            r = r.and(o.finish());
        }
        if let Some(s) = shade_stage {
            r = r.and(s.finish());
        }
        r
    }

    /// Runs the shared triangle whose word is `records[at]` (`class`: its
    /// samples' records') inside `tile`: the pixels any of its samples
    /// covers are shaded once into `shade` (the scissor and alpha tests
    /// too), then each sample's covered pixels among those the shading
    /// kept go to its stage (`stage` sample 0's, `others` the rest) with
    /// the shaded colours and the sample's depth: what a scene of that
    /// sample alone would hand its stages, where they shaded again.
    #[allow(clippy::too_many_arguments)]
    fn run_group<'t, 'f>(
        &self,
        at: usize,
        class: &Class,
        tile: Rect,
        shade: &mut FragmentStage<'_, '_>,
        stage: &mut FragmentStage<'t, 'f>,
        others: &mut [FragmentStage<'t, 'f>],
        work: &mut GroupWork,
    ) {
        let Some(&present) = self.records.get(at) else { return };
        let n = usize::from(class.n);
        let slots = &class.slots[..n];
        let height = class.params.height;
        // Each sample's record: its coverage and where its planes are.
        let mut recs: [Option<(usize, usize)>; 4] = [None; 4];
        let mut preps: [Option<Prepared>; 4] = [None; 4];
        let mut p = at + 1;
        // The tile's rows the samples' boxes reach: `lo..hi`.
        let rows = (tile.y1 - tile.y0) as usize;
        let (mut lo, mut hi) = (rows, 0);
        for s in 0..4 {
            if present >> s & 1 == 0 {
                continue;
            }
            let Some(&w0) = self.records.get(p) else { return };
            let Some((prep, c)) = self.records.get(p + 1..).and_then(|w| Prepared::decode(w0 >> 30, w)) else {
                return;
            };
            recs[s] = Some((p + 1 + c, s));
            let r = prep.rect().intersect(tile);
            if !r.is_empty() {
                lo = lo.min((r.y0 - tile.y0) as usize);
                hi = hi.max((r.y1 - tile.y0) as usize);
            }
            preps[s] = Some(prep);
            p += 1 + c + 3 * n;
        }
        if lo >= hi {
            return;
        }
        // Each sample's coverage of those rows, and their union.
        let union = &mut work.union;
        union[lo..hi].fill(0);
        for (s, prep) in preps.iter().enumerate() {
            let Some(prep) = prep else { continue };
            work.masks[s][lo..hi].fill(0);
            let mut sink = MaskSink {
                rows: &mut work.masks[s],
                origin: (tile.x0, tile.y0),
                planes: &mut work.planes,
            };
            prep.cover(tile, height, &mut sink, |_| None);
            for (u, m) in union[lo..hi].iter_mut().zip(&work.masks[s][lo..hi]) {
                *u |= m;
            }
        }
        let Some(first) = union[lo..hi].iter().position(|&m| m != 0) else {
            return;
        };
        let lo = lo + first;
        let hi = hi - union[lo..hi].iter().rev().position(|&m| m != 0).unwrap_or(0);
        // Early tests: the pixels no sample's stencil and depth tests can
        // pass are not shaded (the per-sample specialists shade only what
        // those tests leave: a skybox behind the scene, a reflection
        // outside its stencil, were shaded whole otherwise).
        let early = self.draws.get(class.draw as usize + 1).and_then(EarlyTests::of);
        let mut probe = work.probes.get_mut(class.draw as usize);
        if let Some(p) = probe.as_deref_mut() {
            if early.is_some() && !p.testing(&work.union[lo..hi]) {
                probe = None;
            }
        }
        if let (Some(early), Some(probe)) = (early, probe) {
            let z = class.params.depth.is_some();
            let pass = &mut work.pass;
            pass[lo..hi].fill(0);
            for &(planes, s) in recs.iter().flatten() {
                let Some(to) = sample_stage(stage, others, s) else {
                    continue;
                };
                let plane = planes_of_at(&self.records, planes, n)
                    .filter(|_| z)
                    .and_then(|p| p.last_chunk::<3>())
                    .map(|&[a0, dadx, dady]| [a0, dadx, dady].map(f32::from_bits));
                let masks = &work.masks[s];
                to.direct(|t| early.pass(t, plane, (tile, height), (lo, hi), masks, pass));
            }
            let (mut tested, mut kept) = (0, 0);
            for (u, p) in work.union[lo..hi].iter_mut().zip(&pass[lo..hi]) {
                tested += u.count_ones();
                *u &= p;
                kept += u.count_ones();
            }
            probe.tested(tested, kept);
            if kept == 0 {
                return;
            }
        }
        let union = &work.union;
        let len = tile.x1 - tile.x0;
        // Shade: the marks cleared where the pixels are, then every pixel
        // any sample covers.
        shade.direct(|t| {
            for (r, &m) in union[..hi].iter().enumerate().skip(lo).filter(|(_, m)| **m != 0) {
                let (lo, hi) = (m.trailing_zeros(), 63 - m.leading_zeros());
                let i = t.index(tile.x0 + lo, tile.y0 + r as u32);
                if let Some(st) = t.stencil_mut().and_then(|st| st.get_mut(i..=i + (hi - lo) as usize)) {
                    st.fill(0);
                }
            }
        });
        let Some(first) = recs.iter().flatten().next().map(|&(planes, _)| planes) else {
            return;
        };
        let planes_of = |p: usize| self.records.get(p..p + 3 * n).unwrap_or(&[]);
        if let Some(to) = shade.planes_mut() {
            copy_planes(to, slots, planes_of(first));
        }
        let span = &mut work.span;
        for (r, &m) in union[..hi].iter().enumerate().skip(lo).filter(|(_, m)| **m != 0) {
            (span.x, span.y, span.len, span.mask) = (tile.x0, tile.y0 + r as u32, len, m);
            shade.span(span);
        }
        // The fragments the shading kept (marked 1), and their colours.
        let (alive, colors) = (&mut work.alive, &mut work.colors);
        shade.direct(|t| {
            for (r, &m) in union[..hi].iter().enumerate().skip(lo) {
                alive[r] = 0;
                if m == 0 {
                    continue;
                }
                let i = t.index(tile.x0, tile.y0 + r as u32);
                let Some(st) = t.stencil_mut().and_then(|st| st.get(i..i + len as usize)) else {
                    continue;
                };
                // Every pixel of the row tested, sixteen at once, no bit
                // scan; then those shaded kept.
                let mut keep = 0u64;
                for (k, c) in st.chunks(16).enumerate().take(4) {
                    keep |= match <[u8; 16]>::try_from(c) {
                        Ok(c) => u64::from(u8x16::new(c).simd_eq(u8x16::splat(1)).to_bitmask()) << (16 * k),
                        Err(_) => c
                            .iter()
                            .enumerate()
                            .fold(0, |m, (b, &v)| m | u64::from(v == 1) << (16 * k + b)),
                    };
                }
                alive[r] = keep & m;
            }
            for (r, &m) in alive[..hi].iter().enumerate().skip(lo) {
                if m == 0 {
                    continue;
                }
                let o = t.color_offset(tile.x0, tile.y0 + r as u32);
                // The colours of the pixels from the first kept to the last
                // (the stages read the kept ones), four channels apart.
                let (b0, b1) = (m.trailing_zeros() as usize, 64 - m.leading_zeros() as usize);
                let (Some(c), Some([tr, tg, tb, ta])) = (t.color().get(o + 4 * b0..o + 4 * b1), colors.get_mut(r))
                else {
                    continue;
                };
                let to = tr[b0..b1]
                    .iter_mut()
                    .zip(&mut tg[b0..b1])
                    .zip(&mut tb[b0..b1])
                    .zip(&mut ta[b0..b1]);
                for (px, (((r, g), b), a)) in c.chunks_exact(4).zip(to) {
                    (*r, *g, *b, *a) = (px[0], px[1], px[2], px[3]);
                }
            }
        });
        // Each sample: its covered pixels among those kept, with its depth.
        let d32 = match class.params.depth {
            Some(f @ DepthFormat::D32) => Some(f),
            _ => None,
        };
        for &(planes, s) in recs.iter().flatten() {
            let Some(to) = sample_stage(stage, others, s) else {
                continue;
            };
            let planes = planes_of(planes);
            if let Some(p) = to.planes_mut() {
                copy_planes(p, slots, planes);
            }
            // 32-bit depth is the span's, as `Prepared::cover` makes it.
            let z = d32.and_then(|f| {
                planes
                    .last_chunk::<3>()
                    .map(|&[a0, dadx, dady]| (f, f32::from_bits(a0), f32::from_bits(dadx), f32::from_bits(dady)))
            });
            for (r, (&m, &a)) in work.masks[s][..hi].iter().zip(&alive[..hi]).enumerate().skip(lo) {
                let m = m & a;
                if m == 0 {
                    continue;
                }
                let y = tile.y0 + r as u32;
                to.span_filled((tile.x0, y, len), m, |span| {
                    if let Some(c) = colors.get(r) {
                        (span.r, span.g, span.b, span.a) = (c[0], c[1], c[2], c[3]);
                    }
                    if let Some((f, a0, dadx, dady)) = z {
                        let row = softgl_jit::interp::row_of(y, height);
                        for b in crate::raster::set_bits(m) {
                            let x = (tile.x0 + b as u32) as f32;
                            let v = dady.mul_add(row, dadx.mul_add(x, a0));
                            span.z[b] = crate::framebuffer::depth_to_unorm(f64::from(v), f);
                        }
                    }
                });
            }
        }
    }
}

/// A band's room for the shared shading of multisampled draws
/// ([`Scene::run_group`]): the colour (RGBA8) and marks (a stencil) of its
/// rows, and the per-tile work.
struct SharedShade {
    color: Vec<u8>,
    stencil: Vec<u8>,
}

/// What [`Scene::run_group`] works in: each sample's coverage of a tile
/// and their union (rows from the tile's bottom, bit `i` its column `i`;
/// only the rows a triangle's boxes reach are cleared and read: zeroing
/// them all was ~2% of a frame in `memset`), the fragments the shading
/// kept and their colours (a channel a row), a span and planes to cover
/// into.
struct GroupWork {
    masks: [[u64; TILE as usize]; 4],
    union: [u64; TILE as usize],
    /// The pixels some sample's early tests pass ([`EarlyTests`]).
    pass: [u64; TILE as usize],
    alive: [u64; TILE as usize],
    colors: [[[u8; SPAN_MAX]; 4]; TILE as usize],
    span: FragmentSpan,
    planes: Planes,
    /// Whether each draw's early tests pay, in this band ([`Probe`]).
    probes: Vec<Probe>,
}

/// Whether a shared draw's early tests ([`EarlyTests`]) are run, from
/// what they killed lately in the band: they cost tens of instructions a
/// pixel, and each sample's pending batch runs before them (they read the
/// samples' buffers, so a sample's batch ended at every triangle), so
/// where they kill little they cost more than the shading they save.
/// MuJoCo's lit passes (a depth test equal to the base pass's own depth)
/// pass everywhere: `shadow_fbo plane-640x480` spent ~90 M instructions a
/// frame on them; the reflection through the stencil is killed in most
/// pixels. So a draw's tests run over a window of [`Probe::WINDOW`]
/// pixels; when they killed less than a quarter of them the next
/// [`Probe::SKIP`] pixels are shaded untested, then a window is tested
/// again (that frame: 845 M → 755 M instructions together with the rows'
/// zeroing, `fragment.rs`; ~60 M of it these tests). Skipping them changes no byte: the per-sample half runs the
/// exact tests on what is shaded.
#[derive(Clone, Copy, Debug, Default)]
struct Probe {
    /// Pixels tested in this window, and those the tests kept.
    tested: u32,
    kept: u32,
    /// Pixels still to shade untested.
    skip: u32,
}

impl Probe {
    const WINDOW: u32 = 1024;
    const SKIP: u32 = 16 * 1024;

    /// Whether the pixels of `union` are tested (else they count against
    /// the pixels to skip).
    #[inline]
    fn testing(&mut self, union: &[u64]) -> bool {
        if self.skip == 0 {
            return true;
        }
        let n: u32 = union.iter().map(|m| m.count_ones()).sum();
        self.skip = self.skip.saturating_sub(n);
        false
    }

    /// `tested` pixels were tested, of which the tests kept `kept`.
    #[inline]
    fn tested(&mut self, tested: u32, kept: u32) {
        self.tested += tested;
        self.kept += kept;
        if self.tested >= Self::WINDOW {
            if 4 * (self.tested - self.kept) < self.tested {
                self.skip = Self::SKIP;
            }
            (self.tested, self.kept) = (0, 0);
        }
    }
}

impl SharedShade {
    /// Room for a band `width` wide and `rows` high when `shared`, else none.
    fn new(shared: bool, width: u32, rows: usize) -> SharedShade {
        let n = if shared { width as usize * rows } else { 0 };
        SharedShade {
            color: vec![0; 4 * n],
            stencil: vec![0; n],
        }
    }

    /// The band's shading target, when there is room.
    fn target(&mut self, size: (u32, u32), rows: (u32, u32)) -> Option<Target<'_>> {
        if self.stencil.is_empty() {
            return None;
        }
        Target::band(size, rows, ColorFormat::Rgba8, &mut self.color, Some(&mut self.stencil)).ok()
    }
}

impl GroupWork {
    fn boxed() -> Box<GroupWork> {
        Box::new(GroupWork {
            masks: [[0; TILE as usize]; 4],
            union: [0; TILE as usize],
            pass: [0; TILE as usize],
            alive: [0; TILE as usize],
            colors: [[[0; SPAN_MAX]; 4]; TILE as usize],
            span: FragmentSpan::new(0, 0),
            planes: Planes::default(),
            probes: Vec::new(),
        })
    }
}

/// The `3 * n` words of the planes at `at` of `records`.
fn planes_of_at(records: &[u32], at: usize, n: usize) -> Option<&[u32]> {
    records.get(at..at + 3 * n)
}

/// A shared draw's stencil and depth tests as the shading half runs them
/// early ([`Scene::run_group`]): a pixel is shaded only when some sample
/// covering it may pass both, in its buffers as they are before the
/// primitive. Only for keys whose stencil test changes nothing where a
/// fragment fails (`fail` and `zfail` keep): a pixel not shaded then
/// leaves every buffer as the per-sample half would. The stencil test is
/// exact; depth is evaluated in f64 and may fail only by more than a
/// margin bounding the f32 rounding of the plane (so a pixel whose test
/// passes is always shaded: the per-sample half runs the exact test).
#[derive(Clone, Copy, Debug)]
struct EarlyTests {
    stencil: Option<(CompareFunc, u8, u8)>,
    depth: Option<CompareFunc>,
}

/// Sample `s`'s stage of a shared draw: `stage` for sample 0, else
/// `others[s - 1]` ([`Scene::run_group`]).
fn sample_stage<'a, 't, 'f>(
    stage: &'a mut FragmentStage<'t, 'f>,
    others: &'a mut [FragmentStage<'t, 'f>],
    s: usize,
) -> Option<&'a mut FragmentStage<'t, 'f>> {
    match s {
        0 => Some(stage),
        s => others.get_mut(s - 1),
    }
}

impl EarlyTests {
    /// The early tests of the per-sample half `ops`, if it has some that
    /// may be run early.
    fn of(ops: &DrawState) -> Option<EarlyTests> {
        let k = &ops.key;
        if k.stencil
            .is_some_and(|s| s.fail != StencilOp::Keep || s.zfail != StencilOp::Keep)
        {
            return None;
        }
        let u = &ops.uniforms;
        let stencil = k
            .stencil
            .map(|s| (s.func, u.stencil_ref & u.stencil_value_mask, u.stencil_value_mask));
        let depth = k.depth.map(|d| d.func).filter(|f| *f != CompareFunc::Always);
        (stencil.is_some() || depth.is_some()).then_some(EarlyTests { stencil, depth })
    }

    /// Sets in `pass` the pixels of `masks` (a sample's coverage of rows
    /// `lo..hi` of `tile`) whose tests may pass in `t`, the sample's band;
    /// `plane`: its depth plane, `height` the framebuffer's.
    fn pass(
        &self,
        t: &mut Target<'_>,
        plane: Option<[f32; 3]>,
        (tile, height): (Rect, u32),
        (lo, hi): (usize, usize),
        masks: &[u64; TILE as usize],
        pass: &mut [u64; TILE as usize],
    ) {
        // The buffers and the depth format are matched once a row, not once
        // a pixel (MuJoCo's skybox shared, two `noshadow` frames at
        // 640×480: 253 M → 201 M instructions of tests).
        let plane = plane.map(|p| p.map(f64::from));
        for r in lo..hi {
            // (Pixels an earlier sample passes need no more tests.)
            let m = masks[r] & !pass[r];
            if m == 0 {
                continue;
            }
            let y = tile.y0 + r as u32;
            let i0 = t.index(tile.x0, y);
            let mut keep = m;
            if let (Some((func, reference, mask)), Some(st)) = (self.stencil, t.stencil_mut()) {
                for b in crate::raster::set_bits(m) {
                    if st.get(i0 + b).is_some_and(|&v| !func.test(reference, v & mask)) {
                        keep &= !(1 << b);
                    }
                }
            }
            if let (Some(func), Some(plane), Some(d), true) = (self.depth, plane, t.depth_mut(), keep != 0) {
                let at = DepthRow {
                    func,
                    plane,
                    x0: f64::from(tile.x0),
                    row: f64::from(softgl_jit::interp::row_of(y, height)),
                };
                let unorm = |f: DepthFormat| f64::from(f.max_value());
                keep = match d {
                    DepthTarget::D16(v) => at.keep(keep, v.get(i0..), (unorm(DepthFormat::D16), 2.0), f64::from),
                    DepthTarget::D24(v) => at.keep(keep, v.get(i0..), (unorm(DepthFormat::D24), 2.0), f64::from),
                    DepthTarget::D32(v) => at.keep(keep, v.get(i0..), (unorm(DepthFormat::D32), 2.0), f64::from),
                    DepthTarget::D32F(v) => at.keep(keep, v.get(i0..), (1.0, 0.0), |v| f64::from(f32::from_bits(v))),
                };
            }
            pass[r] |= keep;
        }
    }
}

/// One row's early depth test ([`EarlyTests::pass`]).
struct DepthRow {
    func: CompareFunc,
    /// The sample's depth plane, and the tile's first column and the row
    /// as the plane takes them.
    plane: [f64; 3],
    x0: f64,
    row: f64,
}

impl DepthRow {
    /// `keep` without the pixels (bit `b`: `row[b]`, a buffer of `max`
    /// units rounded to within `slack` of them, `stored` reading one)
    /// whose depth test fails by more than the margin. The plane is evaluated in f64; a unorm depth is
    /// rounded to a unit (two to spare), a float one is the plane's f32
    /// value, within `err`. (Float depth had the unorm's two units too,
    /// which in [0, 1] let every fragment pass: MuJoCo's buffers are
    /// float, so no depth test of its killed early.)
    #[inline(always)]
    fn keep<T: Copy>(&self, keep: u64, row: Option<&[T]>, (max, slack): (f64, f64), stored: impl Fn(T) -> f64) -> u64 {
        const E: f64 = 1.0 / (1u64 << 20) as f64;
        let [a0, dadx, dady] = self.plane;
        let row = row.unwrap_or(&[]);
        let mut out = keep;
        for b in crate::raster::set_bits(keep) {
            let Some(&v) = row.get(b) else { continue };
            let x = self.x0 + b as f64;
            let z = a0 + dadx * x + dady * self.row;
            // f32 rounding of the plane's terms, generously.
            let err = (a0.abs() + (dadx * x).abs() + (dady * self.row).abs()) * E + E;
            if !z.is_finite() || !err.is_finite() {
                continue;
            }
            let (z, stored) = (z.clamp(0.0, 1.0) * max, stored(v));
            let margin = err * max + slack;
            let ok = match self.func {
                CompareFunc::Never => false,
                CompareFunc::Less => z - margin < stored,
                CompareFunc::Lequal => z - margin <= stored,
                CompareFunc::Greater => z + margin > stored,
                CompareFunc::Gequal => z + margin >= stored,
                CompareFunc::Equal => (z - stored).abs() <= margin,
                CompareFunc::Notequal | CompareFunc::Always => true,
            };
            if !ok {
                out &= !(1 << b);
            }
        }
        out
    }
}

/// Collects the rows a triangle covers in a tile as bit masks
/// ([`Scene::run_group`]).
struct MaskSink<'m> {
    rows: &'m mut [u64; TILE as usize],
    /// The tile's lower-left pixel.
    origin: (u32, u32),
    /// Where the rasterizer's planes go (never read).
    planes: &'m mut Planes,
}

impl SpanSink for MaskSink<'_> {
    fn span(&mut self, span: &FragmentSpan) {
        let (Some(r), Some(dx)) = (span.y.checked_sub(self.origin.1), span.x.checked_sub(self.origin.0)) else {
            return;
        };
        if let Some(row) = self.rows.get_mut(r as usize) {
            if dx < 64 {
                *row |= span.live_mask() << dx;
            }
        }
    }

    fn planes_mut(&mut self) -> Option<&mut Planes> {
        Some(self.planes)
    }

    fn row(&mut self, y: u32, x0: u32, x1: u32) {
        let (Some(r), Some(lo), Some(hi)) = (
            y.checked_sub(self.origin.1),
            x0.checked_sub(self.origin.0),
            x1.checked_sub(self.origin.0),
        ) else {
            return;
        };
        if let Some(row) = self.rows.get_mut(r as usize) {
            if lo <= hi && hi < 64 {
                *row |= (u64::MAX >> (63 - (hi - lo))) << lo;
            }
        }
    }
}

/// Runs `bands` (band index, rows) through `run_band` on the calling pool
/// thread and `threads - 2` more of [`super::pool::pool`]`(threads)`, one
/// more once `help` is set: a background flush keeps a core for the
/// caller while it records, and takes it back when the caller waits. With
/// two threads a background flush ran on one thread from start to end, the
/// caller waiting idle beside it: MuJoCo's light passes flush in the
/// background (their textures pass `TEXTURE_BOUND`), and `perf` of the
/// 2-thread frame showed that one thread with 41% of the samples, the two
/// threads of the flushes made at once 25% together. Bands are taken in
/// order from a shared queue; the first error in band order is returned,
/// as [`Scene::run`]'s.
fn helped<'t>(
    threads: usize,
    bands: Vec<(usize, Vec<Target<'t>>)>,
    help: &AtomicBool,
    run_band: impl Fn((usize, Vec<Target<'t>>)) -> Result<(), FragmentError> + Sync,
) -> Result<(), FragmentError> {
    let n = bands.len();
    let queue = Mutex::new(bands.into_iter());
    let results: Mutex<Vec<(usize, Result<(), FragmentError>)>> = Mutex::new(Vec::with_capacity(n));
    let all_done = Condvar::new();
    // A band's panic, raised again once every band is accounted for.
    let panicked = Mutex::new(None);
    let next = || queue.lock().unwrap_or_else(PoisonError::into_inner).next();
    let one = |band: (usize, Vec<Target<'t>>)| {
        let ty = band.0;
        let r = match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_band(band))) {
            Ok(r) => r,
            Err(p) => {
                panicked.lock().unwrap_or_else(PoisonError::into_inner).get_or_insert(p);
                Ok(())
            }
        };
        let mut done = results.lock().unwrap_or_else(PoisonError::into_inner);
        done.push((ty, r));
        if done.len() == n {
            all_done.notify_all();
        }
    };
    let work = || {
        while let Some(band) = next() {
            one(band);
        }
    };
    match super::pool::pool(threads) {
        Some(pool) => pool.in_place_scope(|s| {
            // Helpers beside this thread: `threads - 2` now, one more on help.
            let mut helpers = 0;
            let wanted = |helped: bool| if helped { threads - 1 } else { threads - 2 };
            loop {
                while helpers < wanted(help.load(Ordering::Acquire)) {
                    s.spawn(|_| work());
                    helpers += 1;
                }
                let Some(band) = next() else { break };
                one(band);
            }
            // Wait for the helpers' bands here, not in the scope's end:
            // this thread is a worker of the background pool, and waiting
            // there it would take that pool's next job (another scene's
            // flush) before handing this one back.
            let mut done = results.lock().unwrap_or_else(PoisonError::into_inner);
            while done.len() < n {
                done = all_done.wait(done).unwrap_or_else(PoisonError::into_inner);
            }
        }),
        None => work(),
    }
    if let Some(p) = panicked.into_inner().unwrap_or_else(PoisonError::into_inner) {
        std::panic::resume_unwind(p);
    }
    let mut results = results.into_inner().unwrap_or_else(PoisonError::into_inner);
    results.sort_by_key(|(ty, _)| *ty);
    results.into_iter().try_for_each(|(_, r)| r)
}

/// A triangle's record being made ([`RECORD`] words).
#[derive(Debug)]
struct Record([u32; RECORD]);

impl Default for Record {
    fn default() -> Self {
        Record([0; RECORD])
    }
}

/// Records one draw's primitives into a scene ([`Scene::draw`]).
pub struct Binner<'s> {
    scene: &'s mut Scene,
    fb: &'s mut Framebuffer,
    /// Where a flush past the bound runs with two or more threads.
    background: &'s mut Background,
    threads: usize,
    state: DrawState,
    /// A draw whose samples share the shading: its per-sample half,
    /// recorded right after `state` ([`Scene::draw_shared`]).
    ops: Option<DrawState>,
    /// The draw's index in the scene, once a primitive of it is recorded
    /// (again after a flush).
    draw: Option<u32>,
    error: Option<FragmentError>,
}

impl Binner<'_> {
    /// Ends the draw: the first error of a flush it made, if any.
    pub fn finish(self) -> Result<(), FragmentError> {
        self.error.map_or(Ok(()), Err)
    }

    /// The draw's index in the scene, recording it with the first primitive.
    #[inline(always)]
    fn draw(&mut self) -> u32 {
        match self.draw {
            Some(d) => d,
            None => self.first_draw(),
        }
    }

    /// [`Binner::draw`] at the draw's first primitive (after a flush too):
    /// out of line, so that the others cost a test.
    #[inline(never)]
    fn first_draw(&mut self) -> u32 {
        match self.draw {
            Some(d) => d,
            // A shared draw's two halves, never joined with another.
            None if self.ops.is_some() => {
                let d = self.scene.draws.len() as u32;
                self.scene.bytes += 2 * std::mem::size_of::<DrawState>();
                self.scene.hold_textures(&self.state);
                self.scene.draws.push(self.state.clone());
                self.scene.draws.extend(self.ops.clone());
                self.draw = Some(d);
                d
            }
            // The scene's last draw runs with the same state: its primitives
            // join it (a strip per glBegin/glEnd is one run of a tile).
            None if self.scene.draws.last().is_some_and(|last| last.same_as(&self.state)) => {
                let d = self.scene.draws.len() as u32 - 1;
                self.draw = Some(d);
                d
            }
            None => {
                let d = self.scene.draws.len() as u32;
                self.scene.bytes += std::mem::size_of::<DrawState>();
                self.scene.hold_textures(&self.state);
                self.scene.draws.push(self.state.clone());
                self.draw = Some(d);
                d
            }
        }
    }

    /// Records a line or a point with its vertices.
    fn record(
        &mut self,
        r: Option<Rect>,
        params: &RasterParams,
        kind: Kind,
        v: &[&RasterVertex],
        flat: Option<&Varyings>,
    ) {
        let Some(r) = r else { return };
        let draw = self.draw();
        let scene = &mut *self.scene;
        let n = params.layout.len();
        let (first, vary) = (scene.verts.len() as u32, scene.vary.len() as u32);
        for v in v {
            scene.verts.push(Vert {
                x: v.x,
                y: v.y,
                y_down: v.y_down,
                inv_w: v.inv_w,
                z: v.z,
            });
            scene.vary.extend_from_slice(&v.v[..n]);
        }
        if let Some(f) = flat {
            scene.vary.extend_from_slice(&f[..n]);
        }
        let flat = flat.is_some();
        scene.bytes += v.len() * std::mem::size_of::<Vert>() + (v.len() + usize::from(flat)) * n * 4;
        self.push(r, draw, kind, (first, vary), flat, params);
    }

    /// Records the line or point and bins it into the tiles `r` touches;
    /// flushes past the bounds (out of line).
    #[inline(always)]
    fn push(&mut self, r: Rect, draw: u32, kind: Kind, (first, vary): (u32, u32), flat: bool, params: &RasterParams) {
        let scene = &mut *self.scene;
        let entry = scene.prims.len() as u32;
        scene.prims.push(Binned {
            draw,
            kind,
            first,
            vary,
            flat,
            params: *params,
        });
        scene.bytes += std::mem::size_of::<Binned>();
        scene.bin(r, entry);
        if scene.full() {
            self.flush();
        }
    }

    #[cold]
    #[inline(never)]
    fn flush(&mut self) {
        let r = self.background.start(self.scene, self.fb, self.threads);
        if let Err(e) = r {
            self.error.get_or_insert(e);
        }
        self.draw = None;
    }
}

/// Bitmaps merged into one ([`Scene::bitmap`]), with what they run with.
#[derive(Debug)]
struct PendingBitmap {
    state: DrawState,
    params: RasterParams,
    vertex: RasterVertex,
    /// The raster colour and depth they were drawn with.
    colour: [f32; 4],
    z: f64,
    /// The merged bits, [`CACHE_WIDTH`]×[`CACHE_HEIGHT`], at `(x, y)`.
    x: i64,
    y: i64,
    bits: Vec<u64>,
}

impl Scene {
    /// Records bitmap `b` drawn with `state` and the constants of `v` (the
    /// raster position's, colour `colour`): merged with the bitmaps before
    /// it as Mesa's bitmap cache merges them ([`crate::pixel_rect::CACHE_WIDTH`]).
    pub fn bitmap(
        &mut self,
        state: DrawState,
        params: &RasterParams,
        v: RasterVertex,
        b: crate::pixel_rect::PlacedBitmap,
        colour: [f32; 4],
        fb: &Framebuffer,
    ) {
        use crate::pixel_rect::{CACHE_HEIGHT, CACHE_WIDTH};
        self.fit(fb.width(), fb.height());
        let (w, h) = (b.image.width(), b.image.height());
        if w > CACHE_WIDTH || h > CACHE_HEIGHT {
            self.settle();
            let r = b.rect(params.bounds);
            let index = self.bitmaps.len() as u32;
            self.bytes += std::mem::size_of_val(&b) + b.image.bytes();
            self.bitmaps.push(b);
            self.record_rect(state, params, &v, Kind::Bitmap { index }, r);
            return;
        }
        let words = CACHE_WIDTH / 64;
        if let Some(p) = self.pending.as_mut() {
            // Positions saturate far off-screen: the offsets may not exist.
            let (px, py) = (b.x.checked_sub(p.x).unwrap_or(-1), b.y.checked_sub(p.y).unwrap_or(-1));
            let fits = px >= 0
                && py >= 0
                && px.saturating_add(i64::from(w)) <= i64::from(CACHE_WIDTH)
                && py.saturating_add(i64::from(h)) <= i64::from(CACHE_HEIGHT);
            if fits && p.colour == colour && (p.z - v.z).abs() <= 1e-6 && p.state.same_as(&state) && p.params == *params
            {
                b.image.or_into(&mut p.bits, words, px as u32, py as u32);
                return;
            }
        }
        self.settle();
        let py = (CACHE_HEIGHT - h) / 2;
        let mut bits = vec![0u64; (words * CACHE_HEIGHT) as usize];
        b.image.or_into(&mut bits, words, 0, py);
        self.pending = Some(Box::new(PendingBitmap {
            state,
            params: *params,
            colour,
            z: v.z,
            vertex: v,
            x: b.x,
            y: b.y.saturating_sub(i64::from(py)),
            bits,
        }));
    }

    /// Records the merged bitmaps, if any.
    fn settle(&mut self) {
        let Some(p) = self.pending.take() else { return };
        let image = crate::pixel_rect::BitmapImage::from_words(
            crate::pixel_rect::CACHE_WIDTH,
            crate::pixel_rect::CACHE_HEIGHT,
            p.bits,
        );
        let b = crate::pixel_rect::PlacedBitmap { image, x: p.x, y: p.y };
        let r = b.rect(p.params.bounds);
        let index = self.bitmaps.len() as u32;
        self.bytes += std::mem::size_of_val(&b) + b.image.bytes();
        self.bitmaps.push(b);
        self.record_rect(p.state, &p.params, &p.vertex, Kind::Bitmap { index }, r);
    }

    /// Records pixel rectangle `img` drawn with `state` (after the bitmaps
    /// before it), `v` its raster position.
    pub fn pixels(
        &mut self,
        state: DrawState,
        params: &RasterParams,
        v: RasterVertex,
        img: crate::pixel_rect::PlacedImage,
        fb: &Framebuffer,
    ) {
        self.fit(fb.width(), fb.height());
        self.settle();
        let r = img.rect(params.bounds);
        let index = self.images.len() as u32;
        self.bytes += std::mem::size_of_val(&img) + img.bytes();
        self.images.push(img);
        self.record_rect(state, params, &v, Kind::Image { index }, r);
    }

    /// Records a bitmap or pixel rectangle `kind` covering `r`, its
    /// constants those of `v`.
    fn record_rect(&mut self, state: DrawState, params: &RasterParams, v: &RasterVertex, kind: Kind, r: Option<Rect>) {
        let Some(r) = r else { return };
        let draw = match self.draws.last() {
            Some(last) if last.same_as(&state) => self.draws.len() as u32 - 1,
            _ => {
                self.hold_textures(&state);
                self.bytes += std::mem::size_of::<DrawState>();
                self.draws.push(state);
                self.draws.len() as u32 - 1
            }
        };
        let n = params.layout.len();
        let (first, vary) = (self.verts.len() as u32, self.vary.len() as u32);
        self.verts.push(Vert {
            x: v.x,
            y: v.y,
            y_down: v.y_down,
            inv_w: v.inv_w,
            z: v.z,
        });
        self.vary.extend_from_slice(&v.v[..n]);
        self.bytes += std::mem::size_of::<Vert>() + 4 * n;
        let entry = self.prims.len() as u32;
        self.prims.push(Binned {
            draw,
            kind,
            first,
            vary,
            flat: false,
            params: *params,
        });
        self.bytes += std::mem::size_of::<Binned>();
        self.bin(r, entry);
    }
}

impl Scene {
    /// Appends the record `rec[..len]` at `used`: the first [`COPY`] words
    /// of `rec` in one fixed-size copy (a lit triangle's record is 21 to 23
    /// words), the rest, if any, after. `extend_from_slice` of its length
    /// called `memmove` for each: 4.9% of `lit16`'s samples on the thread
    /// that records (`perf`, one thread).
    #[inline(always)]
    fn append(records: &mut Vec<u32>, used: &mut usize, rec: &[u32; RECORD], len: usize) {
        let at = *used;
        if records.len() < at + RECORD {
            Scene::grow(records, at);
        }
        if let (Some(to), Some(from)) = (records.get_mut(at..at + COPY), rec.first_chunk::<COPY>()) {
            to.copy_from_slice(from);
        }
        if len > COPY {
            if let Some(to) = records.get_mut(at + COPY..at + len) {
                to.copy_from_slice(&rec[COPY..len]);
            }
        }
        *used = at + len;
    }

    /// Makes room for at least one more record past `used` in `records`
    /// (doubling).
    #[cold]
    #[inline(never)]
    fn grow(records: &mut Vec<u32>, used: usize) {
        let room = (2 * records.len()).max(used + RECORD).max(1 << 14);
        records.resize(room, 0);
    }

    /// The class of a triangle of draw `draw` with `params`: the last
    /// triangle's when it is the same draw and what a flush reads of the
    /// parameters is the same (the height, the depth format and the
    /// layout: the bounds and the offset are spent at recording; comparing
    /// all of them, floats included, was 39 instructions a triangle), else
    /// a new one.
    #[inline(always)]
    fn class(&mut self, draw: u32, params: &RasterParams, v: [&RasterVertex; 3], swap: bool) -> u32 {
        let same = |k: &Class| {
            k.draw == draw
                && k.params.height == params.height
                && k.params.depth == params.depth
                && k.params.layout == params.layout
        };
        match self.class {
            Some(c) if self.classes.get(c as usize).is_some_and(same) => c,
            _ => self.new_class(draw, params, v, swap),
        }
    }

    /// Records a class of triangles; its slots are those `setup_planes`
    /// puts for `v` (the same for any triangle with `params`).
    #[inline(never)]
    fn new_class(&mut self, draw: u32, params: &RasterParams, v: [&RasterVertex; 3], swap: bool) -> u32 {
        let mut class = Class {
            draw,
            params: *params,
            slots: [0; PLANES],
            n: 0,
        };
        setup_planes(v, swap, None, params, &mut |k, _| {
            if let Some(s) = class.slots.get_mut(usize::from(class.n)) {
                *s = k as u8;
                class.n += 1;
            }
        });
        let c = self.classes.len() as u32;
        self.classes.push(class);
        self.bytes += std::mem::size_of::<Class>();
        self.class = Some(c);
        c
    }

    /// Whether a draw flushes the scene now, on `threads` threads.
    #[inline(always)]
    fn full(&self) -> bool {
        self.bytes > self.bound() || self.textures_full
    }

    /// Counts the texel images of `state` (a draw about to be recorded)
    /// the scene does not hold yet; one that takes them past
    /// [`TEXTURE_BOUND`] in a scene that held draws before flushes it.
    fn hold_textures(&mut self, state: &DrawState) {
        let mut added = false;
        for t in state.textures.texels() {
            if self.textures.insert(Arc::as_ptr(t) as usize) {
                self.texture_bytes += t.len();
                added = true;
            }
        }
        if added && self.texture_bytes > TEXTURE_BOUND && !self.draws.is_empty() {
            self.textures_full = true;
        }
    }
}

impl PrimSink for Binner<'_> {
    /// Sets the triangle up once (its coverage and planes) and records
    /// it; one that no pixel is inside is not recorded.
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) {
        self.triangle_at(v, flat, params, None)
    }

    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams) {
        let reach = super::line::line_width_pixels(width) as f32 / 2.0 + 1.0;
        let r = reach_box(&[(a.x, a.y), (b.x, b.y)], reach, params.bounds);
        self.record(r, params, Kind::Line { width }, &[a, b], flat);
    }

    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams) {
        let reach = super::point::point_size_pixels(size) as f32 / 2.0 + 1.0;
        let r = reach_box(&[(v.x, v.y)], reach, params.bounds);
        self.record(r, params, Kind::Point { size }, &[v], None);
    }
}

impl Binner<'_> {
    /// [`PrimSink::triangle`], covering at the sample `at` of a multisampled
    /// framebuffer (`multisample.rs`) when given: the coverage of the
    /// triangle moved by minus the sample's offset (exact in fixed point),
    /// and the depth plane moved to the sample; the other planes stay at the
    /// pixel centre. Inlined, so that the single-sampled path (`None`)
    /// compiles to what it was.
    #[inline(always)]
    pub(crate) fn triangle_at(
        &mut self,
        v: [&RasterVertex; 3],
        flat: Option<&Varyings>,
        params: &RasterParams,
        at: Option<&crate::multisample::SampleAt>,
    ) {
        self.triangle_points(Edges::window_points(v, params.height), v, flat, params, at)
    }

    /// [`Binner::triangle_at`] of the snapped bottom-up points `p` (the
    /// corners of a multisampled line: `multisample::Fan`), whose planes
    /// are set up from `v`.
    #[inline(always)]
    pub(crate) fn triangle_points(
        &mut self,
        p: [(i64, i64); 3],
        v: [&RasterVertex; 3],
        flat: Option<&Varyings>,
        params: &RasterParams,
        at: Option<&crate::multisample::SampleAt>,
    ) {
        let covered = match at {
            None => p,
            Some(s) => p.map(|(x, y)| (x - s.fixed.0, y - s.fixed.1)),
        };
        let Some(prep) = Prepared::new(covered, params.bounds) else {
            return;
        };
        let draw = self.draw();
        let swap = plane_swap(p);
        let scene = &mut *self.scene;
        let class = scene.class(draw, params, v, swap);
        // The record is made aside, then appended at once (appending it
        // in pieces of a known length, with their inline stores, was 9
        // instructions a triangle more: each piece tests the capacity).
        let rec = &mut scene.record.0;
        let Some(cover) = rec[1..].first_chunk_mut::<{ Prepared::WORDS }>() else {
            return;
        };
        let (n, tag) = prep.encode(cover);
        rec[0] = class | tag << 30;
        let mut len = 1 + n;
        setup_planes(v, swap, flat, params, &mut |k, plane| {
            let plane = match at {
                Some(s) if k == slot::Z => Plane {
                    a0: plane.a0 + (plane.dadx * s.plane.0 + plane.dady * s.plane.1),
                    ..plane
                },
                _ => plane,
            };
            if let Some(to) = rec.get_mut(len..len + 3) {
                to.copy_from_slice(&[plane.a0.to_bits(), plane.dadx.to_bits(), plane.dady.to_bits()]);
                len += 3;
            }
        });
        let entry = TRI | scene.used as u32;
        Scene::append(&mut scene.records, &mut scene.used, rec, len);
        scene.triangles += 1;
        scene.bytes += 4 * len;
        scene.bin(prep.rect(), entry);
        if scene.full() {
            self.flush();
        }
    }
}

impl Binner<'_> {
    /// Records a triangle of a draw whose samples share the shading
    /// ([`Scene::draw_shared`]), covered at each sample `s` of `at` that
    /// `mask` keeps (bit `s`) as [`Binner::triangle_points`] covers it: a
    /// word of the samples that have a pixel inside, then each one's
    /// record (its coverage, and its planes with the depth plane moved to
    /// the sample: the same words as a scene of that sample alone holds),
    /// binned once into the tiles of their boxes. The planes are set up
    /// once for the samples.
    pub(crate) fn triangle_shared(
        &mut self,
        p: [(i64, i64); 3],
        v: [&RasterVertex; 3],
        flat: Option<&Varyings>,
        params: &RasterParams,
        (at, mask): (&[crate::multisample::SampleAt; 4], u32),
    ) {
        let preps: [Option<Prepared>; 4] = std::array::from_fn(|s| {
            let a = &at[s];
            (mask >> s & 1 != 0)
                .then(|| Prepared::new(p.map(|(x, y)| (x - a.fixed.0, y - a.fixed.1)), params.bounds))
                .flatten()
        });
        let present = preps
            .iter()
            .enumerate()
            .fold(0u32, |m, (s, q)| if q.is_some() { m | 1 << s } else { m });
        if present == 0 {
            return;
        }
        let draw = self.draw();
        let swap = plane_swap(p);
        let scene = &mut *self.scene;
        let class = scene.class(draw, params, v, swap);
        // The planes once, the depth plane's place among them kept.
        let mut planes = [0u32; 3 * PLANES];
        let (mut n_planes, mut z) = (0, None);
        setup_planes(v, swap, flat, params, &mut |k, plane| {
            if k == slot::Z {
                z = Some((n_planes, plane));
            }
            if let Some(to) = planes.get_mut(n_planes..n_planes + 3) {
                to.copy_from_slice(&[plane.a0.to_bits(), plane.dadx.to_bits(), plane.dady.to_bits()]);
                n_planes += 3;
            }
        });
        let head = scene.used;
        if scene.records.len() < head + 1 + RECORD {
            Scene::grow(&mut scene.records, head + 1);
        }
        scene.records[head] = present;
        scene.used = head + 1;
        let mut words = 1;
        let mut rect: Option<Rect> = None;
        for (s, prep) in preps.iter().enumerate() {
            let Some(prep) = prep else { continue };
            let rec = &mut scene.record.0;
            let Some(cover) = rec[1..].first_chunk_mut::<{ Prepared::WORDS }>() else {
                return;
            };
            let (n, tag) = prep.encode(cover);
            rec[0] = class | tag << 30;
            let len = 1 + n + n_planes;
            if let Some(to) = rec.get_mut(1 + n..len) {
                to.copy_from_slice(&planes[..n_planes]);
            }
            if let Some((k, plane)) = z {
                // As `triangle_points` moves it, in the same f32 operations.
                let a = &at[s];
                let a0 = plane.a0 + (plane.dadx * a.plane.0 + plane.dady * a.plane.1);
                if let Some(w) = rec.get_mut(1 + n + k) {
                    *w = a0.to_bits();
                }
            }
            Scene::append(&mut scene.records, &mut scene.used, rec, len);
            words += len;
            let r = prep.rect();
            rect = Some(match rect {
                None => r,
                Some(u) => Rect {
                    x0: u.x0.min(r.x0),
                    y0: u.y0.min(r.y0),
                    x1: u.x1.max(r.x1),
                    y1: u.y1.max(r.y1),
                },
            });
        }
        scene.triangles += 1;
        scene.bytes += 4 * words;
        if let Some(r) = rect {
            scene.bin(r, TRI | GROUP | head as u32);
        }
        if scene.full() {
            self.flush();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What a recorded primitive costs, against a copy of its vertices: a
    /// line with its vertices; a lit triangle (1/w, the colour and depth:
    /// six planes) of one pixel, of a 2×2 box partly covered, and a large
    /// one, with their coverage, as [`Binner::triangle`] records them.
    #[test]
    fn a_recorded_primitive_is_smaller_than_its_raster_vertices() {
        let line = std::mem::size_of::<Binned>() + 2 * std::mem::size_of::<Vert>();
        assert!(
            line * 3 < 2 * std::mem::size_of::<RasterVertex>(),
            "{line} bytes a line"
        );
        let params = RasterParams {
            bounds: Rect {
                x0: 0,
                y0: 0,
                x1: 1024,
                y1: 1024,
            },
            depth: Some(DepthFormat::D24),
            height: 1024,
            layout: crate::geometry::varying::VaryingLayout {
                color: true,
                ..Default::default()
            },
            offset: None,
        };
        let at = |x: f32, y: f32| RasterVertex {
            x,
            y,
            y_down: 1024.0 - y,
            z: 0.5,
            inv_w: 1.0,
            v: [0.5; MAX_VARYINGS],
        };
        let bytes = |v: [RasterVertex; 3]| {
            let v = [&v[0], &v[1], &v[2]];
            let p = Edges::window_points(v, params.height);
            let prep = Prepared::new(p, params.bounds).expect("some pixel is inside");
            let (n, _) = prep.encode(&mut [0; Prepared::WORDS]);
            let mut planes = 0;
            setup_planes(v, plane_swap(p), None, &params, &mut |_, _| planes += 1);
            4 * (1 + n + 3 * planes)
        };
        let copied = 3 * std::mem::size_of::<RasterVertex>();
        let one = bytes([at(10.2, 10.2), at(10.9, 10.3), at(10.4, 10.9)]);
        let masked = bytes([at(10.2, 10.2), at(12.4, 10.3), at(10.4, 12.4)]);
        let large = bytes([at(10.0, 10.0), at(500.0, 10.0), at(10.0, 500.0)]);
        assert_eq!((one, masked, large), (84, 92, 132));
        assert!(masked * 6 < copied, "{masked} bytes recorded, {copied} copied");
    }
}
