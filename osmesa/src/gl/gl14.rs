//! Small GL 1.3 and 1.4 entry points: the transposed matrices
//! (`glLoadTransposeMatrix`, `glMultTransposeMatrix`, GL 1.3 and
//! `ARB_transpose_matrix`) and the point parameters (`glPointParameter`, GL
//! 1.4, `ARB_point_parameters`, `EXT_point_parameters`). Each is compiled
//! into display lists as GL says.

use super::get::Val;
use super::{checked, rec};
use crate::consts::*;
use glam::Mat4;
use softgl::state::PointParams;
use softgl::{Context, GlError, GlResult, MatrixMode};

const GL_POINT_SIZE_MIN: GLenum = 0x8126;
const GL_POINT_SIZE_MAX: GLenum = 0x8127;
const GL_POINT_FADE_THRESHOLD_SIZE: GLenum = 0x8128;
const GL_POINT_DISTANCE_ATTENUATION: GLenum = 0x8129;

/// 16 values at `m`, column major once transposed; `None` for null (the
/// call then does nothing, as Mesa's `_mesa_LoadTransposeMatrixf`).
///
/// # Safety
/// `m` is null or points to 16 values.
unsafe fn transposed<T: Copy + Into<f64>>(m: *const T) -> Option<Mat4> {
    if m.is_null() {
        return None;
    }
    // SAFETY: 16 readable values, by the caller's contract.
    let s = unsafe { std::slice::from_raw_parts(m, 16) };
    let a: [f64; 16] = std::array::from_fn(|i| s[i].into());
    Some(glam::DMat4::from_cols_array(&a).transpose().as_mat4())
}

/// Sets point parameter `pname` from `v` (one value, or three for the
/// attenuation; a scalar call sets the attenuation to `(v, 0, 0)` as Mesa's
/// `_mesa_PointParameterf` does).
fn point_parameter(gl: &mut Context, pname: GLenum, v: [f32; 3]) -> GlResult {
    let mut p = gl.state().point_params;
    match pname {
        GL_POINT_SIZE_MIN => p.size_min = v[0],
        GL_POINT_SIZE_MAX => p.size_max = v[0],
        GL_POINT_FADE_THRESHOLD_SIZE => p.fade_threshold = v[0],
        GL_POINT_DISTANCE_ATTENUATION => p.attenuation = v,
        _ => return Err(GlError::InvalidEnum),
    }
    gl.point_parameters(p)
}

/// The values `pname` takes (1, or 3 for the attenuation), read from `v`.
///
/// # Safety
/// `v` is null or holds the values `pname` takes.
unsafe fn point_values<T: Copy + Into<f64>>(pname: GLenum, v: *const T) -> Option<[f32; 3]> {
    if v.is_null() {
        return None;
    }
    let n = if pname == GL_POINT_DISTANCE_ATTENUATION { 3 } else { 1 };
    // SAFETY: `n` readable values, by the caller's contract.
    let s = unsafe { std::slice::from_raw_parts(v, n) };
    let mut out = [0.0f32; 3];
    for (o, x) in out.iter_mut().zip(s) {
        *o = (*x).into() as f32;
    }
    Some(out)
}

fn point_parameter_v(pname: GLenum, v: Option<[f32; 3]>) {
    rec(move |_, gl| match v {
        Some(v) => point_parameter(gl, pname, v),
        None => Err(GlError::InvalidValue),
    })
}

/// The point parameters and sample coverage `glGet*` answers.
pub(super) fn value(gl: &Context, pname: GLenum) -> Option<Val> {
    let p: PointParams = gl.state().point_params;
    let f = |v: f32| Val::F(vec![f64::from(v)]);
    Some(match pname {
        GL_POINT_SIZE_MIN => f(p.size_min),
        GL_POINT_SIZE_MAX => f(p.size_max),
        GL_POINT_FADE_THRESHOLD_SIZE => f(p.fade_threshold),
        GL_POINT_DISTANCE_ATTENUATION => Val::F(p.attenuation.iter().map(|&a| f64::from(a)).collect()),
        // GL_TRANSPOSE_{MODELVIEW,PROJECTION,TEXTURE}_MATRIX
        0x84E3..=0x84E5 => {
            let mode = [MatrixMode::Modelview, MatrixMode::Projection, MatrixMode::Texture][(pname - 0x84E3) as usize];
            Val::F(
                gl.matrix(mode)
                    .transpose()
                    .to_cols_array()
                    .iter()
                    .map(|&x| f64::from(x))
                    .collect(),
            )
        }
        _ => return None,
    })
}

exports! {
    /// # Safety
    /// `m` is null or points to 16 floats.
    [unsafe] fn glLoadTransposeMatrixf(m: *const f32) {
        // SAFETY: 16 floats by GL's contract; null is refused.
        let m = unsafe { transposed(m) };
        checked(move |gl| m.map_or(Ok(()), |m| gl.load_matrix(&m)))
    }
    /// # Safety
    /// `m` is null or points to 16 doubles.
    [unsafe] fn glLoadTransposeMatrixd(m: *const f64) {
        // SAFETY: 16 doubles by GL's contract; null is refused.
        let m = unsafe { transposed(m) };
        checked(move |gl| m.map_or(Ok(()), |m| gl.load_matrix(&m)))
    }
    /// # Safety
    /// `m` is null or points to 16 floats.
    [unsafe] fn glMultTransposeMatrixf(m: *const f32) {
        // SAFETY: 16 floats by GL's contract; null is refused.
        let m = unsafe { transposed(m) };
        checked(move |gl| m.map_or(Ok(()), |m| gl.mult_matrix(&m)))
    }
    /// # Safety
    /// `m` is null or points to 16 doubles.
    [unsafe] fn glMultTransposeMatrixd(m: *const f64) {
        // SAFETY: 16 doubles by GL's contract; null is refused.
        let m = unsafe { transposed(m) };
        checked(move |gl| m.map_or(Ok(()), |m| gl.mult_matrix(&m)))
    }
    /// # Safety
    /// As [`glLoadTransposeMatrixf`].
    [unsafe] fn glLoadTransposeMatrixfARB(m: *const f32) {
        // SAFETY: the same contract.
        unsafe { glLoadTransposeMatrixf(m) }
    }
    /// # Safety
    /// As [`glLoadTransposeMatrixd`].
    [unsafe] fn glLoadTransposeMatrixdARB(m: *const f64) {
        // SAFETY: the same contract.
        unsafe { glLoadTransposeMatrixd(m) }
    }
    /// # Safety
    /// As [`glMultTransposeMatrixf`].
    [unsafe] fn glMultTransposeMatrixfARB(m: *const f32) {
        // SAFETY: the same contract.
        unsafe { glMultTransposeMatrixf(m) }
    }
    /// # Safety
    /// As [`glMultTransposeMatrixd`].
    [unsafe] fn glMultTransposeMatrixdARB(m: *const f64) {
        // SAFETY: the same contract.
        unsafe { glMultTransposeMatrixd(m) }
    }
    [] fn glPointParameterf(pname: GLenum, param: f32) {
        point_parameter_v(pname, Some([param, 0.0, 0.0]))
    }
    [] fn glPointParameteri(pname: GLenum, param: i32) {
        point_parameter_v(pname, Some([param as f32, 0.0, 0.0]))
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glPointParameterfv(pname: GLenum, params: *const f32) {
        // SAFETY: by GL's contract.
        point_parameter_v(pname, unsafe { point_values(pname, params) })
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glPointParameteriv(pname: GLenum, params: *const i32) {
        // SAFETY: by GL's contract.
        point_parameter_v(pname, unsafe { point_values(pname, params) })
    }
    [] fn glPointParameterfARB(pname: GLenum, param: f32) {
        glPointParameterf(pname, param)
    }
    /// # Safety
    /// As [`glPointParameterfv`].
    [unsafe] fn glPointParameterfvARB(pname: GLenum, params: *const f32) {
        // SAFETY: the same contract.
        unsafe { glPointParameterfv(pname, params) }
    }
    [] fn glPointParameterfEXT(pname: GLenum, param: f32) {
        glPointParameterf(pname, param)
    }
    /// # Safety
    /// As [`glPointParameterfv`].
    [unsafe] fn glPointParameterfvEXT(pname: GLenum, params: *const f32) {
        // SAFETY: the same contract.
        unsafe { glPointParameterfv(pname, params) }
    }
}
