//! The fragment stage as the rasterizer sees it: spans are batched and handed
//! to the back end for the draw's key. A triangle's rows arrive as headers
//! ([`SpanSink::row`]) written straight into the batch, whose `BATCH` spans
//! are there from the stage's start: no whole span is zeroed and copied per
//! row (with the row walk in `raster::triangle`, ops 3248 M → 3079 M
//! instructions a two-frame run, callgrind).

use crate::raster::SpanSink;
use softgl_jit::shade::slot;
use softgl_jit::texture::{TextureSet, MAX_UNITS};
use softgl_jit::{
    interp, DrawTextures, FragmentError, FragmentKey, FragmentSpan, FragmentUniforms, Planes, Specialist, Target,
    SPAN_MAX,
};

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

/// The storage of a [`FragmentStage`]'s batch, kept from one stage to the
/// next (a tile runs a stage per run of one draw's primitives).
#[derive(Debug, Default)]
pub struct StageBuffers {
    batch: Vec<FragmentSpan>,
    planes: Vec<Planes>,
}

/// Collects spans and runs the fragment stages over them in batches, with the
/// key's specialist when there is one, else with the interpreter. Each span
/// names the planes of its primitive among the batch's.
pub struct FragmentStage<'t, 'f> {
    specialist: Option<&'t Specialist>,
    key: FragmentKey,
    uniforms: FragmentUniforms,
    /// The textures the key's units sample.
    textures: &'t TextureSet<'t>,
    /// What the specialist reads of them, made once for the draw.
    view: &'t DrawTextures<'t>,
    target: &'t mut Target<'f>,
    /// The batch's spans (`batch[..count]`) and planes, in storage reused
    /// from stage to stage.
    buffers: &'t mut StageBuffers,
    count: usize,
    /// Whether the stages read the spans' colours and depths (a key without
    /// a shading stage, or one leaving them to the span).
    span_color: bool,
    span_z: bool,
    /// The planes of the batch's primitives are `planes[..planes_len]`; the
    /// last is the current one's. A primitive writes the slots it uses over
    /// whatever an earlier one left.
    planes_len: usize,
    /// Bit `u` set when unit `u` samples (its coordinate slots are read).
    tex_units: u8,
    error: Option<FragmentError>,
}

impl<'t, 'f> FragmentStage<'t, 'f> {
    /// A stage for `key`, checked against `target` once here, sampling
    /// `textures` (`view`: what `specialist` reads of them,
    /// [`Specialist::texture_view`]). `specialist`, if given, must have been
    /// compiled for `key`; without one the interpreter runs.
    pub fn new(
        key: FragmentKey,
        uniforms: FragmentUniforms,
        textures: &'t TextureSet<'t>,
        view: &'t DrawTextures<'t>,
        target: &'t mut Target<'f>,
        specialist: Option<&'t Specialist>,
        buffers: &'t mut StageBuffers,
    ) -> Result<Self, FragmentError> {
        interp::check_key(&key, target)?;
        buffers.batch.resize_with(BATCH, || FragmentSpan::new(0, 0));
        let specialist = specialist.filter(|s| *s.key() == key);
        Ok(FragmentStage {
            view,
            specialist,
            span_color: key.shade.is_none_or(|s| !s.color),
            span_z: key.depth.is_some() && key.shade.is_none_or(|s| !s.depth),
            count: 0,
            key,
            uniforms,
            textures,
            target,
            buffers,
            planes_len: 0,
            tex_units: key.shade.map_or(0, |s| {
                (0..MAX_UNITS)
                    .filter(|&u| s.tex[u].is_some())
                    .fold(0, |m, u| m | 1 << u)
            }),
            error: None,
        })
    }

    /// Runs the batch's spans.
    fn run(&mut self) {
        if self.count == 0 {
            return;
        }
        let spans = &self.buffers.batch[..self.count];
        let planes = &self.buffers.planes[..self.planes_len];
        let r = match self.specialist {
            Some(s) => s.run_with_view(&self.uniforms, (self.textures, self.view), spans, planes, self.target),
            None => interp::run_with_planes(&self.key, &self.uniforms, self.textures, spans, planes, self.target),
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
            let (head, tail) = self.buffers.planes.split_at_mut(self.planes_len - 1);
            let (to, from) = (&mut head[0].coeffs, &tail[0].coeffs);
            to[..slot::TEX0].copy_from_slice(&from[..slot::TEX0]);
            for u in (0..MAX_UNITS).filter(|&u| self.tex_units & (1 << u) != 0) {
                let k = slot::tex(u);
                to[k..k + 4].copy_from_slice(&from[k..k + 4]);
            }
        }
        self.planes_len = self.planes_len.min(1);
    }

    /// Runs what is left and reports the first error, if any.
    pub fn finish(mut self) -> Result<(), FragmentError> {
        self.flush();
        self.error.map_or(Ok(()), Err)
    }
}

impl SpanSink for FragmentStage<'_, '_> {
    fn span(&mut self, span: &FragmentSpan) {
        if span.live_mask() == 0 {
            return;
        }
        // Only what the stages read is copied: with planes, the header.
        // (`batch` holds `BATCH` spans from the stage's start on.)
        let Some(s) = self.buffers.batch.get_mut(self.count) else {
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
        self.count += 1;
        if self.count == BATCH {
            self.flush();
        }
    }

    #[inline]
    fn row(&mut self, y: u32, x0: u32, x1: u32) {
        let planes = self.planes_len.saturating_sub(1) as u32;
        for (x, len, mask) in crate::raster::row_spans(x0, x1) {
            // `batch` holds `BATCH` spans from the stage's start on.
            let Some(s) = self.buffers.batch.get_mut(self.count) else {
                return;
            };
            (s.x, s.y, s.len, s.mask, s.planes) = (x, y, len, mask, planes);
            // The row's colours and depths are zero (`SpanSink::row`).
            if self.span_color | self.span_z {
                for c in [&mut s.r, &mut s.g, &mut s.b, &mut s.a] {
                    *c = [0; SPAN_MAX];
                }
                s.z = [0; SPAN_MAX];
            }
            self.count += 1;
            if self.count == BATCH {
                self.flush();
            }
        }
    }

    fn planes_mut(&mut self) -> Option<&mut Planes> {
        if self.planes_len == BATCH {
            // A new primitive: no later span reads the batch's planes.
            self.run();
            self.planes_len = 0;
        }
        if self.planes_len == self.buffers.planes.len() {
            self.buffers.planes.push(Planes::default());
        }
        self.planes_len += 1;
        Some(&mut self.buffers.planes[self.planes_len - 1])
    }
}
