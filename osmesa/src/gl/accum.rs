//! The accumulation buffer's entry points (`softgl::accum`): both are
//! compiled into display lists.

use super::checked;
use softgl::{AccumOp, GlError};

exports! {
    /// `glAccum`: `GL_INVALID_ENUM` for an unknown operation, then
    /// `GL_INVALID_OPERATION` without an accumulation buffer, as Mesa checks them.
    [] fn glAccum(op: u32, value: f32) {
        checked(move |gl| {
            if gl.inside_begin() {
                return Err(GlError::InvalidOperation);
            }
            gl.accum(AccumOp::from_gl(op)?, value)
        })
    }
    /// `glClearAccum`: clamped to `[-1, 1]`.
    [] fn glClearAccum(r: f32, g: f32, b: f32, a: f32) {
        checked(move |gl| gl.clear_accum(r, g, b, a))
    }
}
