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
    /// The object-space boxes of its chunks of [`CULL_CHUNK`] vertices, made
    /// at `glEnd` for a long run of independent triangles or quads
    /// ([`ImmediateRun::visible_chunks`]); empty for the others.
    boxes: Vec<ChunkBox>,
}

/// Vertices of a run a [`ChunkBox`] bounds: whole triangles and quads (a
/// multiple of 12). MuJoCo's infinite plane (200×200 quads, a column of 200
/// quads after the other) is 1,667 chunks of 24 quads.
pub(crate) const CULL_CHUNK: usize = 96;

/// Runs shorter than this are drawn whole (their chunks not tested).
const CULL_MIN: usize = 1024;

/// The box of a chunk of a run's vertices (`lo`, `hi`: x, y, z), when each
/// is finite with w = 1 (`usable`); else the chunk is always drawn.
#[derive(Clone, Copy, Debug)]
struct ChunkBox {
    lo: [f32; 3],
    hi: [f32; 3],
    usable: bool,
}

impl ChunkBox {
    fn of(pos: &[Vec4]) -> ChunkBox {
        let mut b = ChunkBox {
            lo: [f32::INFINITY; 3],
            hi: [f32::NEG_INFINITY; 3],
            usable: true,
        };
        for p in pos {
            b.usable &= p.w == 1.0 && p.truncate().is_finite();
            for (k, c) in p.truncate().to_array().into_iter().enumerate() {
                b.lo[k] = b.lo[k].min(c);
                b.hi[k] = b.hi[k].max(c);
            }
        }
        b
    }

    /// Whether every point of the box is outside one plane of the view
    /// volume (`-w <= x, y, z <= w`) in clip coordinates `m · p` (rows `m`,
    /// f64), by more than the error of the geometry stage's f32 transform
    /// of a vertex inside it: each clip coordinate of such a vertex is a
    /// convex combination of the corners' (exactly), and its f32 value is
    /// within a few ulps of the sum of the products' magnitudes (`bound`),
    /// so every vertex of the chunk gets the same outcode bit and each of
    /// its primitives is rejected by the clipper. Margins: 1e-5 of those
    /// magnitudes, about 100 ulps; none when a bound reaches 1e30 (an f32
    /// overflow there would make the codes NaN).
    fn outside(&self, m: &[[f64; 4]; 4]) -> bool {
        if !self.usable {
            return false;
        }
        let far = |k: usize| f64::from(self.lo[k].abs().max(self.hi[k].abs()));
        let bound = m.map(|r| r[0].abs() * far(0) + r[1].abs() * far(1) + r[2].abs() * far(2) + r[3].abs());
        if bound.iter().any(|b| b.is_nan() || *b >= 1e30) {
            return false;
        }
        // Per plane (x, y, z against w, each side): the largest value over
        // the corners of `w ± c`, which must stay below minus the margin.
        let mut most = [f64::NEG_INFINITY; 6];
        for corner in 0..8 {
            let p = [0, 1, 2].map(|k| f64::from(if corner >> k & 1 == 0 { self.lo[k] } else { self.hi[k] }));
            let c = m.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3]);
            for k in 0..3 {
                most[2 * k] = most[2 * k].max(c[3] + c[k]);
                most[2 * k + 1] = most[2 * k + 1].max(c[3] - c[k]);
            }
        }
        (0..6).any(|i| most[i] < -1e-5 * (bound[i / 2] + bound[3]))
    }
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
            boxes: Vec::new(),
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
        if matches!(self.mode, PrimitiveMode::Triangles | PrimitiveMode::Quads) && self.pos.len() >= CULL_MIN {
            self.boxes = self.pos.chunks(CULL_CHUNK).map(ChunkBox::of).collect();
        }
    }

    /// The chunks of [`CULL_CHUNK`] vertices of a run of independent
    /// triangles or quads that may show through `mvp` (the draw's
    /// projection times modelview) into `kept` (emptied first); `false`
    /// (and `kept` empty) when every chunk may, or the run has no boxes. A
    /// chunk left out is wholly outside one plane of the view volume
    /// ([`ChunkBox::outside`]): its primitives would be transformed and
    /// rejected one by one, making no fragment. MuJoCo's 40,000-quad plane
    /// is mostly outside the view: a noshadow frame's geometry stage spent
    /// ~290 instructions a vertex on 160,000 vertices a pass (callgrind).
    pub(crate) fn visible_chunks(&self, mvp: &glam::Mat4, kept: &mut Vec<u32>) -> bool {
        kept.clear();
        if self.boxes.is_empty() {
            return false;
        }
        let m = [0, 1, 2, 3].map(|r| mvp.row(r).to_array().map(f64::from));
        let mut culled = false;
        for (k, b) in self.boxes.iter().enumerate() {
            if b.outside(&m) {
                culled = true;
            } else {
                kept.push(k as u32);
            }
        }
        if !culled {
            kept.clear();
        }
        culled
    }

    /// [`ImmediateRun::fill`] of the vertices of chunks `kept` only (in
    /// their order), as `fill` makes them.
    pub(crate) fn fill_chunks(&self, before: &CurrentAttribs, kept: &[u32], out: &mut Vec<InVertex>) {
        out.clear();
        let t = before.vertex(Vec4::ZERO, 0);
        for &k in kept {
            let first = k as usize * CULL_CHUNK;
            let end = (first + CULL_CHUNK).min(self.pos.len());
            for (i, &pos) in self.pos.iter().enumerate().take(end).skip(first) {
                out.push(InVertex {
                    pos,
                    normal: self.normal.at(i).unwrap_or(t.normal),
                    color: self.color.at(i).unwrap_or(t.color),
                    ..t
                });
            }
        }
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

    /// A long run of triangles, most of it outside the view: its draw
    /// leaves chunks out and makes the bytes its calls make one by one
    /// (unlit with per-vertex colours, and lit with normals and colour
    /// material).
    #[test]
    fn a_run_left_out_outside_the_view_draws_what_its_calls_draw() {
        use crate::{Capability, Context, FramebufferDesc, MatrixMode, ReadFormat};
        let mut run = ImmediateRun::new(PrimitiveMode::Triangles);
        let n = 60;
        let at = |i: usize| i as f32 - n as f32 / 2.0;
        for x in 0..n {
            for y in 0..n {
                if (x + y) % 7 == 3 {
                    run.normal3(0.3, 0.1, 0.95);
                }
                for (dx, dy) in [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)] {
                    if x > 2 {
                        let k = (x * 31 + y * 17 + dx * 5 + dy * 3) % 256;
                        run.color4(k as f32 / 255.0, 0.5, 1.0 - k as f32 / 255.0, 1.0);
                    }
                    run.vertex4(at(x + dx), at(y + dy), 0.0, 1.0);
                }
            }
        }
        run.end();
        for lit in [false, true] {
            let draw = |by_run: bool| {
                let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(64, 48)).unwrap();
                gl.matrix_mode(MatrixMode::Projection).unwrap();
                gl.frustum(-0.1, 0.1, -0.075, 0.075, 0.1, 12.0).unwrap();
                gl.matrix_mode(MatrixMode::Modelview).unwrap();
                gl.translate(0.5, 0.0, -3.0).unwrap();
                gl.rotate(-60.0, 1.0, 0.0, 0.0).unwrap();
                if lit {
                    gl.enable(Capability::Lighting).unwrap();
                    gl.enable(Capability::Light(0)).unwrap();
                    gl.enable(Capability::ColorMaterial).unwrap();
                }
                let mvp = gl.matrix(MatrixMode::Projection) * gl.matrix(MatrixMode::Modelview);
                if by_run {
                    gl.draw_run(&run).unwrap();
                } else {
                    run.replay(&mut gl).unwrap();
                }
                (gl.read_pixels(0, 0, 64, 48, ReadFormat::Rgba8).unwrap(), mvp)
            };
            let ((calls, mvp), (drawn, _)) = (draw(false), draw(true));
            let mut kept = Vec::new();
            assert!(run.visible_chunks(&mvp, &mut kept));
            assert!(
                kept.len() < run.boxes.len() / 2,
                "{} of {}",
                kept.len(),
                run.boxes.len()
            );
            assert!(calls.chunks(4).filter(|p| p[..3] != [0, 0, 0]).count() > 1000);
            assert!(calls == drawn, "lit {lit}");
        }
    }
}
