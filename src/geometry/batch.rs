//! Vertex batches: vertices are fetched and transformed to clip space 256 at a
//! time, as primitive assembly reaches them, so a draw of any size needs one
//! batch of memory and the transform runs as a tight loop.
//!
//! [`VertexBatch::transform`] is the one place a vertex's varyings are filled,
//! as the draw's [`VertexStage`] says: colours copied (and clamped) or lit
//! (front and back, primary and secondary, [`super::lighting`]), the fog
//! coordinate taken from the eye-space depth or from `glFogCoord`, the
//! texture coordinates generated and transformed ([`crate::texture::texgen`]).

use super::clip::ClipVertex;
use super::lighting::{LightInput, LightSetup};
use super::varying::{VaryingLayout, MAX_VARYINGS};
use super::InVertex;
use crate::texture::texgen::TexCoordStage;
use glam::{Mat4, Vec4};

/// Vertices transformed at once.
pub const BATCH: usize = 256;

/// Where the fog coordinate of a vertex comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FogSource {
    /// `GL_FRAGMENT_DEPTH`: `|z_eye|`, z_eye computed as Mesa's fixed-function
    /// vertex program does when it needs no other eye coordinate (a `DP4` of
    /// the position with the modelview's third row, `docs/llvmpipe-facts.md`).
    EyeDepth { row: Vec4 },
    /// `GL_FOG_COORD`: `|fog_coord|` of the vertex.
    FogCoord,
}

/// The per-draw constants of the vertex stage: what each vertex computes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexStage<'a> {
    /// Object to clip coordinates.
    pub mvp: Mat4,
    /// The varyings to fill.
    pub layout: VaryingLayout,
    /// The fog coordinate's source, when `layout.fog`.
    pub fog: FogSource,
    /// With `GL_LIGHTING`: the colours are lit, not copied. `None` when
    /// lighting is off (no normal is then transformed, nothing computed).
    pub lighting: Option<LightSetup>,
    /// Materials that vary per vertex (`glMaterial` between `glBegin` and
    /// `glEnd`, which Mesa keeps as vertex attributes): when not empty, a
    /// vertex is lit by `vertex_materials[v.material]` instead of `lighting`.
    pub vertex_materials: &'a [LightSetup],
    /// The texture coordinates of the units `layout` carries and where the
    /// vertices' come from (`None` when it carries none: no texture work at all).
    pub tex_coords: Option<(&'a TexCoordStage, TexFetch<'a>)>,
}

/// Texture coordinates `(s, t, r, q)` of vertex `i` for unit `u`, as
/// `fetch(i, u)`: apart from [`InVertex`] so that an untextured draw neither
/// fetches nor copies them.
#[derive(Clone, Copy)]
pub struct TexFetch<'a>(pub &'a dyn Fn(usize, usize) -> Vec4);

impl std::fmt::Debug for TexFetch<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("TexFetch")
    }
}

impl PartialEq for TexFetch<'_> {
    /// The same function.
    fn eq(&self, o: &Self) -> bool {
        std::ptr::addr_eq(self.0, o.0)
    }
}

impl VertexStage<'_> {
    /// A stage transforming by `mvp`, filling the colours `layout` carries.
    pub fn new(mvp: Mat4, layout: VaryingLayout) -> VertexStage<'static> {
        VertexStage {
            mvp,
            layout,
            fog: FogSource::FogCoord,
            lighting: None,
            vertex_materials: &[],
            tex_coords: None,
        }
    }

    /// Vertex `v` (index `i` of the draw) in clip space with its varyings.
    pub fn transform(&self, i: usize, v: &InVertex) -> ClipVertex {
        let mut out = ClipVertex {
            pos: (self.mvp * v.pos).as_dvec4(),
            v: [0.0; MAX_VARYINGS],
        };
        if let Some(light) = &self.lighting {
            let light = self.vertex_materials.get(usize::from(v.material)).unwrap_or(light);
            let lit = light.light_vertex(&LightInput {
                pos: v.pos,
                normal: v.normal,
                color: v.color,
            });
            let l = &self.layout;
            for (slot, c) in [
                (l.color(), lit.front),
                (l.back_color(), lit.back),
                (l.secondary(), lit.front_secondary),
                (l.back_secondary(), lit.back_secondary),
            ] {
                if let Some(o) = slot {
                    out.v[o..o + 4].copy_from_slice(&c);
                }
            }
        } else {
            if let Some(o) = self.layout.color() {
                out.v[o..o + 4].copy_from_slice(&clamp_color(v.color));
            }
            if let Some(o) = self.layout.secondary() {
                out.v[o..o + 4].copy_from_slice(&clamp_color(v.secondary));
            }
        }
        if let Some(o) = self.layout.fog() {
            out.v[o] = match self.fog {
                FogSource::EyeDepth { row } => match self.lighting.as_ref().and_then(|l| l.eye_position(v.pos)) {
                    Some(eye) => eye[2].abs(),
                    None => eye_dot(row, v.pos).abs(),
                },
                FogSource::FogCoord => v.fog_coord.abs(),
            };
        }
        if let Some((t, fetch)) = self.tex_coords {
            t.fill(v, |u| (fetch.0)(i, u), &mut out.v);
        }
        out
    }
}

/// GL clamps vertex colors to `[0, 1]`; NaN reads as 0 on every target.
fn clamp_color(c: Vec4) -> [f32; 4] {
    c.to_array().map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) })
}

/// `DP4` as llvmpipe's vertex shaders run it (`lower_fdot` with `ffma`
/// lowered, `nir_lower_alu_width.c`): products summed from the last
/// component, `((p.w·m.w + p.z·m.z) + p.y·m.y) + p.x·m.x`, each step rounded.
pub fn eye_dot(m: Vec4, p: Vec4) -> f32 {
    let mut s = p.w * m.w;
    s += p.z * m.z;
    s += p.y * m.y;
    s + p.x * m.x
}

/// A sliding window of transformed vertices, plus vertex 0, which fans,
/// polygons and line loops refer back to.
pub struct VertexBatch<'a> {
    stage: VertexStage<'a>,
    fetch: &'a dyn Fn(usize) -> InVertex,
    count: usize,
    base: usize,
    clip: Vec<ClipVertex>,
    first: Option<ClipVertex>,
}

impl<'a> VertexBatch<'a> {
    /// A batch over `count` vertices, `fetch(i)` giving vertex `i`.
    pub fn new(stage: VertexStage<'a>, count: usize, fetch: &'a dyn Fn(usize) -> InVertex) -> VertexBatch<'a> {
        VertexBatch {
            stage,
            fetch,
            count,
            base: 0,
            clip: Vec::with_capacity(BATCH),
            first: None,
        }
    }

    fn transform(&self, i: usize) -> ClipVertex {
        self.stage.transform(i, &(self.fetch)(i))
    }

    /// Vertex `i` in clip space. Assembly asks for indices that never fall more
    /// than three behind the newest one (or for vertex 0), so refilling the
    /// window from `i - 3` keeps every vertex of the current primitive.
    pub fn get(&mut self, i: usize) -> ClipVertex {
        if i == 0 {
            if let Some(v) = self.first {
                return v;
            }
            let v = self.transform(0);
            self.first = Some(v);
            return v;
        }
        if i < self.base || i >= self.base + self.clip.len() {
            self.base = i.saturating_sub(3);
            let end = (self.base + BATCH).min(self.count);
            self.clip.clear();
            for k in self.base..end {
                let v = self.transform(k);
                self.clip.push(v);
            }
        }
        self.clip[i - self.base]
    }
}
