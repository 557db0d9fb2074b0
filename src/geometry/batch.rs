//! Vertex batches: vertices are fetched and transformed to clip space 256 at a
//! time, as primitive assembly reaches them, so a draw of any size needs one
//! batch of memory and the transform runs as a tight loop.

use super::clip::ClipVertex;
use super::InVertex;
use glam::{Mat4, Vec4};

/// Vertices transformed at once.
pub const BATCH: usize = 256;

/// A sliding window of transformed vertices, plus vertex 0, which fans,
/// polygons and line loops refer back to.
pub struct VertexBatch<'a> {
    mvp: Mat4,
    fetch: &'a dyn Fn(usize) -> InVertex,
    count: usize,
    base: usize,
    clip: Vec<ClipVertex>,
    first: Option<ClipVertex>,
}

impl<'a> VertexBatch<'a> {
    /// A batch over `count` vertices, `fetch(i)` giving vertex `i`.
    pub fn new(mvp: Mat4, count: usize, fetch: &'a dyn Fn(usize) -> InVertex) -> VertexBatch<'a> {
        VertexBatch {
            mvp,
            fetch,
            count,
            base: 0,
            clip: Vec::with_capacity(BATCH),
            first: None,
        }
    }

    fn transform(&self, v: InVertex) -> ClipVertex {
        // GL clamps vertex colors to [0, 1]; NaN reads as 0 on every target.
        let color = Vec4::from_array(
            v.color
                .to_array()
                .map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) }),
        );
        ClipVertex {
            pos: (self.mvp * v.pos).as_dvec4(),
            color,
        }
    }

    /// Vertex `i` in clip space. Assembly asks for indices that never fall more
    /// than three behind the newest one (or for vertex 0), so refilling the
    /// window from `i - 3` keeps every vertex of the current primitive.
    pub fn get(&mut self, i: usize) -> ClipVertex {
        if i == 0 {
            if let Some(v) = self.first {
                return v;
            }
            let v = self.transform((self.fetch)(0));
            self.first = Some(v);
            return v;
        }
        if i < self.base || i >= self.base + self.clip.len() {
            self.base = i.saturating_sub(3);
            let end = (self.base + BATCH).min(self.count);
            self.clip.clear();
            for k in self.base..end {
                let v = self.transform((self.fetch)(k));
                self.clip.push(v);
            }
        }
        self.clip[i - self.base]
    }
}
