//! State, matrices, clears and synchronisation.

use super::enums::{self, decode, Cap};
use super::{checked, gl, rec};
use crate::consts::*;
use crate::gl_state::{GlState, HINTS};
use crate::state::{with_current, with_gl};
use glam::{DMat4, Mat4};
use softgl::{ClearMask, Context, GlError, GlResult};

/// `glEnable`/`glDisable` of `cap`.
fn set_cap(gl: &mut softgl::Context, inert: &mut Vec<GLenum>, cap: GLenum, on: bool) -> GlResult {
    if gl.inside_begin() {
        return Err(GlError::InvalidOperation);
    }
    match enums::cap(cap)? {
        Cap::Core(c) if on => gl.enable(c),
        Cap::Core(c) => gl.disable(c),
        Cap::Inert(e) => {
            inert.retain(|&x| x != e);
            if on {
                inert.push(e);
            }
            Ok(())
        }
        // Disabling what is never on is correct; enabling it is not done yet.
        Cap::Missing if on => Err(GlError::InvalidOperation),
        Cap::Missing => Ok(()),
    }
}

/// `glEnable`/`glDisable`, which in a compatibility context also switch the
/// client arrays (`GL_VERTEX_ARRAY`, …) as Mesa does (`_mesa_set_enable`,
/// `src/mesa/main/enable.c`), where GL 1.5 asks for `glEnableClientState`.
fn set_cap_or_array(os: &mut GlState, gl: &mut Context, cap: GLenum, on: bool) -> GlResult {
    match os.array_mut(cap) {
        Some(array) => {
            super::outside(gl)?;
            array.enabled = on;
            Ok(())
        }
        None => set_cap(gl, &mut os.inert_caps, cap, on),
    }
}

/// Reads 16 values through `m` (column-major, as GL lays them out).
///
/// # Safety
/// `m` is null or points to 16 readable values.
unsafe fn matrix_from<T: Copy + Into<f64>>(m: *const T) -> GlResult<Mat4> {
    if m.is_null() {
        return Err(GlError::InvalidValue);
    }
    // SAFETY: 16 readable values, by the caller's contract.
    let s = unsafe { std::slice::from_raw_parts(m, 16) };
    let mut a = [0.0f64; 16];
    for (d, v) in a.iter_mut().zip(s) {
        *d = (*v).into();
    }
    Ok(DMat4::from_cols_array(&a).as_mat4())
}

exports! {
    [] fn glEnable(cap: GLenum) {
        rec(move |os, gl| set_cap_or_array(os, gl, cap, true))
    }
    [] fn glDisable(cap: GLenum) {
        rec(move |os, gl| set_cap_or_array(os, gl, cap, false))
    }
    [] fn glIsEnabled(cap: GLenum) -> u8 {
        with_gl(GL_FALSE, |os, gl| match super::get::is_enabled(os, gl, cap) {
            Ok(b) => u8::from(b),
            Err(e) => {
                gl.record_error(e);
                GL_FALSE
            }
        })
    }
    /// Between `glBegin` and `glEnd` it is itself `GL_INVALID_OPERATION` and
    /// returns `GL_NO_ERROR`, leaving the pending error for later, as in Mesa.
    [] fn glGetError() -> GLenum {
        with_gl(GL_NO_ERROR, |_, gl| {
            if gl.inside_begin() {
                gl.record_error(GlError::InvalidOperation);
                return GL_NO_ERROR;
            }
            gl.get_error().map_or(GL_NO_ERROR, GlError::code)
        })
    }
    /// The converted formats reach the caller's buffer, and the Z24S8 copy
    /// `OSMesaGetDepthBuffer` handed out is brought up to date.
    [] fn glFlush() {
        if super::refused_inside_begin() {
            return;
        }
        with_current((), |os| os.flush())
    }
    /// As `glFlush`: softgl draws at each call, so there is nothing to wait for.
    [] fn glFinish() {
        if super::refused_inside_begin() {
            return;
        }
        with_current((), |os| os.flush())
    }
    [] fn glHint(target: GLenum, mode: GLenum) {
        rec(move |os, gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            let i = HINTS.iter().position(|&t| t == target).ok_or(GlError::InvalidEnum)?;
            if !matches!(mode, GL_DONT_CARE | GL_FASTEST | GL_NICEST) {
                return Err(GlError::InvalidEnum);
            }
            os.hints[i] = mode;
            Ok(())
        })
    }
    /// `GL_FRONT` and its aliases: an OSMesa context is single-buffered;
    /// `GL_NONE` turns colour writes off; on a framebuffer object
    /// `GL_COLOR_ATTACHMENTi` or `GL_NONE` (`src/fbo.rs`).
    [] fn glDrawBuffer(mode: GLenum) {
        checked(move |gl| super::fbo::draw_buffer(gl, mode))
    }
    [] fn glReadBuffer(mode: GLenum) {
        checked(move |gl| super::fbo::read_buffer(gl, mode))
    }

    [] fn glClear(mask: u32) {
        checked(move |gl| {
            let known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
            if mask & !known != 0 {
                return Err(GlError::InvalidValue);
            }
            // Without an accumulation buffer, its bit has no effect, as for any absent buffer.
            gl.clear(ClearMask {
                accum: mask & GL_ACCUM_BUFFER_BIT != 0,
                color: mask & GL_COLOR_BUFFER_BIT != 0,
                depth: mask & GL_DEPTH_BUFFER_BIT != 0,
                stencil: mask & GL_STENCIL_BUFFER_BIT != 0,
            })
        })
    }
    [] fn glClearColor(r: f32, g: f32, b: f32, a: f32) {
        gl(move |gl| gl.clear_color(r, g, b, a))
    }
    [] fn glClearDepth(depth: f64) {
        gl(move |gl| gl.clear_depth(depth))
    }
    [] fn glClearStencil(s: i32) {
        gl(move |gl| gl.clear_stencil(s))
    }
    [] fn glViewport(x: i32, y: i32, width: i32, height: i32) {
        gl(move |gl| gl.viewport(x, y, width, height))
    }
    [] fn glDepthRange(near: f64, far: f64) {
        gl(move |gl| gl.depth_range(near, far))
    }
    /// ARB_clip_control (compiled into display lists, as Mesa's `save_ClipControl`).
    [] fn glClipControl(origin: GLenum, depth: GLenum) {
        gl(move |gl| gl.clip_control(origin, depth))
    }
    [] fn glScissor(x: i32, y: i32, width: i32, height: i32) {
        gl(move |gl| gl.scissor(x, y, width, height))
    }

    [] fn glMatrixMode(mode: GLenum) {
        checked(move |gl| gl.matrix_mode(decode(mode)?))
    }
    [] fn glPushMatrix() {
        gl(Context::push_matrix)
    }
    [] fn glPopMatrix() {
        gl(Context::pop_matrix)
    }
    [] fn glLoadIdentity() {
        gl(Context::load_identity)
    }
    /// # Safety
    /// `m` is null or points to 16 floats.
    [unsafe] fn glLoadMatrixf(m: *const f32) {
        // SAFETY: 16 floats by GL's contract; null is refused.
        let m = unsafe { matrix_from(m) };
        checked(move |gl| gl.load_matrix(&m?))
    }
    /// # Safety
    /// `m` is null or points to 16 doubles.
    [unsafe] fn glLoadMatrixd(m: *const f64) {
        // SAFETY: 16 doubles by GL's contract; null is refused.
        let m = unsafe { matrix_from(m) };
        checked(move |gl| gl.load_matrix(&m?))
    }
    /// # Safety
    /// `m` is null or points to 16 floats.
    [unsafe] fn glMultMatrixf(m: *const f32) {
        // SAFETY: 16 floats by GL's contract; null is refused.
        let m = unsafe { matrix_from(m) };
        checked(move |gl| gl.mult_matrix(&m?))
    }
    /// # Safety
    /// `m` is null or points to 16 doubles.
    [unsafe] fn glMultMatrixd(m: *const f64) {
        // SAFETY: 16 doubles by GL's contract; null is refused.
        let m = unsafe { matrix_from(m) };
        checked(move |gl| gl.mult_matrix(&m?))
    }
    [] fn glTranslatef(x: f32, y: f32, z: f32) {
        gl(move |gl| gl.translate(x, y, z))
    }
    [] fn glTranslated(x: f64, y: f64, z: f64) {
        gl(move |gl| gl.translate(x as f32, y as f32, z as f32))
    }
    [] fn glScalef(x: f32, y: f32, z: f32) {
        gl(move |gl| gl.scale(x, y, z))
    }
    [] fn glScaled(x: f64, y: f64, z: f64) {
        gl(move |gl| gl.scale(x as f32, y as f32, z as f32))
    }
    [] fn glRotatef(angle: f32, x: f32, y: f32, z: f32) {
        gl(move |gl| gl.rotate(angle, x, y, z))
    }
    [] fn glRotated(angle: f64, x: f64, y: f64, z: f64) {
        gl(move |gl| gl.rotate(angle as f32, x as f32, y as f32, z as f32))
    }
    [] fn glFrustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) {
        gl(move |gl| gl.frustum(l, r, b, t, n, f))
    }
    [] fn glOrtho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) {
        gl(move |gl| gl.ortho(l, r, b, t, n, f))
    }

    [] fn glShadeModel(mode: GLenum) {
        checked(move |gl| gl.shade_model(decode(mode)?))
    }
    [] fn glFrontFace(mode: GLenum) {
        checked(move |gl| gl.front_face(decode(mode)?))
    }
    [] fn glCullFace(mode: GLenum) {
        checked(move |gl| gl.cull_face(decode(mode)?))
    }
    [] fn glPolygonMode(face: GLenum, mode: GLenum) {
        checked(move |gl| gl.polygon_mode(decode(face)?, decode(mode)?))
    }
    [] fn glPolygonOffset(factor: f32, units: f32) {
        gl(move |gl| gl.polygon_offset(factor, units))
    }
    [] fn glPointSize(size: f32) {
        gl(move |gl| gl.point_size(size))
    }
    [] fn glLineWidth(width: f32) {
        gl(move |gl| gl.line_width(width))
    }
    /// GL 1.3 (and `glSampleCoverageARB`): compiled into display lists.
    [] fn glSampleCoverage(value: f32, invert: u8) {
        gl(move |gl| gl.sample_coverage(value, invert != 0))
    }
    [] fn glSampleCoverageARB(value: f32, invert: u8) {
        gl(move |gl| gl.sample_coverage(value, invert != 0))
    }

    [] fn glAlphaFunc(func: GLenum, reference: f32) {
        checked(move |gl| gl.alpha_func(decode(func)?, reference))
    }
    [] fn glStencilFunc(func: GLenum, reference: i32, mask: u32) {
        checked(move |gl| gl.stencil_func(decode(func)?, reference, mask))
    }
    [] fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) {
        checked(move |gl| gl.stencil_op(decode(fail)?, decode(zfail)?, decode(zpass)?))
    }
    [] fn glStencilMask(mask: u32) {
        gl(move |gl| gl.stencil_mask(mask))
    }
    [] fn glDepthFunc(func: GLenum) {
        checked(move |gl| gl.depth_func(decode(func)?))
    }
    [] fn glDepthMask(flag: u8) {
        gl(move |gl| gl.depth_mask(flag != 0))
    }
    [] fn glBlendFunc(src: GLenum, dst: GLenum) {
        checked(move |gl| gl.blend_func(decode(src)?, decode(dst)?))
    }
    [] fn glBlendFuncSeparate(src_rgb: GLenum, dst_rgb: GLenum, src_alpha: GLenum, dst_alpha: GLenum) {
        checked(move |gl| {
            gl.blend_func_separate(
                decode(src_rgb)?,
                decode(dst_rgb)?,
                decode(src_alpha)?,
                decode(dst_alpha)?,
            )
        })
    }
    [] fn glBlendFuncSeparateEXT(src_rgb: GLenum, dst_rgb: GLenum, src_alpha: GLenum, dst_alpha: GLenum) {
        glBlendFuncSeparate(src_rgb, dst_rgb, src_alpha, dst_alpha)
    }
    [] fn glBlendEquation(mode: GLenum) {
        checked(move |gl| gl.blend_equation(decode(mode)?))
    }
    [] fn glBlendEquationEXT(mode: GLenum) {
        glBlendEquation(mode)
    }
    [] fn glBlendEquationSeparate(rgb: GLenum, alpha: GLenum) {
        checked(move |gl| gl.blend_equation_separate(decode(rgb)?, decode(alpha)?))
    }
    [] fn glBlendColor(r: f32, g: f32, b: f32, a: f32) {
        gl(move |gl| gl.blend_color(r, g, b, a))
    }
    [] fn glBlendColorEXT(r: f32, g: f32, b: f32, a: f32) {
        glBlendColor(r, g, b, a)
    }
    [] fn glLogicOp(op: GLenum) {
        checked(move |gl| gl.logic_op(decode(op)?))
    }
    [] fn glColorMask(r: u8, g: u8, b: u8, a: u8) {
        gl(move |gl| gl.color_mask(r != 0, g != 0, b != 0, a != 0))
    }
}
