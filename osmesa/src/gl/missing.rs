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
}
