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
//! Within a tile a primitive is rasterized by the row rasterizer with its
//! bounds cut to the tile: coverage decides each pixel on its own, so the
//! pixels are those of the whole primitive at once.

use super::{reach_box, triangle_box, PrimSink, Rasterize, RasterParams, RasterVertex};
use crate::fragment::FragmentStage;
use crate::framebuffer::{Clear, Framebuffer, Rect};
use crate::geometry::varying::Varyings;
use crate::texture::unit::{SharedPlan, TexturePlan};
use softgl_jit::texture::TextureSet;
use softgl_jit::{DrawTextures, FragmentError, FragmentKey, FragmentUniforms, Specialist, Target};
use std::sync::Arc;

/// Side of a tile, in pixels.
pub const TILE: u32 = 64;

/// A scene is flushed when what it holds passes this many bytes, so a
/// frame of any number of primitives runs in bounded memory.
pub const MEMORY_BOUND: usize = 64 << 20;

/// Bin entries with this bit are clears; the others primitives.
const CLEAR: u32 = 1 << 31;

/// What a draw's fragments run with.
#[derive(Clone, Debug)]
pub struct DrawState {
    pub key: FragmentKey,
    pub uniforms: FragmentUniforms,
    /// `None`: the interpreter runs the key.
    pub specialist: Option<Arc<Specialist>>,
    pub textures: SharedPlan,
}

/// One recorded primitive, as the geometry stage handed it over.
#[derive(Clone, Debug)]
enum Prim {
    Triangle {
        v: [RasterVertex; 3],
        flat: Option<Box<Varyings>>,
    },
    Line {
        v: [RasterVertex; 2],
        width: f32,
        flat: Option<Box<Varyings>>,
    },
    Point {
        v: RasterVertex,
        size: f32,
    },
}

#[derive(Clone, Debug)]
struct Binned {
    draw: u32,
    params: RasterParams,
    prim: Prim,
}

impl Binned {
    /// Rasterizes the primitive's pixels inside `tile` into `sink`.
    fn rasterize(&self, tile: Rect, sink: &mut dyn PrimSink) {
        let params = RasterParams {
            bounds: self.params.bounds.intersect(tile),
            ..self.params
        };
        match &self.prim {
            Prim::Triangle { v, flat } => sink.triangle([&v[0], &v[1], &v[2]], flat.as_deref(), &params),
            Prim::Line { v, width, flat } => sink.line(&v[0], &v[1], *width, flat.as_deref(), &params),
            Prim::Point { v, size } => sink.point(v, *size, &params),
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
    clears: Vec<Clear>,
    /// Per tile, row by row from the bottom: entries into `prims`, or into
    /// `clears` with [`CLEAR`] set, in the order recorded.
    bins: Vec<Vec<u32>>,
    bytes: usize,
    /// See [`Scene::bound`].
    bound: usize,
    peak: usize,
    flushes: u64,
}

impl Scene {
    /// Whether nothing waits to be drawn.
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty() && self.clears.is_empty()
    }

    /// Bytes held (primitives, bin entries, draws): the scene is flushed past [`MEMORY_BOUND`].
    pub fn bytes(&self) -> usize {
        self.bytes
    }

    /// Primitives recorded since the last flush.
    pub fn primitives(&self) -> usize {
        self.prims.len()
    }

    /// Makes the (empty) scene's tiles cover a `width`×`height` framebuffer.
    fn fit(&mut self, width: u32, height: u32) {
        if (self.width, self.height) != (width, height) || self.bins.is_empty() {
            debug_assert!(self.is_empty(), "a scene is flushed before its framebuffer changes");
            self.width = width;
            self.height = height;
            self.tiles_x = width.div_ceil(TILE).max(1);
            let tiles = self.tiles_x as usize * height.div_ceil(TILE).max(1) as usize;
            self.bins = vec![Vec::new(); tiles];
        }
    }

    /// The tiles `r` touches, as index ranges of columns and rows.
    fn tiles_of(&self, r: Rect) -> (std::ops::Range<u32>, std::ops::Range<u32>) {
        (r.x0 / TILE..r.x1.div_ceil(TILE), r.y0 / TILE..r.y1.div_ceil(TILE))
    }

    fn bin(&mut self, r: Rect, entry: u32) {
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
    pub fn draw<'s>(&'s mut self, fb: &'s mut Framebuffer, threads: usize, state: DrawState) -> Binner<'s> {
        self.fit(fb.width(), fb.height());
        Binner {
            scene: self,
            fb,
            threads,
            state,
            draw: None,
            error: None,
        }
    }

    /// Bytes past which a draw flushes ([`MEMORY_BOUND`] unless set).
    pub fn bound(&self) -> usize {
        if self.bound == 0 {
            MEMORY_BOUND
        } else {
            self.bound
        }
    }

    /// Sets the bytes past which a draw flushes (0: [`MEMORY_BOUND`]).
    pub fn set_bound(&mut self, bytes: usize) {
        self.bound = bytes;
    }

    /// The most bytes held at once since the scene was made, and the flushes run.
    pub fn peak(&self) -> (usize, u64) {
        (self.peak, self.flushes)
    }

    /// Runs every tile into `fb` on `threads` threads and empties the scene.
    /// Returns the first error of a fragment stage (in tile order).
    pub fn flush(&mut self, fb: &mut Framebuffer, threads: usize) -> Result<(), FragmentError> {
        if self.is_empty() {
            return Ok(());
        }
        let r = self.run(fb, threads);
        self.peak = self.peak.max(self.bytes);
        self.flushes += 1;
        self.draws.clear();
        self.prims.clear();
        self.clears.clear();
        for b in &mut self.bins {
            b.clear();
        }
        self.bytes = 0;
        r
    }

    fn run(&self, fb: &mut Framebuffer, threads: usize) -> Result<(), FragmentError> {
        debug_assert_eq!((fb.width(), fb.height()), (self.width, self.height));
        let plans: Vec<TexturePlan<'_>> = self.draws.iter().map(|d| d.textures.plan()).collect();
        let sets: Vec<TextureSet<'_>> = plans.iter().map(TexturePlan::set).collect();
        let bands = fb.target().into_bands(TILE);
        let run_band = |(ty, mut band): (usize, Target<'_>)| self.run_band(ty as u32, &mut band, &sets);
        let results: Vec<Result<(), FragmentError>> = if threads <= 1 || bands.len() <= 1 {
            bands.into_iter().enumerate().map(run_band).collect()
        } else {
            super::pool::run(threads, bands.into_iter().enumerate().collect(), run_band)
        };
        results.into_iter().collect()
    }

    /// Runs the tiles of row `ty` into `band`, its rows of the framebuffer.
    fn run_band(&self, ty: u32, band: &mut Target<'_>, sets: &[TextureSet<'_>]) -> Result<(), FragmentError> {
        let mut views: Vec<Option<DrawTextures<'_>>> = Vec::new();
        views.resize_with(self.draws.len(), || None);
        let mut first_error = None;
        for tx in 0..self.tiles_x {
            let tile = Rect {
                x0: tx * TILE,
                y0: ty * TILE,
                x1: ((tx + 1) * TILE).min(self.width),
                y1: ((ty + 1) * TILE).min(self.height),
            };
            let bin = &self.bins[(ty * self.tiles_x + tx) as usize];
            let mut i = 0;
            while i < bin.len() {
                let e = bin[i];
                if e & CLEAR != 0 {
                    self.clears[(e & !CLEAR) as usize].apply(band, tile);
                    i += 1;
                    continue;
                }
                // The run of this draw's primitives shares one fragment stage.
                let d = self.prims[e as usize].draw as usize;
                let end = bin[i..]
                    .iter()
                    .position(|&e| e & CLEAR != 0 || self.prims[e as usize].draw as usize != d)
                    .map_or(bin.len(), |n| i + n);
                let draw = &self.draws[d];
                let specialist = draw.specialist.as_deref();
                let view = views[d].get_or_insert_with(|| {
                    specialist.map_or(DrawTextures::None, |s| s.texture_view(&sets[d]))
                });
                let r = FragmentStage::new(draw.key, draw.uniforms, &sets[d], view, band, specialist).and_then(
                    |mut stage| {
                        for &e in &bin[i..end] {
                            self.prims[e as usize].rasterize(tile, &mut Rasterize(&mut stage));
                        }
                        stage.finish()
                    },
                );
                if let Err(e) = r {
                    first_error.get_or_insert(e);
                }
                i = end;
            }
        }
        first_error.map_or(Ok(()), Err)
    }
}

/// Records one draw's primitives into a scene ([`Scene::draw`]).
pub struct Binner<'s> {
    scene: &'s mut Scene,
    fb: &'s mut Framebuffer,
    threads: usize,
    state: DrawState,
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

    fn record(&mut self, r: Option<Rect>, params: &RasterParams, prim: Prim) {
        let Some(r) = r else { return };
        let draw = match self.draw {
            Some(d) => d,
            None => {
                let d = self.scene.draws.len() as u32;
                self.scene.bytes += std::mem::size_of::<DrawState>();
                self.scene.draws.push(self.state.clone());
                self.draw = Some(d);
                d
            }
        };
        let entry = self.scene.prims.len() as u32;
        self.scene.bytes += std::mem::size_of::<Binned>()
            + match &prim {
                Prim::Triangle { flat: Some(_), .. } | Prim::Line { flat: Some(_), .. } => {
                    std::mem::size_of::<Varyings>()
                }
                _ => 0,
            };
        self.scene.prims.push(Binned {
            draw,
            params: *params,
            prim,
        });
        self.scene.bin(r, entry);
        if self.scene.bytes > self.scene.bound() {
            if let Err(e) = self.scene.flush(self.fb, self.threads) {
                self.error.get_or_insert(e);
            }
            self.draw = None;
        }
    }
}

impl PrimSink for Binner<'_> {
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) {
        let r = triangle_box(v, params);
        let prim = Prim::Triangle {
            v: v.map(|v| *v),
            flat: flat.map(|f| Box::new(*f)),
        };
        self.record(r, params, prim);
    }

    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams) {
        let reach = super::line::line_width_pixels(width) as f32 / 2.0 + 1.0;
        let r = reach_box(&[(a.x, a.y), (b.x, b.y)], reach, params.bounds);
        let prim = Prim::Line {
            v: [*a, *b],
            width,
            flat: flat.map(|f| Box::new(*f)),
        };
        self.record(r, params, prim);
    }

    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams) {
        let reach = super::point::point_size_pixels(size) as f32 / 2.0 + 1.0;
        let r = reach_box(&[(v.x, v.y)], reach, params.bounds);
        self.record(r, params, Prim::Point { v: *v, size });
    }
}
