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

    /// Whether the colour `bit` is in the format (varies per vertex).
    pub(crate) fn has(&self, bit: u8) -> bool {
        self.attribs & bit != 0
    }

    /// `vbo_reset_all_attr`.
    fn reset(&mut self) {
        *self = VertexFormat::default();
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
