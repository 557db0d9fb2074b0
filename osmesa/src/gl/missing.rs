//! Entry points of GL 1.x that softgl does not implement yet. Each is
//! exported (so that GLU and PyOpenGL resolve it here, not in another GL
//! library) and records `GL_INVALID_OPERATION` when it runs: compiled into a
//! display list like the command it stands for, or at once for the commands
//! GL never compiles (queries, `glRenderMode`, client arrays). None reads
//! or writes through its pointers, so none is `unsafe`.
//! The README lists them by group.

use super::{missing, missing_now};
use crate::consts::*;

exports! {
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glRenderMode(_mode: GLenum) -> i32 {
        missing_now();
        0
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glSelectBuffer(_size: i32, _buffer: *mut u32) {
        missing_now()
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glFeedbackBuffer(_size: i32, _ty: GLenum, _buffer: *mut f32) {
        missing_now()
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glInitNames() {
        missing()
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glLoadName(_name: u32) {
        missing()
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPushName(_name: u32) {
        missing()
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPopName() {
        missing()
    }
    /// Selection and feedback (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glPassThrough(_token: f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap1f(_target: GLenum, _u1: f32, _u2: f32, _stride: i32, _order: i32, _points: *const f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap2f(_target: GLenum, _u1: f32, _u2: f32, _ustride: i32, _uorder: i32, _v1: f32, _v2: f32, _vstride: i32, _vorder: i32, _points: *const f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid1f(_un: i32, _u1: f32, _u2: f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid2f(_un: i32, _u1: f32, _u2: f32, _vn: i32, _v1: f32, _v2: f32) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetMapfv(_target: GLenum, _query: GLenum, _v: *mut f32) {
        missing_now()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap1d(_target: GLenum, _u1: f64, _u2: f64, _stride: i32, _order: i32, _points: *const f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMap2d(_target: GLenum, _u1: f64, _u2: f64, _ustride: i32, _uorder: i32, _v1: f64, _v2: f64, _vstride: i32, _vorder: i32, _points: *const f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid1d(_un: i32, _u1: f64, _u2: f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glMapGrid2d(_un: i32, _u1: f64, _u2: f64, _vn: i32, _v1: f64, _v2: f64) {
        missing()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetMapdv(_target: GLenum, _query: GLenum, _v: *mut f64) {
        missing_now()
    }
    /// Evaluators (not in softgl yet): `GL_INVALID_OPERATION`.
    [] fn glGetMapiv(_target: GLenum, _query: GLenum, _v: *mut i32) {
        missing_now()
    }
}
