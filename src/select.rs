//! Selection and feedback (GL 1.5 §5.2, §5.3), as Mesa 22.3.6 does them
//! (`src/mesa/main/feedback.c`, and `state_tracker/st_cb_feedback.c`: the
//! draw module's pipeline with a last stage that records instead of
//! rasterizing). In `GL_SELECT` and `GL_FEEDBACK` render modes a draw runs
//! the geometry pipeline as far as clipping, culling and polygon mode, and
//! its primitives reach [`ModeSink`] instead of the rasterizer: window
//! coordinates as llvmpipe's rasterizer would get them.
//!
//! The buffers are owned here; the C ABI copies what was written into the
//! application's buffer when the mode is left (GL leaves the buffer's
//! contents undefined until then).

use crate::error::{GlError, GlResult};
use crate::geometry::varying::{VaryingLayout, Varyings};
use crate::raster::{PrimSink, RasterParams, RasterVertex};
use glam::Vec4;

/// `GL_MAX_NAME_STACK_DEPTH` (Mesa's `MAX_NAME_STACK_DEPTH`).
pub const MAX_NAME_STACK_DEPTH: usize = 64;

/// `glRenderMode`'s modes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RenderMode {
    #[default]
    Render,
    Select,
    Feedback,
}

/// `glFeedbackBuffer`'s types: what a vertex writes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FeedbackType {
    #[default]
    D2,
    D3,
    D3Color,
    D3ColorTexture,
    D4ColorTexture,
}

/// The feedback tokens (`GL_POINT_TOKEN`, …), as GL numbers them.
pub mod token {
    pub const PASS_THROUGH: f32 = 0x0700 as f32;
    pub const POINT: f32 = 0x0701 as f32;
    pub const LINE: f32 = 0x0702 as f32;
    pub const POLYGON: f32 = 0x0703 as f32;
    pub const BITMAP: f32 = 0x0704 as f32;
    pub const DRAW_PIXEL: f32 = 0x0705 as f32;
    pub const COPY_PIXEL: f32 = 0x0706 as f32;
    pub const LINE_RESET: f32 = 0x0707 as f32;
}

/// Selection state: the buffer, the name stack, the pending hit.
#[derive(Clone, Debug, Default)]
pub struct Selection {
    /// `glSelectBuffer`'s size, and the values written (at most `size`).
    pub size: usize,
    pub buffer: Vec<u32>,
    /// Values a hit record has produced, written or not (overflow when > size).
    pub count: usize,
    pub hits: i32,
    pub names: Vec<u32>,
    hit: bool,
    min_z: f32,
    max_z: f32,
}

impl Selection {
    fn write(&mut self, value: u32) {
        if self.count < self.size {
            self.buffer.push(value);
        }
        self.count += 1;
    }

    /// Mesa's `_mesa_update_hitflag`.
    pub fn hit(&mut self, z: f32) {
        self.hit = true;
        self.min_z = self.min_z.min(z);
        self.max_z = self.max_z.max(z);
    }

    /// Mesa's `update_hit_record` (no hardware select on llvmpipe): a
    /// record of the name stack when a primitive hit since the last one.
    fn record(&mut self) {
        if !self.hit {
            return;
        }
        // [0, 1] times 2^32 - 1 in f32 (2^32), then C's float-to-unsigned
        // conversion, which x86-64 makes through a 64-bit integer (1.0 gives 0).
        let scale = u32::MAX as f32;
        let (zmin, zmax) = ((scale * self.min_z) as i64 as u32, (scale * self.max_z) as i64 as u32);
        self.write(self.names.len() as u32);
        self.write(zmin);
        self.write(zmax);
        for i in 0..self.names.len() {
            self.write(self.names[i]);
        }
        self.hit = false;
        self.min_z = 1.0;
        self.max_z = -1.0;
        self.hits += 1;
    }

    fn reset_names(&mut self) {
        self.names.clear();
        self.hit = false;
        self.min_z = 1.0;
        self.max_z = 0.0;
    }
}

/// Feedback state: the buffer and its type.
#[derive(Clone, Debug, Default)]
pub struct Feedback {
    pub ty: FeedbackType,
    pub size: usize,
    pub buffer: Vec<f32>,
    pub count: usize,
    /// A line stipple reset is pending (the next line is a `GL_LINE_RESET_TOKEN`).
    reset: bool,
}

impl Feedback {
    /// Mesa's `_mesa_feedback_token`.
    pub fn token(&mut self, value: f32) {
        if self.count < self.size {
            self.buffer.push(value);
        }
        self.count += 1;
    }

    /// Mesa's `_mesa_feedback_vertex`: window x, y, z, clip w, colour, texture coordinates.
    pub fn vertex(&mut self, win: [f32; 4], color: Vec4, tex: Vec4) {
        self.token(win[0]);
        self.token(win[1]);
        if self.ty != FeedbackType::D2 {
            self.token(win[2]);
        }
        if self.ty == FeedbackType::D4ColorTexture {
            self.token(win[3]);
        }
        if !matches!(self.ty, FeedbackType::D2 | FeedbackType::D3) {
            color.to_array().into_iter().for_each(|c| self.token(c));
        }
        if matches!(self.ty, FeedbackType::D3ColorTexture | FeedbackType::D4ColorTexture) {
            tex.to_array().into_iter().for_each(|c| self.token(c));
        }
    }
}

/// What a mode wrote, handed back when it is left: the selection buffer's
/// or the feedback buffer's values (at most the buffer's size).
#[derive(Clone, Debug, Default, PartialEq)]
pub enum ModeOutput {
    #[default]
    None,
    Select(Vec<u32>),
    Feedback(Vec<f32>),
}

/// Render mode, selection and feedback state of a context.
#[derive(Clone, Debug, Default)]
pub struct RenderModeState {
    pub mode: RenderMode,
    pub select: Selection,
    pub feedback: Feedback,
}

impl RenderModeState {
    /// `glRenderMode`: the hits or feedback values of the mode left (−1
    /// on overflow, 0 from `GL_RENDER`). Errors as Mesa's `_mesa_RenderMode`:
    /// entering a mode whose buffer was never given is `GL_INVALID_OPERATION`
    /// (recorded, the mode still changes).
    pub fn set_mode(&mut self, mode: RenderMode) -> (i32, ModeOutput, Option<GlError>) {
        let (result, output) = match self.mode {
            RenderMode::Render => (0, ModeOutput::None),
            RenderMode::Select => {
                let s = &mut self.select;
                s.record();
                let r = if s.count > s.size { -1 } else { s.hits };
                s.count = 0;
                s.hits = 0;
                s.reset_names();
                (r, ModeOutput::Select(std::mem::take(&mut s.buffer)))
            }
            RenderMode::Feedback => {
                let f = &mut self.feedback;
                let r = if f.count > f.size { -1 } else { f.count as i32 };
                f.count = 0;
                (r, ModeOutput::Feedback(std::mem::take(&mut f.buffer)))
            }
        };
        let error = match mode {
            RenderMode::Render => None,
            RenderMode::Select => {
                self.select.buffer.clear();
                (self.select.size == 0).then_some(GlError::InvalidOperation)
            }
            RenderMode::Feedback => {
                self.feedback.buffer.clear();
                self.feedback.reset = false;
                (self.feedback.size == 0).then_some(GlError::InvalidOperation)
            }
        };
        self.mode = mode;
        (result, output, error)
    }

    /// `glSelectBuffer`.
    pub fn select_buffer(&mut self, size: i32) -> GlResult {
        if size < 0 {
            return Err(GlError::InvalidValue);
        }
        if self.mode == RenderMode::Select {
            return Err(GlError::InvalidOperation);
        }
        let s = &mut self.select;
        (s.size, s.count, s.hit, s.min_z, s.max_z) = (size as usize, 0, false, 1.0, 0.0);
        s.buffer.clear();
        Ok(())
    }

    /// `glFeedbackBuffer` (its type already checked).
    pub fn feedback_buffer(&mut self, size: i32, ty: FeedbackType) -> GlResult {
        if self.mode == RenderMode::Feedback {
            return Err(GlError::InvalidOperation);
        }
        if size < 0 {
            return Err(GlError::InvalidValue);
        }
        let f = &mut self.feedback;
        (f.ty, f.size, f.count) = (ty, size as usize, 0);
        f.buffer.clear();
        Ok(())
    }

    /// `glPassThrough`: a token in feedback mode, nothing otherwise.
    pub fn pass_through(&mut self, value: f32) {
        if self.mode == RenderMode::Feedback {
            self.feedback.token(token::PASS_THROUGH);
            self.feedback.token(value);
        }
    }

    /// `glInitNames` (ignored outside select mode).
    pub fn init_names(&mut self) {
        if self.mode == RenderMode::Select {
            self.select.record();
            self.select.reset_names();
        }
    }

    /// `glLoadName`.
    pub fn load_name(&mut self, name: u32) -> GlResult {
        if self.mode != RenderMode::Select {
            return Ok(());
        }
        if self.select.names.is_empty() {
            return Err(GlError::InvalidOperation);
        }
        self.select.record();
        *self.select.names.last_mut().expect("not empty") = name;
        Ok(())
    }

    /// `glPushName`.
    pub fn push_name(&mut self, name: u32) -> GlResult {
        if self.mode != RenderMode::Select {
            return Ok(());
        }
        if self.select.names.len() >= MAX_NAME_STACK_DEPTH {
            return Err(GlError::StackOverflow);
        }
        self.select.record();
        self.select.names.push(name);
        Ok(())
    }

    /// `glPopName`.
    pub fn pop_name(&mut self) -> GlResult {
        if self.mode != RenderMode::Select {
            return Ok(());
        }
        if self.select.names.is_empty() {
            return Err(GlError::StackUnderflow);
        }
        self.select.record();
        self.select.names.pop();
        Ok(())
    }

    /// The sink a draw's primitives reach in this (non-render) mode.
    /// A valid raster position set (`glRasterPos`, `glWindowPos`): in
    /// select mode a hit at its window z (GL 1.5 §5.2; Mesa's
    /// `_mesa_RasterPos` and `window_pos3f`, `main/rastpos.c`).
    pub fn raster_hit(&mut self, z: f32) {
        if self.mode == RenderMode::Select {
            self.select.hit(z);
        }
    }

    /// A bitmap or pixel rectangle at the valid raster position `r` outside
    /// render mode: in feedback mode `token` (`GL_BITMAP_TOKEN`, …) and the
    /// raster position as a vertex (its window coordinates and w as they are,
    /// the raster colour and unit 0's coordinates); in select mode nothing
    /// (GL 1.5 §5.3, Mesa's `main/drawpix.c`). `false` in render mode: draw it.
    pub fn raster_primitive(&mut self, token: f32, r: &crate::raster_pos::RasterPos) -> bool {
        match self.mode {
            RenderMode::Render => false,
            RenderMode::Select => true,
            RenderMode::Feedback => {
                self.feedback.token(token);
                self.feedback.vertex(r.window, r.color, r.tex_coords[0]);
                true
            }
        }
    }

    pub fn sink(&mut self, layout: VaryingLayout, color: Vec4, tex: Vec4) -> ModeSink<'_> {
        ModeSink {
            state: self,
            layout,
            color,
            tex,
        }
    }
}

/// The last stage of a draw in select or feedback mode (Mesa's
/// `select_stage` and `feedback_stage`).
pub struct ModeSink<'a> {
    state: &'a mut RenderModeState,
    layout: VaryingLayout,
    /// The current colour and texture coordinates of unit 0, written when
    /// the draw's vertices do not carry them (as `feedback_vertex` does).
    color: Vec4,
    tex: Vec4,
}

impl ModeSink<'_> {
    /// A vertex's window coordinates, clip w, colour (each vertex its own,
    /// flat shading or not: llvmpipe, not the draw module, flattens) and
    /// coordinates of unit 0. Window y is `height - y` of the top-down
    /// viewport's y, as `feedback_vertex` computes it.
    fn vertex(&mut self, v: &RasterVertex, height: f32) {
        let slot = |v: &Varyings, o: Option<usize>, d: Vec4| o.map_or(d, |o| Vec4::from_slice(&v[o..o + 4]));
        let color = slot(&v.v, self.layout.color(), self.color);
        let tex = slot(&v.v, self.layout.tex(0), self.tex);
        let win = [v.x, height - v.y_down, v.z as f32, 1.0 / v.inv_w];
        self.state.feedback.vertex(win, color, tex);
    }

    fn vertices(&mut self, vs: &[&RasterVertex], params: &RasterParams, tokens: &[f32]) {
        match self.state.mode {
            RenderMode::Select => vs.iter().for_each(|v| self.state.select.hit(v.z as f32)),
            RenderMode::Feedback => {
                tokens.iter().for_each(|&t| self.state.feedback.token(t));
                vs.iter().for_each(|v| self.vertex(v, params.height as f32));
            }
            RenderMode::Render => {}
        }
    }
}

impl PrimSink for ModeSink<'_> {
    fn triangle(&mut self, v: [&RasterVertex; 3], _flat: Option<&Varyings>, params: &RasterParams) {
        self.vertices(&v, params, &[token::POLYGON, 3.0]);
    }

    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, _w: f32, _flat: Option<&Varyings>, p: &RasterParams) {
        let t = if std::mem::take(&mut self.state.feedback.reset) {
            token::LINE_RESET
        } else {
            token::LINE
        };
        self.vertices(&[a, b], p, &[t]);
    }

    fn point(&mut self, v: &RasterVertex, _size: f32, params: &RasterParams) {
        self.vertices(&[v], params, &[token::POINT]);
    }

    fn reset_stipple(&mut self) {
        self.state.feedback.reset = true;
    }
}
