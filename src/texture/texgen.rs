//! Texture coordinates in the vertex stage: `glTexGen` then the texture
//! matrix, for each unit a draw samples, as llvmpipe runs Mesa's
//! fixed-function vertex program (`build_texture_transform`,
//! `main/ffvertex_prog.c`) in f32 without fused operations
//! (`docs/llvmpipe-facts.md` §19):
//! - `OBJECT_LINEAR`: `DP4(position, object plane)`; `EYE_LINEAR`:
//!   `DP4(eye position, eye plane)`, the eye position `MUL`/`MAD` by the
//!   modelview's columns; a `DP4` sums `((w·w' + z·z') + y·y') + x·x'`.
//! - `SPHERE_MAP`: `u` the normalized eye position, `n` the eye normal,
//!   `r = u − 2(n·u)n`, `m = 2·sqrt(r.x² + r.y² + (r.z + 1)²)`, `r/m + 1/2`
//!   (`m` as `0.5·rsq(…)`); `REFLECTION_MAP`: `r`; `NORMAL_MAP`: `n`.
//! - The texture matrix (when not the identity, Mesa's `_TexMatEnabled`):
//!   `MUL`/`MAD` by its columns.

use super::unit::{TexGenMode, TextureUnits};
use crate::geometry::batch::eye_dot;
use crate::geometry::lighting::{dp3, normalize_vp, rsq, NormalTransform, V3};
use crate::geometry::varying::{VaryingLayout, Varyings};
use crate::geometry::InVertex;
use crate::lighting::LightingState;
use glam::{Mat4, Vec4};
use softgl_jit::texture::MAX_UNITS;

/// What one sampling unit computes per vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
struct UnitCoords {
    unit: usize,
    /// Offset of its 4 slots in the varyings.
    offset: usize,
    /// Per coordinate, when generated: the mode and its plane (object or eye).
    gen: [Option<(TexGenMode, [f32; 4])>; 4],
    /// The texture matrix's columns, when not the identity.
    matrix: Option<[f32; 16]>,
}

/// The texture coordinate work of one draw, built once from the state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexCoordStage {
    units: [UnitCoords; MAX_UNITS],
    count: usize,
    /// The modelview's columns (for the eye position).
    modelview: [f32; 16],
    /// Eye normals (texture generation always wants them in eye space).
    normal: NormalTransform,
}

/// `MUL`/`MAD` by the columns `c`: `((x·c0 + y·c1) + z·c2) + w·c3`.
#[inline(always)]
fn transform(c: &[f32; 16], p: [f32; 4]) -> [f32; 4] {
    [0, 1, 2, 3].map(|r| ((p[0] * c[r] + p[1] * c[4 + r]) + p[2] * c[8 + r]) + p[3] * c[12 + r])
}

/// The program's reflection vector `(−2(n·u))·n + u`, `u` the unit eye vector.
#[inline(always)]
fn reflect(n: V3, u: V3) -> V3 {
    let d = dp3(n, u);
    let d2 = d + d;
    [0, 1, 2].map(|k| -d2 * n[k] + u[k])
}

impl TexCoordStage {
    /// The stage for the units `layout` carries under the modelview `mv`;
    /// `None` when it carries none.
    pub fn new(
        units: &TextureUnits,
        layout: &VaryingLayout,
        mv: &Mat4,
        lighting: &LightingState,
    ) -> Option<TexCoordStage> {
        if layout.tex == 0 {
            return None;
        }
        let empty = UnitCoords {
            unit: 0,
            offset: 0,
            gen: [None; 4],
            matrix: None,
        };
        let mut stage = TexCoordStage {
            units: [empty; MAX_UNITS],
            count: 0,
            modelview: mv.to_cols_array(),
            normal: NormalTransform::new(lighting, mv, true),
        };
        for (u, offset) in layout.tex_units() {
            let state = &units.units[u];
            let gen = state.gen.map(|g| {
                g.enabled.then_some(match g.mode {
                    TexGenMode::ObjectLinear => (g.mode, g.object_plane),
                    _ => (g.mode, g.eye_plane),
                })
            });
            let m = units.matrix(u);
            stage.units[stage.count] = UnitCoords {
                unit: u,
                offset,
                gen,
                matrix: (*m != Mat4::IDENTITY).then(|| m.to_cols_array()),
            };
            stage.count += 1;
        }
        Some(stage)
    }

    /// Writes the texture coordinates of `v` into `out`, `tex(u)` giving the
    /// vertex's own coordinates for unit `u`.
    pub fn fill(&self, v: &InVertex, tex: impl Fn(usize) -> Vec4, out: &mut Varyings) {
        let mut shared = Shared::default();
        for u in &self.units[..self.count] {
            let mut c = tex(u.unit).to_array();
            if u.gen.iter().any(Option::is_some) {
                let sphere = u.gen.iter().flatten().any(|g| g.0 == TexGenMode::SphereMap).then(|| {
                    let r = shared.reflected(self, v);
                    let t = [r[0], r[1], r[2] + 1.0];
                    let inv_m = rsq(dp3(t, t)) * 0.5;
                    [r[0] * inv_m + 0.5, r[1] * inv_m + 0.5]
                });
                for (j, g) in u.gen.iter().enumerate() {
                    let Some((mode, plane)) = *g else { continue };
                    let plane = Vec4::from_array(plane);
                    c[j] = match mode {
                        TexGenMode::ObjectLinear => eye_dot(plane, v.pos),
                        TexGenMode::EyeLinear => eye_dot(plane, Vec4::from_array(shared.eye(self, v))),
                        TexGenMode::SphereMap => sphere.map_or(0.0, |s| s[j.min(1)]),
                        TexGenMode::ReflectionMap => shared.reflected(self, v)[j.min(2)],
                        TexGenMode::NormalMap => shared.normal(self, v)[j.min(2)],
                    };
                }
            }
            if let Some(m) = &u.matrix {
                c = transform(m, c);
            }
            out[u.offset..u.offset + 4].copy_from_slice(&c);
        }
    }
}

/// What the program computes at most once per vertex, when a unit needs it.
#[derive(Default)]
struct Shared {
    eye: Option<[f32; 4]>,
    normal: Option<V3>,
    reflected: Option<V3>,
}

impl Shared {
    fn eye(&mut self, stage: &TexCoordStage, v: &InVertex) -> [f32; 4] {
        *self
            .eye
            .get_or_insert_with(|| transform(&stage.modelview, v.pos.to_array()))
    }

    fn normal(&mut self, stage: &TexCoordStage, v: &InVertex) -> V3 {
        *self.normal.get_or_insert_with(|| stage.normal.apply(v.normal))
    }

    fn reflected(&mut self, stage: &TexCoordStage, v: &InVertex) -> V3 {
        if let Some(r) = self.reflected {
            return r;
        }
        let e = self.eye(stage, v);
        let hat = normalize_vp([e[0], e[1], e[2]]);
        let r = reflect(self.normal(stage, v), hat);
        self.reflected = Some(r);
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::unit::TexGen;

    #[test]
    fn transform_sums_columns_in_the_programs_order() {
        let m = Mat4::from_translation(glam::Vec3::new(1.0, 2.0, 3.0)).to_cols_array();
        assert_eq!(transform(&m, [0.5, 0.25, 0.0, 1.0]), [1.5, 2.25, 3.0, 1.0]);
    }

    /// The coordinates of unit `u` that `units` give a vertex at `pos` with normal `n`.
    fn coords(units: &TextureUnits, u: usize, mv: &Mat4, pos: [f32; 4], n: [f32; 3]) -> [f32; 4] {
        let layout = VaryingLayout {
            color: true,
            tex: 1 << u,
            ..VaryingLayout::default()
        };
        let stage = TexCoordStage::new(units, &layout, mv, &LightingState::default()).unwrap();
        let mut v = InVertex::new(Vec4::from_array(pos), Vec4::ONE);
        v.normal = glam::Vec3::from_array(n);
        let mut out = [0.0; crate::geometry::varying::MAX_VARYINGS];
        stage.fill(&v, |_| Vec4::new(0.25, 0.5, 0.75, 1.0), &mut out);
        [out[4], out[5], out[6], out[7]]
    }

    #[test]
    fn without_texgen_or_matrix_the_vertex_coordinates_pass() {
        let units = TextureUnits::default();
        let got = coords(&units, 3, &Mat4::IDENTITY, [1.0, 2.0, 3.0, 1.0], [0.0, 0.0, 1.0]);
        assert_eq!(got, [0.25, 0.5, 0.75, 1.0]);
        let layout = VaryingLayout::default();
        assert!(TexCoordStage::new(&units, &layout, &Mat4::IDENTITY, &LightingState::default()).is_none());
    }

    #[test]
    fn object_and_eye_linear_are_plane_dot_products() {
        let mut units = TextureUnits::default();
        let g = &mut units.units[0].gen;
        g[0] = TexGen {
            enabled: true,
            mode: TexGenMode::ObjectLinear,
            object_plane: [0.5, 0.0, 0.0, 0.5],
            eye_plane: [0.0; 4],
        };
        g[1] = TexGen {
            enabled: true,
            mode: TexGenMode::EyeLinear,
            object_plane: [0.0; 4],
            eye_plane: [0.0, 0.0, -1.0, 0.0],
        };
        // Eye position of (0.5, 0, 0, 1) under a translation by (0, 0, -4) is z = -4.
        let mv = Mat4::from_translation(glam::Vec3::new(0.0, 0.0, -4.0));
        let got = coords(&units, 0, &mv, [0.5, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0]);
        // s = 0.5·0.5 + 0.5 (object space), t = -z_eye = 4; r and q are the vertex's.
        assert_eq!(got, [0.75, 4.0, 0.75, 1.0]);
    }

    #[test]
    fn sphere_reflection_and_normal_maps() {
        let mut units = TextureUnits::default();
        for (k, mode) in [TexGenMode::SphereMap, TexGenMode::SphereMap, TexGenMode::NormalMap]
            .into_iter()
            .enumerate()
        {
            units.units[1].gen[k].enabled = true;
            units.units[1].gen[k].mode = mode;
        }
        // A vertex straight ahead (eye vector (0, 0, -1)) facing the eye: r = (0, 0, 1),
        // m = 2·sqrt(0 + 0 + 4) = 4, s = t = 0/4 + 1/2; the normal's z is 1.
        let got = coords(&units, 1, &Mat4::IDENTITY, [0.0, 0.0, -2.0, 1.0], [0.0, 0.0, 1.0]);
        assert_eq!(got, [0.5, 0.5, 1.0, 1.0]);
        // Eye vector (0.6, 0, -0.8) on normal (0, 0, 1): r = (0.6, 0, 0.8),
        // m = 2·sqrt(0.36 + 3.24) = 3.7947…, s = 0.6/m + 0.5 = 0.658114.
        units.units[1].gen[2].mode = TexGenMode::ReflectionMap;
        let got = coords(&units, 1, &Mat4::IDENTITY, [3.0, 0.0, -4.0, 1.0], [0.0, 0.0, 1.0]);
        assert!((got[0] - 0.658_114).abs() < 1e-6, "{got:?}");
        assert_eq!(got[1], 0.5);
        assert!((got[2] - 0.8).abs() < 1e-6, "{got:?}");
    }

    #[test]
    fn the_texture_matrix_follows_texgen() {
        let mut units = TextureUnits::default();
        *units.matrix_stack_mut(2).top_mut() = Mat4::from_scale(glam::Vec3::new(2.0, 4.0, 1.0));
        units.units[2].gen[0].enabled = true;
        units.units[2].gen[0].mode = TexGenMode::ObjectLinear;
        // s = x = 0.125 generated, then doubled; t = 0.5 given, times 4.
        let got = coords(&units, 2, &Mat4::IDENTITY, [0.125, 7.0, 0.0, 1.0], [0.0, 0.0, 1.0]);
        assert_eq!(got, [0.25, 2.0, 0.75, 1.0]);
    }

    #[test]
    fn reflect_mirrors_about_the_normal() {
        // Looking straight down -z at a face whose normal is +z: r = (0, 0, 1).
        assert_eq!(reflect([0.0, 0.0, 1.0], [0.0, 0.0, -1.0]), [0.0, 0.0, 1.0]);
        assert_eq!(reflect([0.0, 1.0, 0.0], [0.6, -0.8, 0.0]), [0.6, 0.8, 0.0]);
    }
}
