//! Which colours a `glBegin`/`glEnd` draw carries per vertex, the way Mesa's
//! immediate mode decides it (`docs/llvmpipe-facts.md` §20): the colours in
//! its vertex format vary, the others are the current values, which Mesa's
//! fixed-function fragment shader reads as constants (uniforms).
//!
//! Mesa buffers the vertices of `glBegin`/`glEnd` and draws them later with
//! the vertex format `exec->vtx.enabled` (`vbo/vbo_exec_api.c`). softgl draws
//! at `end`; [`VertexFormat`] follows that format: the draw at `end` uses the
//! format of its vertices, which is Mesa's format when it draws them (a new
//! attribute makes Mesa draw the vertices buffered before it first).
//!
//! [`ImmediateRun`] is a display list's `glBegin` … `glEnd` of `glVertex`,
//! `glNormal`, `glColor` and `glTexCoord` calls compiled into arrays (what
//! Mesa's `vbo_save` does), which [`crate::Context::draw_run`] replays as one
//! draw: the vertices are made from the arrays and the current attributes
//! in one pass into the buffer `begin`/`end` uses, the vertex format steps
//! through [`VertexFormat::run`], and the draw is `end`'s. Before, a list
//! held a boxed closure per call (3.2 M `Arc`s for lit16list's 1.6 M
//! vertices, ~200 MB chased through the heap at every `glCallList`, each
//! call replayed through the attribute path); a run holds 28 bytes a vertex
//! (position, normal) read in order. Callgrind, lit16list
//! (`osmesa/bench/instructions.sh lit16list`): 2.401 G instructions a frame
//! before, 2.334 G after (lit16, the same calls made at once: 2.459 G;
//! llvmpipe's lit16list 2.398 G). Where the cycles went: last-level cache
//! misses (callgrind `--cache-sim=yes`, `fill lit16list 1`: the compile and
//! two frames, one thread) 4.20 M reads and 4.29 M writes before, 0.61 M
//! and 1.88 M after.

use crate::context::CurrentAttribs;
use crate::geometry::InVertex;
use crate::state::PrimitiveMode;
use glam::{Vec3, Vec4};

/// [`VertexFormat`] bit of the primary colour (`glColor`).
pub(crate) const COLOR: u8 = 1;
/// [`VertexFormat`] bit of the secondary colour (`glSecondaryColor`).
pub(crate) const SECONDARY: u8 = 2;

/// Mesa's immediate-mode vertex format, as far as the colours go.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct VertexFormat {
    /// [`COLOR`], [`SECONDARY`]: the colours in the format.
    attribs: u8,
    /// Whether a vertex was given since the format was last emptied
    /// (`exec->vtx.attr[VBO_ATTRIB_POS].size`).
    pos: bool,
    /// Whether a `glEnd` left vertices to draw (`NeedFlush & FLUSH_STORED_VERTICES`).
    pending: bool,
    /// Vertices buffered since Mesa last drew (`exec->vtx.vert_count`).
    buffered: usize,
}

impl VertexFormat {
    /// A colour call (`bit`), between `begin` and `end` when `inside`
    /// (`vbo_exec_fixup_vertex` → `vbo_exec_wrap_upgrade_vertex`): a colour
    /// new to the format draws the buffered vertices first, and outside
    /// `begin`/`end` with more than 8 of them, it empties the format before.
    #[inline]
    pub(crate) fn attrib(&mut self, bit: u8, inside: bool) {
        if self.attribs & bit != 0 {
            return;
        }
        self.add(bit, inside);
    }

    /// [`VertexFormat::attrib`] for a colour not in the format yet: once per
    /// format, out of the way of the attribute calls.
    #[cold]
    fn add(&mut self, bit: u8, inside: bool) {
        if !inside && self.buffered > 8 {
            self.reset();
        }
        self.buffered = 0;
        self.attribs |= bit;
    }

    /// A vertex between `begin` and `end`.
    #[inline]
    pub(crate) fn vertex(&mut self) {
        self.pos = true;
        self.buffered += 1;
    }

    /// `glBegin` (`_mesa_Begin`): attributes given since the format was last
    /// emptied but no vertex yet are current values, not a format.
    pub(crate) fn begin(&mut self) {
        if self.attribs != 0 && !self.pos {
            self.reset();
        }
    }

    /// `glEnd` after `count` vertices.
    pub(crate) fn end(&mut self, count: usize) {
        self.pending |= count > 0;
    }

    /// A state change or draw call (`FLUSH_VERTICES`, `FLUSH_FOR_DRAW`):
    /// vertices left by `glEnd` are drawn and the format is emptied.
    pub(crate) fn flush(&mut self) {
        if self.pending {
            self.reset();
        }
    }

    /// A display list's `glBegin` … `glEnd` ([`ImmediateRun`]) of `count`
    /// vertices whose first colour call came after `color_at` of them: the
    /// same steps as its calls (`begin`, `vertex` × `color_at`,
    /// `attrib(COLOR, true)`, `vertex` × the rest, `end`), at once.
    pub(crate) fn run(&mut self, color_at: Option<usize>, count: usize) {
        self.begin();
        let mut rest = count;
        if let Some(k) = color_at {
            self.pos |= k > 0;
            self.buffered += k;
            self.attrib(COLOR, true);
            rest = count - k;
        }
        self.pos |= rest > 0;
        self.buffered += rest;
        self.end(count);
    }

    /// Whether the colour `bit` is in the format (varies per vertex).
    pub(crate) fn has(&self, bit: u8) -> bool {
        self.attribs & bit != 0
    }

    /// `vbo_reset_all_attr`.
    fn reset(&mut self) {
        *self = VertexFormat::default();
    }
}

/// One attribute of an [`ImmediateRun`]: its value at each vertex from the
/// first call that set it on (`first`), and its value after the run.
#[derive(Clone, Debug)]
struct RunAttrib<T> {
    /// Vertices given before the first call setting it (`None`: never set);
    /// those take the current value at replay.
    first: Option<usize>,
    /// The value at vertex `first + i`.
    vals: Vec<T>,
    /// The value the last call set.
    last: T,
}

impl<T: Copy> RunAttrib<T> {
    fn new(zero: T) -> RunAttrib<T> {
        RunAttrib {
            first: None,
            vals: Vec::new(),
            last: zero,
        }
    }

    fn set(&mut self, v: T, vertices: usize) {
        self.first.get_or_insert(vertices);
        self.last = v;
    }

    #[inline]
    fn vertex(&mut self) {
        if self.first.is_some() {
            self.vals.push(self.last);
        }
    }

    /// The value at vertex `i`, when set by then.
    #[inline]
    fn at(&self, i: usize) -> Option<T> {
        let f = self.first?;
        i.checked_sub(f).and_then(|k| self.vals.get(k)).copied()
    }

    /// `(first, vals)` once set (`first` may be the vertex count: set after the last one).
    fn per_vertex(&self) -> Option<(usize, &[T])> {
        self.first.map(|f| (f, &self.vals[..]))
    }
}

/// A display list's `glBegin(mode)`, its `glVertex`, `glNormal`, `glColor`
/// and `glTexCoord` calls, and (when `ended`) its `glEnd`, compiled into
/// arrays (Mesa's `vbo_save` does the same): replayed by
/// [`crate::Context::draw_run`] as one draw, where the calls cost two C ABI
/// calls and a boxed closure each per vertex. A run keeps each attribute
/// from the call that first set it on; the vertices before take the current
/// value when the list runs, as the calls would. Compiling appends to
/// vectors: no allocation per vertex (amortized growth).
#[derive(Clone, Debug)]
pub struct ImmediateRun {
    mode: PrimitiveMode,
    ended: bool,
    pos: Vec<Vec4>,
    normal: RunAttrib<Vec3>,
    color: RunAttrib<Vec4>,
    /// Unit 0's (`glTexCoord`).
    tex: RunAttrib<Vec4>,
}

impl ImmediateRun {
    /// `glBegin(mode)`.
    pub fn new(mode: PrimitiveMode) -> ImmediateRun {
        ImmediateRun {
            mode,
            ended: false,
            pos: Vec::new(),
            normal: RunAttrib::new(Vec3::ZERO),
            color: RunAttrib::new(Vec4::ZERO),
            tex: RunAttrib::new(Vec4::ZERO),
        }
    }

    /// `glVertex4f`.
    #[inline]
    pub fn vertex4(&mut self, x: f32, y: f32, z: f32, w: f32) {
        self.pos.push(Vec4::new(x, y, z, w));
        self.normal.vertex();
        self.color.vertex();
        self.tex.vertex();
    }

    /// `glNormal3f`.
    #[inline]
    pub fn normal3(&mut self, x: f32, y: f32, z: f32) {
        self.normal.set(Vec3::new(x, y, z), self.pos.len());
    }

    /// `glColor4f`.
    #[inline]
    pub fn color4(&mut self, r: f32, g: f32, b: f32, a: f32) {
        self.color.set(Vec4::new(r, g, b, a), self.pos.len());
    }

    /// `glTexCoord4f` (unit 0).
    #[inline]
    pub fn tex_coord(&mut self, c: [f32; 4]) {
        self.tex.set(Vec4::from_array(c), self.pos.len());
    }

    /// `glEnd`; a run never ended replays its calls alone (a list with a
    /// `glBegin` and no `glEnd`).
    pub fn end(&mut self) {
        self.ended = true;
        self.pos.shrink_to_fit();
        self.normal.vals.shrink_to_fit();
        self.color.vals.shrink_to_fit();
        self.tex.vals.shrink_to_fit();
    }

    pub fn mode(&self) -> PrimitiveMode {
        self.mode
    }

    pub fn ended(&self) -> bool {
        self.ended
    }

    pub fn len(&self) -> usize {
        self.pos.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    /// How many vertices came before the first colour call.
    pub(crate) fn color_at(&self) -> Option<usize> {
        self.color.first
    }

    /// Unit 0's texture coordinates at vertex `i`, when a call set them by then.
    #[inline]
    pub(crate) fn tex_at(&self, i: usize) -> Option<Vec4> {
        self.tex.at(i)
    }

    /// The vertices, as the calls would make them with `before` current
    /// at `glBegin`, into `out` (emptied first): one pass per attribute
    /// over an L2-sized buffer, no call per vertex.
    pub(crate) fn fill(&self, before: &CurrentAttribs, out: &mut Vec<InVertex>) {
        out.clear();
        let t = before.vertex(Vec4::ZERO, 0);
        // Positions and normals in one pass (lit16list: a normal per
        // vertex), the colours, when given, in a second.
        let (f, normals) = self.normal.per_vertex().unwrap_or((self.pos.len(), &[]));
        let (head, tail) = self.pos.split_at(f.min(self.pos.len()));
        out.extend(head.iter().map(|&pos| InVertex { pos, ..t }));
        out.extend(
            tail.iter()
                .zip(normals)
                .map(|(&pos, &normal)| InVertex { pos, normal, ..t }),
        );
        if let Some((f, vals)) = self.color.per_vertex() {
            for (v, &c) in out[f..].iter_mut().zip(vals) {
                v.color = c;
            }
        }
    }

    /// The current attributes after the run's calls.
    pub(crate) fn apply_last(&self, current: &mut CurrentAttribs) {
        if self.normal.first.is_some() {
            current.normal = self.normal.last.into();
        }
        if self.color.first.is_some() {
            current.color = self.color.last;
        }
        if self.tex.first.is_some() {
            current.tex_coords[0] = self.tex.last;
        }
    }

    /// The run's calls themselves, one by one, on `gl`: what the list does
    /// where the run cannot be one draw (called between `glBegin` and
    /// `glEnd`, or never ended). Setting an attribute again to the value it
    /// holds changes nothing GL can see, so each is set before every vertex
    /// from its first call on.
    pub(crate) fn replay(&self, gl: &mut crate::Context) -> crate::GlResult {
        let _ = gl.begin(self.mode);
        for (i, p) in self.pos.iter().enumerate() {
            if let Some(n) = self.normal.at(i) {
                gl.normal3(n.x, n.y, n.z);
            }
            if let Some(c) = self.color.at(i) {
                gl.color4(c.x, c.y, c.z, c.w);
            }
            if let Some(t) = self.tex.at(i) {
                gl.tex_coord(t.to_array());
            }
            gl.vertex4(p.x, p.y, p.z, p.w);
        }
        if self.normal.first.is_some() {
            let n = self.normal.last;
            gl.normal3(n.x, n.y, n.z);
        }
        if self.color.first.is_some() {
            let c = self.color.last;
            gl.color4(c.x, c.y, c.z, c.w);
        }
        if self.tex.first.is_some() {
            gl.tex_coord(self.tex.last.to_array());
        }
        if self.ended {
            return gl.end();
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `glColor` (outside) then `glBegin; glVertex ×n; glEnd`.
    fn quad_after_color(f: &mut VertexFormat, n: usize) {
        f.attrib(COLOR, false);
        f.begin();
        for _ in 0..n {
            f.vertex();
        }
        f.end(n);
    }

    /// [`VertexFormat::run`] steps as the calls of its run do, from any format.
    #[test]
    fn a_run_steps_the_format_as_its_calls() {
        for (buffered, attribs, pos, pending) in [
            (0, 0, false, false),
            (9, COLOR, true, true),
            (3, SECONDARY, true, false),
        ] {
            for count in [0, 1, 4] {
                for color_at in [None, Some(0), Some(1), Some(count)] {
                    if color_at.is_some_and(|k| k > count) {
                        continue;
                    }
                    let start = VertexFormat {
                        attribs,
                        pos,
                        pending,
                        buffered,
                    };
                    let mut calls = start;
                    calls.begin();
                    for i in 0..=count {
                        if color_at == Some(i) {
                            calls.attrib(COLOR, true);
                        }
                        if i < count {
                            calls.vertex();
                        }
                    }
                    calls.end(count);
                    let mut run = start;
                    run.run(color_at, count);
                    assert_eq!(run, calls, "{start:?} {count} {color_at:?}");
                }
            }
        }
    }

    #[test]
    fn colour_before_begin_is_constant_inside_varies() {
        let mut f = VertexFormat::default();
        quad_after_color(&mut f, 4);
        assert!(!f.has(COLOR));
        // A second colour and quad with no state call between: Mesa's
        // format now holds the colour (it has a position), so it varies.
        quad_after_color(&mut f, 4);
        assert!(f.has(COLOR));
        // A state change between empties the format: constant again.
        f.flush();
        quad_after_color(&mut f, 4);
        assert!(!f.has(COLOR));
        // More than 8 buffered vertices: the new colour empties the format.
        f.flush();
        quad_after_color(&mut f, 9);
        quad_after_color(&mut f, 4);
        assert!(!f.has(COLOR));
        // Between begin and end it varies, even once.
        f.flush();
        f.begin();
        f.attrib(SECONDARY, true);
        f.vertex();
        f.end(1);
        assert!(f.has(SECONDARY) && !f.has(COLOR));
        // A flush with nothing pending keeps the format.
        let mut g = VertexFormat::default();
        g.attrib(COLOR, false);
        g.flush();
        assert!(g.has(COLOR));
    }
}
