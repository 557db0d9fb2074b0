//! The fragment stage as the rasterizer sees it: spans are batched and handed
//! to the back end for the draw's key. A triangle's rows arrive as headers
//! ([`SpanSink::row`]) written straight into the batch, whose `BATCH` spans
//! are there from the stage's start: no whole span is zeroed and copied per
//! row (with the row walk in `raster::triangle`, ops 3248 M → 3079 M
//! instructions a two-frame run, callgrind).
//!
//! A flush runs one [`FragmentStage`] a band, switched from draw to draw
//! ([`FragmentStage::set_draw`]), and a [`DrawStage`] a draw, made once: the
//! `thrash` frame (256 draws of 50 small triangles, so about one run of a
//! draw per triangle and tile) made, checked and dropped a stage a run,
//! with the key and uniforms copied and compared and the uniforms splatted
//! again for every batch: 89.7 M → 79.3 M instructions a frame (callgrind,
//! one thread).
//!
//! A row ([`SpanSink::row`]: colours and depths zero) zeroed its slot's five
//! arrays (512 bytes) whenever its draw read any of them from the span:
//! 3.5 M rows in two MuJoCo frames at 640×480 (the depth-only shadow-map
//! passes), 171 M instructions of `memset`. The slots only hold something
//! else after a span copied in ([`SpanSink::span`], a shared draw's
//! per-sample half), so each slot is marked dirty then, and a row zeroes
//! only the arrays its draw reads that are dirty (`zero`); a row within a
//! tile (all of a flush's) is one span, written without the span iterator.

use crate::framebuffer::{Clear, Rect};
use crate::raster::SpanSink;
use softgl_jit::compile::SplatUniforms;
use softgl_jit::shade::slot;
use softgl_jit::texture::{TextureSet, MAX_UNITS};
use softgl_jit::{
    interp, DrawTextures, FragmentError, FragmentKey, FragmentSpan, FragmentUniforms, Planes, Specialist, Target,
    SPAN_MAX,
};
use std::sync::atomic::{AtomicU64, Ordering};

/// Spans handed to the back end at once.
const BATCH: usize = 32;

/// Which back end runs the per-fragment stages.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Backend {
    /// The reference interpreter.
    Interpreter,
    /// Specialists compiled with Cranelift (the default); a key that fails to
    /// compile runs on the interpreter.
    Jit,
}

impl Backend {
    /// `SOFTGL_BACKEND=interp|jit`, else the JIT.
    pub fn from_env() -> Backend {
        Backend::parse(std::env::var("SOFTGL_BACKEND").ok().as_deref())
    }

    /// The back end a `SOFTGL_BACKEND` value names: `interp` (or `interpreter`),
    /// else the JIT.
    pub fn parse(value: Option<&str>) -> Backend {
        match value.map(str::trim) {
            Some("interp") | Some("interpreter") => Backend::Interpreter,
            _ => Backend::Jit,
        }
    }
}

/// What the fragment stages of one draw share, made once a flush (not once
/// per run of a tile: `thrash`'s 256 draws of 50 small triangles made a
/// stage per triangle, 450 instructions each, with the key and uniforms
/// copied, checked and compared each time).
pub struct DrawStage<'t> {
    /// The draw's specialist, when it was compiled for the key.
    specialist: Option<&'t Specialist>,
    key: &'t FragmentKey,
    /// The uniforms, as the specialist reads them (`splats.uniforms`: as
    /// the interpreter does).
    splats: SplatUniforms,
    /// The textures the key's units sample.
    textures: &'t TextureSet<'t>,
    /// Whether the stages read the spans' colours and depths (a key without
    /// a shading stage, or one leaving them to the span).
    span_color: bool,
    span_z: bool,
    /// Bit `u` set when unit `u` samples (its coordinate slots are read).
    tex_units: u8,
    /// The occlusion query counter the key's counted fragments go to.
    samples: Option<&'t AtomicU64>,
}

impl<'t> DrawStage<'t> {
    /// A draw's stages for `key`, checked once here against `target`'s
    /// formats (any band of a framebuffer has the same), sampling
    /// `textures`. `specialist`, if given, runs when it was compiled for
    /// `key`; without one the interpreter runs.
    pub fn new(
        key: &'t FragmentKey,
        uniforms: &'t FragmentUniforms,
        textures: &'t TextureSet<'t>,
        specialist: Option<&'t Specialist>,
        target: &Target<'_>,
    ) -> Result<Self, FragmentError> {
        interp::check_key(key, target)?;
        Ok(DrawStage {
            specialist: specialist.filter(|s| s.key() == key),
            key,
            splats: SplatUniforms::new(uniforms),
            textures,
            span_color: key.shade.is_none_or(|s| !s.color),
            span_z: key.depth.is_some() && key.shade.is_none_or(|s| !s.depth),
            tex_units: key.shade.map_or(0, |s| {
                (0..MAX_UNITS)
                    .filter(|&u| s.tex[u].is_some())
                    .fold(0, |m, u| m | 1 << u)
            }),
            samples: None,
        })
    }

    /// The same stages, their counted fragments (keys that count) added to `samples`.
    pub fn counting_into(self, samples: Option<&'t AtomicU64>) -> Self {
        DrawStage {
            samples: samples.filter(|_| self.key.count),
            ..self
        }
    }

    /// The specialist that runs, if any (else the interpreter).
    pub fn specialist(&self) -> Option<&'t Specialist> {
        self.specialist
    }

    /// The textures the key's units sample.
    pub fn textures(&self) -> &'t TextureSet<'t> {
        self.textures
    }
}

/// Collects spans and runs the fragment stages over them in batches, with the
/// current draw's specialist when there is one, else with the interpreter.
/// Each span names the planes of its primitive among the batch's. One stage
/// runs a whole band: a batch goes on across primitives and tiles as long
/// as the draw stays the same ([`FragmentStage::set_draw`]).
pub struct FragmentStage<'t, 'f> {
    /// The draw the batch's spans are of, and what its specialist reads of
    /// its textures ([`Specialist::texture_view`]).
    draw: Option<(&'t DrawStage<'t>, &'t DrawTextures<'t>)>,
    target: &'t mut Target<'f>,
    /// The batch's spans (`batch[..count]`), `BATCH` of them from the start.
    batch: Vec<FragmentSpan>,
    count: usize,
    /// The planes of the batch's primitives are `planes[..planes_len]`; the
    /// last is the current one's. A primitive writes the slots it uses over
    /// whatever an earlier one left.
    planes: Vec<Planes>,
    planes_len: usize,
    /// Copies of the current draw's [`DrawStage`] flags (read per span).
    span_color: bool,
    span_z: bool,
    /// Bit `i` set when `batch[i]`'s colours (`dirty_color`) or depths
    /// (`dirty_z`) may be other than zero: a span copied in wrote them.
    /// A row ([`SpanSink::row`]) zeroes only those its draw reads and are
    /// not zero already (module docs).
    dirty_color: u32,
    dirty_z: u32,
    /// Those of `dirty_color` and `dirty_z` the current draw reads: the
    /// slots a row must zero.
    zero: u32,
    error: Option<FragmentError>,
}

impl<'t, 'f> FragmentStage<'t, 'f> {
    /// A stage writing into `target`, with no draw yet.
    pub fn new(target: &'t mut Target<'f>) -> Self {
        FragmentStage {
            draw: None,
            target,
            batch: vec![FragmentSpan::new(0, 0); BATCH],
            count: 0,
            planes: Vec::new(),
            planes_len: 0,
            span_color: false,
            span_z: false,
            dirty_color: 0,
            dirty_z: 0,
            zero: 0,
            error: None,
        }
    }

    /// Makes the spans that follow `draw`'s (`view`: what its specialist
    /// reads of its textures): the batch so far runs first unless it is of
    /// the same draw.
    #[inline]
    pub fn set_draw(&mut self, draw: &'t DrawStage<'t>, view: &'t DrawTextures<'t>) {
        if let Some((d, _)) = self.draw {
            if std::ptr::eq(d, draw) {
                return;
            }
        }
        self.run();
        self.hand_over_count();
        // A new draw's primitives write their planes before their spans.
        self.planes_len = 0;
        self.draw = Some((draw, view));
        (self.span_color, self.span_z) = (draw.span_color, draw.span_z);
        self.mark();
    }

    /// Makes `zero` the slots the current draw reads that are dirty.
    #[inline(always)]
    fn mark(&mut self) {
        self.zero = (if self.span_color { self.dirty_color } else { 0 }) | (if self.span_z { self.dirty_z } else { 0 });
    }

    /// Applies `clear` to the part of `tile` in the stage's rows, after the
    /// spans so far.
    pub fn clear(&mut self, clear: &Clear, tile: Rect) {
        self.run();
        clear.apply(self.target, tile);
    }

    /// Runs `f` on the target after the spans so far (writes that bypass
    /// the fragment stages: stencil pixel rectangles).
    pub fn direct(&mut self, f: impl FnOnce(&mut Target<'f>)) {
        self.run();
        f(self.target);
    }

    /// Records `e` after what the batch so far reports.
    pub fn fail(&mut self, e: FragmentError) {
        self.run();
        self.error.get_or_insert(e);
    }

    /// Runs the batch's spans.
    fn run(&mut self) {
        if self.count == 0 {
            return;
        }
        let Some((draw, view)) = self.draw else {
            self.count = 0;
            return;
        };
        let spans = &self.batch[..self.count];
        let planes = &self.planes[..self.planes_len];
        let r = match draw.specialist {
            Some(s) => s.run_splatted(&draw.splats, (draw.textures, view), spans, planes, self.target),
            None => interp::run_with_planes(
                draw.key,
                &draw.splats.uniforms,
                draw.textures,
                spans,
                planes,
                self.target,
            ),
        };
        if let Err(e) = r {
            self.error.get_or_insert(e);
        }
        self.count = 0;
    }

    /// Runs the batch's spans; the current primitive's planes stay, as
    /// planes 0, for its next spans. Only the slots the stages read move (the
    /// colour, fog and depth slots and the sampling units' coordinates: 480
    /// bytes untextured, not all 2 KB of a `Planes`).
    fn flush(&mut self) {
        self.run();
        if self.planes_len > 1 {
            let tex_units = self.draw.map_or(0, |(d, _)| d.tex_units);
            let (head, tail) = self.planes.split_at_mut(self.planes_len - 1);
            let (to, from) = (&mut head[0].coeffs, &tail[0].coeffs);
            to[..slot::TEX0].copy_from_slice(&from[..slot::TEX0]);
            for u in (0..MAX_UNITS).filter(|&u| tex_units & (1 << u) != 0) {
                let k = slot::tex(u);
                to[k..k + 4].copy_from_slice(&from[k..k + 4]);
            }
        }
        self.planes_len = self.planes_len.min(1);
    }

    /// Room for the next primitive's planes: the batch runs when its planes
    /// are full (no later span reads them), the storage grows up to them.
    #[cold]
    #[inline(never)]
    fn make_room(&mut self) {
        if self.planes_len == BATCH {
            self.run();
            self.planes_len = 0;
        }
        if self.planes_len == self.planes.len() {
            self.planes.push(Planes::default());
        }
    }

    /// Adds what the target counted for the current draw to its query's
    /// counter: once a band leaves a draw, not once a batch.
    fn hand_over_count(&mut self) {
        if let Some((d, _)) = self.draw {
            if let Some(c) = d.samples {
                c.fetch_add(self.target.take_samples_passed(), Ordering::Relaxed);
            }
        }
    }

    /// Runs what is left and reports the first error, if any.
    pub fn finish(mut self) -> Result<(), FragmentError> {
        self.run();
        self.hand_over_count();
        self.error.map_or(Ok(()), Err)
    }
}

impl FragmentStage<'_, '_> {
    /// Adds the span of `len` fragments at `(x, y)`, `mask` covered, whose
    /// colours and depths `fill` writes into the batch's slot: what
    /// [`SpanSink::span`] of a span so filled does, without the span
    /// made first and copied (512 bytes a span). Lanes `fill` leaves keep
    /// what the slot held (the stages read only the covered lanes).
    #[inline(always)]
    pub(crate) fn span_filled(
        &mut self,
        (x, y, len): (u32, u32, u32),
        mask: u64,
        fill: impl FnOnce(&mut FragmentSpan),
    ) {
        let planes = self.planes_len.saturating_sub(1) as u32;
        let Some(s) = self.batch.get_mut(self.count) else {
            return;
        };
        (s.x, s.y, s.len, s.mask, s.planes) = (x, y, len, mask, planes);
        if s.live_mask() == 0 {
            return;
        }
        fill(s);
        self.pushed(true, true);
    }

    /// Ends the span just written into the batch's next slot: marks its
    /// colours (`colour`) and depths (`z`) dirty for [`FragmentStage::push_row`],
    /// and runs the batch once it is full.
    #[inline(always)]
    fn pushed(&mut self, colour: bool, z: bool) {
        let bit = 1 << self.count;
        if colour {
            self.dirty_color |= bit;
        }
        if z {
            self.dirty_z |= bit;
        }
        self.mark();
        self.count += 1;
        if self.count == BATCH {
            self.flush();
        }
    }

    /// Adds the span of `len` fragments at `(x, y)`, `mask` covered, with
    /// nothing but the planes ([`SpanSink::row`]).
    #[inline(always)]
    fn push_row(&mut self, y: u32, x: u32, len: u32, mask: u64) {
        let planes = self.planes_len.saturating_sub(1) as u32;
        // `batch` holds `BATCH` spans from the stage's start on.
        let Some(s) = self.batch.get_mut(self.count) else {
            return;
        };
        (s.x, s.y, s.len, s.mask, s.planes) = (x, y, len, mask, planes);
        // The row's colours and depths are zero (`SpanSink::row`): those
        // the draw reads, where a span left others.
        let bit = 1 << self.count;
        if self.zero & bit != 0 {
            self.zero_slot();
        }
        self.count += 1;
        if self.count == BATCH {
            self.flush();
        }
    }

    /// Zeroes the colours and depths of the batch's next slot that the
    /// draw reads ([`FragmentStage::push_row`]).
    #[cold]
    #[inline(never)]
    fn zero_slot(&mut self) {
        let bit = 1 << self.count;
        let Some(s) = self.batch.get_mut(self.count) else {
            return;
        };
        if self.span_color && self.dirty_color & bit != 0 {
            for c in [&mut s.r, &mut s.g, &mut s.b, &mut s.a] {
                *c = [0; SPAN_MAX];
            }
            self.dirty_color &= !bit;
        }
        if self.span_z && self.dirty_z & bit != 0 {
            s.z = [0; SPAN_MAX];
            self.dirty_z &= !bit;
        }
        self.mark();
    }

    /// A row of more than [`SPAN_MAX`] fragments ([`SpanSink::row`]).
    #[inline(never)]
    fn long_row(&mut self, y: u32, x0: u32, x1: u32) {
        for (x, len, mask) in crate::raster::row_spans(x0, x1) {
            self.push_row(y, x, len, mask);
        }
    }
}

impl SpanSink for FragmentStage<'_, '_> {
    fn span(&mut self, span: &FragmentSpan) {
        if span.live_mask() == 0 {
            return;
        }
        // Only what the stages read is copied: with planes, the header.
        // (`batch` holds `BATCH` spans from the stage's start on.)
        let Some(s) = self.batch.get_mut(self.count) else {
            return;
        };
        (s.x, s.y, s.len, s.mask) = (span.x, span.y, span.len, span.mask);
        s.planes = self.planes_len.saturating_sub(1) as u32;
        if self.span_color {
            (s.r, s.g, s.b, s.a) = (span.r, span.g, span.b, span.a);
        }
        if self.span_z {
            s.z = span.z;
        }
        self.pushed(self.span_color, self.span_z);
    }

    #[inline(always)]
    fn row(&mut self, y: u32, x0: u32, x1: u32) {
        // A row within a tile (every row of a scene's flush) is one span.
        let last = x1.wrapping_sub(x0);
        if last < SPAN_MAX as u32 {
            self.push_row(y, x0, last + 1, u64::MAX >> (63 - last));
        } else {
            self.long_row(y, x0, x1);
        }
    }

    #[inline]
    fn planes_mut(&mut self) -> Option<&mut Planes> {
        if self.planes_len == BATCH || self.planes_len == self.planes.len() {
            self.make_room();
        }
        self.planes_len += 1;
        self.planes.get_mut(self.planes_len - 1)
    }
}
