//! Selection and feedback (GL 1.5 §5.2, §5.3): a thin layer over
//! `softgl::select`. The context keeps the values a mode writes; they are
//! copied into the application's buffer when `glRenderMode` leaves the mode
//! (GL leaves the buffer undefined until then), only as many as were
//! written. `glInitNames`, `glLoadName`, `glPushName`, `glPopName` and
//! `glPassThrough` are compiled into display lists; `glRenderMode`,
//! `glSelectBuffer` and `glFeedbackBuffer` are not (GL 1.5 §5.4).

use super::get::Val;
use super::{gl, now, outside};
use crate::consts::*;
use crate::gl_state::GlState;
use softgl::select::{FeedbackType, ModeOutput, RenderMode, MAX_NAME_STACK_DEPTH};
use softgl::{Context, GlError};

pub const GL_RENDER: GLenum = 0x1C00;
pub const GL_FEEDBACK: GLenum = 0x1C01;
pub const GL_SELECT: GLenum = 0x1C02;
const GL_RENDER_MODE: GLenum = 0x0C40;
const GL_NAME_STACK_DEPTH: GLenum = 0x0D70;
const GL_MAX_NAME_STACK_DEPTH: GLenum = 0x0D37;
pub const GL_FEEDBACK_BUFFER_POINTER: GLenum = 0x0DF0;
const GL_FEEDBACK_BUFFER_SIZE: GLenum = 0x0DF1;
const GL_FEEDBACK_BUFFER_TYPE: GLenum = 0x0DF2;
pub const GL_SELECTION_BUFFER_POINTER: GLenum = 0x0DF3;
const GL_SELECTION_BUFFER_SIZE: GLenum = 0x0DF4;

/// The application's buffers (`glSelectBuffer`, `glFeedbackBuffer`).
#[derive(Clone, Copy, Debug)]
pub struct ModeBuffers {
    pub select: *mut u32,
    pub feedback: *mut f32,
}

impl Default for ModeBuffers {
    fn default() -> ModeBuffers {
        ModeBuffers {
            select: std::ptr::null_mut(),
            feedback: std::ptr::null_mut(),
        }
    }
}

// SAFETY: the pointers are only written through by the thread the context is
// current on, as GL's contract for them says.
unsafe impl Send for ModeBuffers {}

fn feedback_type(ty: GLenum) -> Option<(FeedbackType, GLenum)> {
    Some((
        match ty {
            0x0600 => FeedbackType::D2,
            0x0601 => FeedbackType::D3,
            0x0602 => FeedbackType::D3Color,
            0x0603 => FeedbackType::D3ColorTexture,
            0x0604 => FeedbackType::D4ColorTexture,
            _ => return None,
        },
        ty,
    ))
}

fn type_enum(ty: FeedbackType) -> GLenum {
    match ty {
        FeedbackType::D2 => 0x0600,
        FeedbackType::D3 => 0x0601,
        FeedbackType::D3Color => 0x0602,
        FeedbackType::D3ColorTexture => 0x0603,
        FeedbackType::D4ColorTexture => 0x0604,
    }
}

/// The `glGet*` values of this module's state, `None` for other names.
pub(super) fn value(os: &GlState, gl: &Context, pname: GLenum) -> Option<Val> {
    let r = gl.render_mode_state();
    let i = |v: i64| Val::I(vec![v]);
    Some(match pname {
        GL_RENDER_MODE => i(i64::from(match r.mode {
            RenderMode::Render => GL_RENDER,
            RenderMode::Feedback => GL_FEEDBACK,
            RenderMode::Select => GL_SELECT,
        })),
        GL_NAME_STACK_DEPTH => i(r.select.names.len() as i64),
        GL_MAX_NAME_STACK_DEPTH => i(MAX_NAME_STACK_DEPTH as i64),
        GL_SELECTION_BUFFER_SIZE => i(r.select.size as i64),
        GL_FEEDBACK_BUFFER_SIZE => i(r.feedback.size as i64),
        GL_FEEDBACK_BUFFER_TYPE => i(i64::from(type_enum(r.feedback.ty))),
        _ => {
            let _ = os;
            return None;
        }
    })
}

/// Copies the values the mode left wrote into the application's buffer.
fn copy_out(os: &GlState, output: &ModeOutput) {
    match output {
        ModeOutput::Select(b) if !os.mode_buffers.select.is_null() => {
            // SAFETY: `glSelectBuffer`'s buffer has room for its `size` values
            // (GL's contract); at most `size` were written.
            unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), os.mode_buffers.select, b.len()) };
        }
        ModeOutput::Feedback(b) if !os.mode_buffers.feedback.is_null() => {
            // SAFETY: as above, for `glFeedbackBuffer`'s buffer.
            unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), os.mode_buffers.feedback, b.len()) };
        }
        _ => {}
    }
}

exports! {
    /// `GL_RENDER`, `GL_SELECT` or `GL_FEEDBACK`: the hits or values of the
    /// mode left (−1 on overflow), written into its buffer.
    [] fn glRenderMode(mode: GLenum) -> i32 {
        let mut result = 0;
        now(|os, ctx| {
            outside(ctx)?;
            let m = match mode {
                GL_RENDER => RenderMode::Render,
                GL_SELECT => RenderMode::Select,
                GL_FEEDBACK => RenderMode::Feedback,
                _ => return Err(GlError::InvalidEnum),
            };
            let (r, output) = ctx.render_mode(m)?;
            copy_out(os, &output);
            result = r;
            Ok(())
        });
        result
    }
    /// The buffer hit records go to (`size` values).
    [] fn glSelectBuffer(size: i32, buffer: *mut u32) {
        now(|os, ctx| {
            ctx.select_buffer(size)?;
            os.mode_buffers.select = buffer;
            Ok(())
        })
    }
    /// The buffer feedback goes to (`size` values of type `ty`).
    [] fn glFeedbackBuffer(size: i32, ty: GLenum, buffer: *mut f32) {
        now(|os, ctx| {
            outside(ctx)?;
            let r = ctx.render_mode_state();
            if r.mode == RenderMode::Feedback {
                return Err(GlError::InvalidOperation);
            }
            if size < 0 {
                return Err(GlError::InvalidValue);
            }
            if buffer.is_null() && size > 0 {
                // Mesa sets the size to 0 then (the count is 0 outside feedback mode).
                ctx.feedback_buffer(0, r.feedback.ty)?;
                return Err(GlError::InvalidValue);
            }
            let (t, _) = feedback_type(ty).ok_or(GlError::InvalidEnum)?;
            ctx.feedback_buffer(size, t)?;
            os.mode_buffers.feedback = buffer;
            Ok(())
        })
    }
    /// Empties the name stack (select mode only).
    [] fn glInitNames() {
        gl(|ctx| ctx.init_names())
    }
    /// Replaces the top of the name stack (select mode only).
    [] fn glLoadName(name: u32) {
        gl(move |ctx| ctx.load_name(name))
    }
    /// Pushes a name (select mode only).
    [] fn glPushName(name: u32) {
        gl(move |ctx| ctx.push_name(name))
    }
    /// Pops a name (select mode only).
    [] fn glPopName() {
        gl(|ctx| ctx.pop_name())
    }
    /// A `GL_PASS_THROUGH_TOKEN` and `token` (feedback mode only).
    [] fn glPassThrough(token: f32) {
        gl(move |ctx| ctx.pass_through(token))
    }
}
