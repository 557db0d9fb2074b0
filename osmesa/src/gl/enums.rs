//! GL enumerants to softgl's types (through the one table of each type,
//! [`softgl::gl_enum`]); anything else is `GL_INVALID_ENUM`.

use crate::consts::GLenum;
use softgl::{Capability, GlEnum, GlError, GlResult};

/// The variant of `T` whose GL value is `v`, or `GL_INVALID_ENUM`.
pub fn decode<T: GlEnum>(v: GLenum) -> GlResult<T> {
    T::from_gl(v).ok_or(GlError::InvalidEnum)
}

/// What `glEnable`/`glDisable` can name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cap {
    /// A capability softgl implements.
    Core(Capability),
    /// Stored in the interface layer (`GL_AUTO_NORMAL`, `GL_MAP1_*`,
    /// `GL_MAP2_*`: read by the evaluators).
    Inert(GLenum),
    /// A valid GL 1.x capability softgl does not implement yet.
    Missing,
}

pub fn cap(v: GLenum) -> GlResult<Cap> {
    if let Some(c) = Capability::from_gl(v) {
        return Ok(Cap::Core(c));
    }
    match v {
        // AUTO_NORMAL, MAP1_*, MAP2_* (the evaluators, `gl/eval.rs`)
        0x0D80 | 0x0D90..=0x0D98 | 0x0DB0..=0x0DB8 => Ok(Cap::Inert(v)),
        // POINT/LINE/POLYGON_SMOOTH, INDEX_LOGIC_OP
        0x0B10 | 0x0B20 | 0x0B41 | 0x0BF1 => Ok(Cap::Missing),
        _ => Err(GlError::InvalidEnum),
    }
}
