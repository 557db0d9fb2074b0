//! The current raster position (GL 1.5 §2.13): `glRasterPos` transforms a
//! point as a vertex is transformed (modelview, projection, clipped against
//! the view volume and the enabled user planes, viewport), and latches the
//! colours and texture coordinates it would have — lit, generated and
//! transformed by the same vertex stage a draw runs (`VertexStage`), for one
//! vertex. `glWindowPos` (GL 1.4) sets it in window coordinates directly.
//! Bitmaps and pixel rectangles (`pixel_rect.rs`) are drawn there.
//!
//! Mesa's fixed-function path (`main/rastpos.c`, `_mesa_RasterPos`, which
//! llvmpipe's state tracker calls with no vertex program): the eye position
//! is `MV·p`, the clip position `P·eye` (two products, not one by `P·MV`);
//! the raster distance is `|eye|` (or the current fog coordinate with
//! `GL_FOG_COORD`); `glWindowPos` clamps z to `[0, 1]` and maps it into the
//! depth range, and takes the current colours clamped.

use crate::context::Context;
use crate::error::GlResult;
use crate::fog::FogCoordSrc;
use crate::geometry::batch::{FogSource, TexFetch, VertexStage};
use crate::geometry::lighting::LightSetup;
use crate::geometry::varying::VaryingLayout;
use crate::geometry::InVertex;
use crate::texture::texgen::TexCoordStage;
use glam::{Vec4, Vec4Swizzles};
use softgl_jit::texture::MAX_UNITS;

/// `GL_CURRENT_RASTER_*`: the raster position and what it latched.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterPos {
    /// `GL_CURRENT_RASTER_POSITION_VALID`.
    pub valid: bool,
    /// `GL_CURRENT_RASTER_POSITION`: window x, y, z (depth in `[0, 1]`) and
    /// the clip w.
    pub window: [f32; 4],
    /// `GL_CURRENT_RASTER_DISTANCE`: the eye distance fog reads.
    pub distance: f32,
    /// `GL_CURRENT_RASTER_COLOR`.
    pub color: Vec4,
    /// `GL_CURRENT_RASTER_SECONDARY_COLOR`.
    pub secondary: Vec4,
    /// `GL_CURRENT_RASTER_TEXTURE_COORDS` of each unit.
    pub tex_coords: [Vec4; MAX_UNITS],
    /// `GL_CURRENT_RASTER_INDEX`.
    pub index: f32,
}

impl Default for RasterPos {
    /// GL's initial raster position: valid, at the origin, white.
    fn default() -> RasterPos {
        RasterPos {
            valid: true,
            window: [0.0, 0.0, 0.0, 1.0],
            distance: 0.0,
            color: Vec4::ONE,
            secondary: Vec4::new(0.0, 0.0, 0.0, 1.0),
            tex_coords: [Vec4::W; MAX_UNITS],
            index: 1.0,
        }
    }
}

/// Whether clip position `c` is inside the view volume (`-w <= x, y, z <= w`),
/// Mesa's `viewclip_point_*` tests.
/// (Always against `z ≥ −w`, under `glClipControl(…, GL_ZERO_TO_ONE)` too: Mesa's
/// `viewclip_point_near_z`, `main/rastpos.c`; docs/llvmpipe-facts.md.)
fn inside_view_volume(c: Vec4) -> bool {
    let w = c.w;
    !(c.x > w || c.x < -w || c.y > w || c.y < -w || c.z < -w || c.z > w)
}

impl Context {
    /// The raster position and what it latched (`glGet` of `GL_CURRENT_RASTER_*`).
    pub fn raster_position(&self) -> &RasterPos {
        &self.raster
    }

    /// Puts back a raster position (`glPopAttrib(GL_CURRENT_BIT)`).
    pub fn set_raster_position(&mut self, r: RasterPos) -> GlResult {
        self.outside()?;
        self.raster = r;
        Ok(())
    }

    /// `glRasterPos4f`: transforms `(x, y, z, w)` as a vertex; outside the
    /// view volume or an enabled user plane the position becomes invalid
    /// (and nothing else changes).
    pub fn raster_pos(&mut self, x: f32, y: f32, z: f32, w: f32) -> GlResult {
        self.outside()?;
        let obj = Vec4::new(x, y, z, w);
        let mv = *self.modelview.top();
        let eye = mv * obj;
        let clip = *self.projection.top() * eye;
        let planes_ok = {
            let l = &self.state.lighting;
            let eye_planes = l.clip_planes.iter().zip(&l.clip_enabled);
            // User planes are kept in eye coordinates: `plane · eye >= 0` keeps it.
            eye_planes
                .filter(|(_, &on)| on)
                .all(|(p, _)| Vec4::from_array(p.map(|c| c as f32)).dot(eye) >= 0.0)
        };
        if !inside_view_volume(clip) || !planes_ok {
            self.raster.valid = false;
            return Ok(());
        }
        // The window position, as Mesa maps it (`_mesa_get_viewport_xform`).
        let s = &self.state;
        let vp = s.viewport;
        let (vw, vh) = (vp.width as f32, vp.height as f32);
        let (z_scale, z_translate) = s.clip_control.depth_xform(s.depth_range);
        let d = if clip.w == 0.0 { 1.0 } else { 1.0 / clip.w };
        let ndc = clip.xyz() * d;
        let window = [
            ndc.x * (vw / 2.0) + (vp.x as f32 + vw / 2.0),
            ndc.y * s.clip_control.y_scale(vh) + (vp.y as f32 + vh / 2.0),
            ndc.z * z_scale + z_translate,
            clip.w,
        ];
        let distance = match s.fog.coord_src {
            FogCoordSrc::FogCoord => self.current.fog_coord,
            FogCoordSrc::FragmentDepth => eye.xyz().length(),
        };
        // The colours and texture coordinates of one vertex at `obj`, from
        // the vertex stage a draw runs: lit, generated, transformed.
        let layout = VaryingLayout {
            color: true,
            secondary: true,
            tex: ((1u32 << MAX_UNITS) - 1) as u8,
            ..VaryingLayout::default()
        };
        let mut stage = VertexStage::new(glam::Mat4::IDENTITY, layout);
        stage.fog = FogSource::FogCoord;
        let lighting = &s.lighting;
        if lighting.enabled {
            stage.lighting = Some(LightSetup::with_eye_coords(lighting, &mv, false));
        }
        let tex_stage = TexCoordStage::new(&self.tex_units, &layout, &mv, lighting);
        let current = self.current.tex_coords;
        let fetch = |_: usize, u: usize| current[u];
        stage.tex_coords = tex_stage.as_ref().map(|t| (t, TexFetch(&fetch)));
        let c = self.current;
        let v = InVertex {
            pos: obj,
            color: c.color,
            secondary: c.secondary,
            fog_coord: c.fog_coord,
            normal: c.normal.into(),
            edge: c.edge_flag,
            material: 0,
        };
        let out = stage.transform(0, &v);
        let at = |o: Option<usize>| o.map_or(Vec4::ZERO, |o| Vec4::from_slice(&out.v[o..o + 4]));
        let mut secondary = at(layout.secondary());
        secondary.w = 1.0;
        let mut tex_coords = [Vec4::W; MAX_UNITS];
        for (u, o) in layout.tex_units() {
            tex_coords[u] = Vec4::from_slice(&out.v[o..o + 4]);
        }
        self.raster = RasterPos {
            valid: true,
            window,
            distance,
            color: at(layout.color()),
            secondary,
            tex_coords,
            index: c.index,
        };
        self.render_mode.raster_hit(window[2]);
        Ok(())
    }

    /// `glWindowPos3f` (GL 1.4): the raster position at window `(x, y)`,
    /// depth `z` clamped to `[0, 1]` and mapped into the depth range;
    /// always valid; the current colours (clamped) and texture coordinates.
    pub fn window_pos(&mut self, x: f32, y: f32, z: f32) -> GlResult {
        self.window_pos4(x, y, z, 1.0)
    }

    /// `glWindowPos4fMESA`: [`Self::window_pos`] with the raster w set to `w`.
    pub fn window_pos4(&mut self, x: f32, y: f32, z: f32, w: f32) -> GlResult {
        self.outside()?;
        let (n, f) = self.state.depth_range;
        let z = if z.is_nan() { 0.0 } else { z.clamp(0.0, 1.0) };
        let z2 = z * (f - n) as f32 + n as f32;
        let c = self.current;
        let clamp = |v: Vec4| Vec4::from_array(v.to_array().map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) }));
        self.raster = RasterPos {
            valid: true,
            window: [x, y, z2, w],
            distance: match self.state.fog.coord_src {
                FogCoordSrc::FogCoord => c.fog_coord,
                FogCoordSrc::FragmentDepth => 0.0,
            },
            color: clamp(c.color),
            secondary: clamp(c.secondary),
            tex_coords: c.tex_coords,
            index: c.index,
        };
        self.render_mode.raster_hit(z2);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::{Context, FramebufferDesc};
    use glam::Vec4;

    fn ctx() -> Context {
        Context::new(FramebufferDesc::rgba8_d24s8(100, 50)).expect("a context")
    }

    #[test]
    fn the_identity_maps_the_view_volume_onto_the_viewport() {
        let mut gl = ctx();
        gl.color4(0.25, 0.5, 0.75, 1.0);
        gl.tex_coord4(1.0, 2.0, 3.0, 4.0);
        gl.raster_pos(0.5, -0.5, 0.5, 1.0).unwrap();
        let r = *gl.raster_position();
        assert!(r.valid);
        assert_eq!(r.window, [75.0, 12.5, 0.75, 1.0]);
        assert_eq!(r.color, Vec4::new(0.25, 0.5, 0.75, 1.0));
        assert_eq!(r.tex_coords[0], Vec4::new(1.0, 2.0, 3.0, 4.0));
        // The distance from the eye (at the origin).
        assert_eq!(r.distance, (0.5f32 * 0.5 * 3.0).sqrt());
    }

    #[test]
    fn outside_the_view_volume_it_is_invalid_and_keeps_the_rest() {
        let mut gl = ctx();
        gl.raster_pos(0.0, 0.0, 0.0, 1.0).unwrap();
        gl.color3(1.0, 0.0, 0.0);
        gl.raster_pos(1.5, 0.0, 0.0, 1.0).unwrap();
        let r = *gl.raster_position();
        assert!(!r.valid);
        assert_eq!(r.window, [50.0, 25.0, 0.5, 1.0]);
        assert_eq!(r.color, Vec4::ONE);
        // On the boundary: valid.
        gl.raster_pos(1.0, -1.0, 1.0, 1.0).unwrap();
        assert!(gl.raster_position().valid);
        // A window position is always valid, its depth in the depth range.
        gl.depth_range(0.5, 1.0).unwrap();
        gl.window_pos(-20.0, 1e6, 2.0).unwrap();
        let r = *gl.raster_position();
        assert!(r.valid);
        assert_eq!(r.window, [-20.0, 1e6, 1.0, 1.0]);
        assert_eq!(r.color, Vec4::new(1.0, 0.0, 0.0, 1.0));
    }
}
