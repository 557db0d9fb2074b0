//! The attribute stacks: `glPushAttrib`/`glPopAttrib` and the client ones.
//! A push saves the whole state; a pop restores the groups its mask named,
//! through the context's own setters. Groups without state in softgl yet
//! (pixel maps, …) save nothing.

use super::texture::TARGETS;
use super::{now, rec};
use crate::consts::*;
use crate::gl_state::{ClientArrays, GlState, SavedAttrib, SavedClient, SavedTextures, MAX_UNITS};
use softgl::lighting::LightingState;
use softgl::texture::TexParamName;
use softgl::GlEnum;
use softgl::{Capability, Context, Face, GlError, GlResult};

/// `GL_MAX_ATTRIB_STACK_DEPTH` and `GL_MAX_CLIENT_ATTRIB_STACK_DEPTH` (Mesa's 16).
pub const MAX_DEPTH: usize = 16;

const CURRENT_BIT: u32 = 0x1;
const POINT_BIT: u32 = 0x2;
const LINE_BIT: u32 = 0x4;
const POLYGON_BIT: u32 = 0x8;
const PIXEL_MODE_BIT: u32 = 0x20;
const POLYGON_STIPPLE_BIT: u32 = 0x10;
const LIGHTING_BIT: u32 = 0x40;
const FOG_BIT: u32 = 0x80;
const DEPTH_BIT: u32 = 0x100;
const ACCUM_BUFFER_BIT: u32 = 0x200;
const STENCIL_BIT: u32 = 0x400;
const VIEWPORT_BIT: u32 = 0x800;
const TRANSFORM_BIT: u32 = 0x1000;
const ENABLE_BIT: u32 = 0x2000;
const COLOR_BIT: u32 = 0x4000;
const HINT_BIT: u32 = 0x8000;
const EVAL_BIT: u32 = 0x10000;
const TEXTURE_BIT: u32 = 0x40000;
const SCISSOR_BIT: u32 = 0x80000;
const MULTISAMPLE_BIT: u32 = 0x2000_0000;
const CLIENT_PIXEL_STORE_BIT: u32 = 0x1;
const CLIENT_VERTEX_ARRAY_BIT: u32 = 0x2;

fn set_cap(gl: &mut Context, cap: Capability, on: bool) -> GlResult {
    if on {
        gl.enable(cap)
    } else {
        gl.disable(cap)
    }
}

/// Restores the inert capabilities among `which` from `saved`.
fn restore_inert(os: &mut GlState, saved: &[GLenum], which: &[GLenum]) {
    os.inert_caps.retain(|c| !which.contains(c));
    os.inert_caps.extend(saved.iter().filter(|c| which.contains(c)));
}

/// Restores the lighting and clip plane state of the groups in `m`:
/// `GL_LIGHTING_BIT` (lights, model, materials, colour material),
/// `GL_TRANSFORM_BIT` (clip planes and their enables, normalize, rescale)
/// and `GL_ENABLE_BIT` (every enable among them).
fn restore_lighting(gl: &mut Context, m: u32, saved: &LightingState) -> GlResult {
    if m & (LIGHTING_BIT | TRANSFORM_BIT | ENABLE_BIT) == 0 {
        return Ok(());
    }
    let mut l = gl.state().lighting.clone();
    if m & LIGHTING_BIT != 0 {
        let clip = (l.clip_planes, l.clip_enabled, l.normalize, l.rescale_normal);
        l = saved.clone();
        (l.clip_planes, l.clip_enabled, l.normalize, l.rescale_normal) = clip;
    }
    if m & TRANSFORM_BIT != 0 {
        (l.clip_planes, l.clip_enabled) = (saved.clip_planes, saved.clip_enabled);
        (l.normalize, l.rescale_normal) = (saved.normalize, saved.rescale_normal);
    }
    if m & ENABLE_BIT != 0 {
        l.enabled = saved.enabled;
        for (light, was) in l.lights.iter_mut().zip(&saved.lights) {
            light.enabled = was.enabled;
        }
        (l.color_material, l.normalize, l.rescale_normal) =
            (saved.color_material, saved.normalize, saved.rescale_normal);
        l.clip_enabled = saved.clip_enabled;
    }
    gl.restore_lighting(l)
}

/// Saves the texture state of `GL_TEXTURE_BIT` (with the bound objects'
/// parameters) or `GL_ENABLE_BIT` (the units alone).
fn save_textures(gl: &mut Context, mask: u32) -> GlResult<SavedTextures> {
    let active = gl.active_texture_unit();
    let bindings: [[u32; TARGETS.len()]; MAX_UNITS] =
        std::array::from_fn(|u| TARGETS.map(|t| gl.texture_binding(u, t.0)));
    let mut objects: Vec<(softgl::TextureTarget, u32, Vec<softgl::TexParam>)> = Vec::new();
    if mask & TEXTURE_BIT != 0 {
        for (u, names) in bindings.iter().enumerate() {
            gl.active_texture(u as u32)?;
            for (&(target, ..), &name) in TARGETS.iter().zip(names) {
                if objects.iter().any(|o| o.0 == target && o.1 == name) {
                    continue;
                }
                let params = TexParamName::TABLE
                    .iter()
                    .filter(|p| p.0 != TexParamName::Resident)
                    .map(|p| gl.get_tex_parameter(target, p.0))
                    .collect::<GlResult<Vec<_>>>()?;
                objects.push((target, name, params));
            }
        }
        gl.active_texture(active as u32)?;
    }
    Ok(SavedTextures {
        active,
        units: gl.tex_units().units,
        bindings,
        objects,
    })
}

/// Restores `GL_TEXTURE_BIT` (everything saved: objects' parameters,
/// bindings, units, the active unit) or, with `GL_ENABLE_BIT` alone, the
/// units' target and coordinate generation enables.
fn restore_textures(gl: &mut Context, m: u32, s: &SavedTextures) -> GlResult {
    if m & TEXTURE_BIT != 0 {
        // Each object's parameters, bound on unit 0 for the time it takes.
        gl.active_texture(0)?;
        for (target, name, params) in &s.objects {
            gl.bind_texture(*target, *name)?;
            for &p in params {
                gl.restore_tex_parameter(*target, p)?;
            }
        }
        for (u, names) in s.bindings.iter().enumerate() {
            gl.active_texture(u as u32)?;
            for (&(target, ..), &name) in TARGETS.iter().zip(names) {
                gl.bind_texture(target, name)?;
            }
            gl.restore_tex_unit(u, s.units[u])?;
        }
        return gl.active_texture(s.active as u32);
    }
    if m & ENABLE_BIT != 0 {
        for (u, saved) in s.units.iter().enumerate() {
            let mut unit = gl.tex_units().units[u];
            unit.enabled = saved.enabled;
            for (g, was) in unit.gen.iter_mut().zip(&saved.gen) {
                g.enabled = was.enabled;
            }
            gl.restore_tex_unit(u, unit)?;
        }
    }
    Ok(())
}

/// Restores the groups of `s.mask`.
fn restore(os: &mut GlState, gl: &mut Context, s: &SavedAttrib) -> GlResult {
    let (m, st) = (s.mask, &s.state);
    if m & CURRENT_BIT != 0 {
        let c = s.current;
        gl.color4(c.color.x, c.color.y, c.color.z, c.color.w);
        gl.normal3(c.normal.x, c.normal.y, c.normal.z);
        for (unit, t) in c.tex_coords.iter().enumerate() {
            gl.multi_tex_coord(unit as u32, t.to_array())?;
        }
        gl.index(c.index);
        gl.edge_flag(c.edge_flag);
        gl.secondary_color3(c.secondary.x, c.secondary.y, c.secondary.z);
        gl.fog_coord(c.fog_coord);
        gl.set_raster_position(s.raster)?;
    }
    if let Some(p) = &s.pixel {
        gl.set_pixel_state(p.clone())?;
    }
    if m & POINT_BIT != 0 {
        gl.point_size(st.point_size)?;
        gl.point_parameters(st.point_params)?;
    }
    if m & LINE_BIT != 0 {
        gl.line_width(st.line_width)?;
        gl.line_stipple(st.line_stipple_factor, st.line_stipple_pattern)?;
    }
    if m & (LINE_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::LineStipple, st.line_stipple)?;
    }
    if m & POLYGON_STIPPLE_BIT != 0 {
        gl.polygon_stipple(st.polygon_stipple_pattern)?;
    }
    if m & (POLYGON_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::PolygonStipple, st.polygon_stipple)?;
        set_cap(gl, Capability::CullFace, st.cull)?;
        set_cap(gl, Capability::PolygonOffsetFill, st.offset_fill)?;
        set_cap(gl, Capability::PolygonOffsetLine, st.offset_line)?;
        set_cap(gl, Capability::PolygonOffsetPoint, st.offset_point)?;
    }
    if m & POLYGON_BIT != 0 {
        gl.cull_face(st.cull_face)?;
        gl.front_face(st.front_face)?;
        gl.polygon_mode(Face::Front, st.polygon_mode_front)?;
        gl.polygon_mode(Face::Back, st.polygon_mode_back)?;
        gl.polygon_offset(st.offset_factor, st.offset_units)?;
    }
    if m & LIGHTING_BIT != 0 {
        gl.shade_model(st.shade_model)?;
    }
    restore_lighting(gl, m, &st.lighting)?;
    if m & (FOG_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::Fog, st.fog.enabled)?;
        set_cap(gl, Capability::ColorSum, st.color_sum)?;
    }
    if m & FOG_BIT != 0 {
        super::fog::restore(gl, &st.fog)?;
    }
    if m & (DEPTH_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::DepthTest, st.depth_test)?;
    }
    if m & DEPTH_BIT != 0 {
        gl.depth_func(st.depth_func)?;
        gl.depth_mask(st.depth_write)?;
        gl.clear_depth(st.clear_depth)?;
    }
    if m & ACCUM_BUFFER_BIT != 0 {
        let [r, g, b, a] = st.clear_accum;
        gl.clear_accum(r, g, b, a)?;
    }
    if m & (STENCIL_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::StencilTest, st.stencil_test)?;
    }
    if m & STENCIL_BIT != 0 {
        gl.stencil_func(st.stencil_func, st.stencil_ref, st.stencil_value_mask)?;
        gl.stencil_op(st.stencil_fail, st.stencil_zfail, st.stencil_zpass)?;
        gl.stencil_mask(st.stencil_write_mask)?;
        gl.clear_stencil(st.clear_stencil)?;
    }
    if m & VIEWPORT_BIT != 0 {
        let v = st.viewport;
        gl.viewport(v.x, v.y, v.width, v.height)?;
        gl.depth_range(st.depth_range.0, st.depth_range.1)?;
    }
    if m & TRANSFORM_BIT != 0 {
        gl.matrix_mode(s.matrix_mode)?;
        // glClipControl's state is transform state (Mesa's `gl_transform_attrib`).
        gl.set_clip_control(st.clip_control)?;
    }
    if m & (COLOR_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::AlphaTest, st.alpha_test)?;
        set_cap(gl, Capability::Blend, st.blend)?;
        set_cap(gl, Capability::Dither, st.dither)?;
        set_cap(gl, Capability::ColorLogicOp, st.color_logic_op)?;
    }
    if m & COLOR_BIT != 0 {
        (os.clear_index, os.index_mask) = s.index;
        gl.alpha_func(st.alpha_func, st.alpha_ref)?;
        let b = st.blend_func;
        gl.blend_func_separate(b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha)?;
        gl.blend_equation_separate(b.eq_rgb, b.eq_alpha)?;
        let [r, g, bl, a] = st.blend_color;
        gl.blend_color(r, g, bl, a)?;
        gl.logic_op(st.logic_op)?;
        let cm = st.color_mask;
        gl.color_mask(cm.r, cm.g, cm.b, cm.a)?;
        let [r, g, bl, a] = st.clear_color;
        gl.clear_color(r, g, bl, a)?;
    }
    // The bound objects' buffers, as Mesa's pop calls glDrawBuffer/glReadBuffer.
    let now = super::fbo::buffers(gl);
    if m & COLOR_BIT != 0 && now.0 != s.buffers.0 {
        super::fbo::draw_buffer(gl, s.buffers.0)?;
    }
    if m & PIXEL_MODE_BIT != 0 && now.1 != s.buffers.1 {
        super::fbo::read_buffer(gl, s.buffers.1)?;
    }
    if m & (SCISSOR_BIT | ENABLE_BIT) != 0 {
        set_cap(gl, Capability::ScissorTest, st.scissor_test)?;
    }
    if m & (MULTISAMPLE_BIT | ENABLE_BIT) != 0 {
        let ms = st.multisample;
        set_cap(gl, Capability::Multisample, ms.enabled)?;
        set_cap(gl, Capability::SampleCoverage, ms.coverage)?;
        set_cap(gl, Capability::SampleAlphaToCoverage, ms.alpha_to_coverage)?;
        set_cap(gl, Capability::SampleAlphaToOne, ms.alpha_to_one)?;
    }
    if m & MULTISAMPLE_BIT != 0 {
        gl.sample_coverage(st.multisample.coverage_value, st.multisample.coverage_invert)?;
    }
    if m & SCISSOR_BIT != 0 {
        let b = st.scissor;
        gl.scissor(b.x, b.y, b.width, b.height)?;
    }
    if m & (ENABLE_BIT | EVAL_BIT) != 0 {
        // The maps' enables and `GL_AUTO_NORMAL` are in both groups.
        let caps: Vec<GLenum> = super::eval::eval_caps().collect();
        restore_inert(os, &s.inert_caps, &caps);
    }
    if m & EVAL_BIT != 0 {
        os.eval.grid = s.eval_grid;
    }
    if m & HINT_BIT != 0 {
        os.hints = s.hints;
    }
    if let Some(t) = &s.textures {
        restore_textures(gl, m, t)?;
    }
    Ok(())
}

exports! {
    [] fn glPushAttrib(mask: u32) {
        rec(move |os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            if os.attrib_stack.len() >= MAX_DEPTH {
                return Err(GlError::StackOverflow);
            }
            let textures = match mask & (TEXTURE_BIT | ENABLE_BIT) {
                0 => None,
                _ => Some(save_textures(gl, mask)?),
            };
            let saved = SavedAttrib {
                mask,
                textures,
                state: gl.state().clone(),
                current: *gl.current(),
                raster: *gl.raster_position(),
                pixel: (mask & PIXEL_MODE_BIT != 0).then(|| gl.pixel_state().clone()),
                matrix_mode: gl.current_matrix_mode(),
                hints: os.hints,
                inert_caps: os.inert_caps.clone(),
                index: (os.clear_index, os.index_mask),
                buffers: super::fbo::buffers(gl),
                eval_grid: os.eval.grid,
            };
            os.attrib_stack.push(saved);
            Ok(())
        })
    }
    [] fn glPopAttrib() {
        rec(move |os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            let saved = os.attrib_stack.pop().ok_or(GlError::StackUnderflow)?;
            restore(os, gl, &saved)
        })
    }
    [] fn glPushClientAttrib(mask: u32) {
        now(|os, gl| {
            super::outside(gl)?;
            if os.client_attrib_stack.len() >= MAX_DEPTH {
                return Err(GlError::StackOverflow);
            }
            let saved = SavedClient {
                mask,
                pack: os.pack,
                unpack: os.unpack,
                arrays: ClientArrays {
                    buffers: super::buffers::bindings(gl),
                    ..os.arrays()
                },
            };
            os.client_attrib_stack.push(saved);
            Ok(())
        })
    }
    [] fn glPopClientAttrib() {
        now(|os, gl| {
            super::outside(gl)?;
            let s = os.client_attrib_stack.pop().ok_or(GlError::StackUnderflow)?;
            if s.mask & CLIENT_PIXEL_STORE_BIT != 0 {
                (os.pack, os.unpack) = (s.pack, s.unpack);
            }
            if s.mask & CLIENT_VERTEX_ARRAY_BIT != 0 {
                os.set_arrays(s.arrays);
                super::buffers::restore_bindings(os, gl, s.arrays.buffers);
            }
            Ok(())
        })
    }
}

/// `GL_ATTRIB_STACK_DEPTH` and `GL_CLIENT_ATTRIB_STACK_DEPTH`.
pub fn depths(os: &GlState) -> (usize, usize) {
    (os.attrib_stack.len(), os.client_attrib_stack.len())
}
