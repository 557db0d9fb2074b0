//! GL errors as values.

/// A GL error, named after the code `glGetError` would return.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, thiserror::Error)]
pub enum GlError {
    /// `GL_INVALID_ENUM`: an enumerant outside the accepted set, or one not
    /// accepted in that place (`SrcAlphaSaturate` as a destination factor).
    #[error("GL_INVALID_ENUM: enumerant out of range")]
    InvalidEnum,
    /// `GL_INVALID_VALUE`: a numeric argument out of range.
    #[error("GL_INVALID_VALUE: numeric argument out of range")]
    InvalidValue,
    /// `GL_INVALID_OPERATION`: not allowed in the current state (e.g. inside `begin`/`end`).
    #[error("GL_INVALID_OPERATION: operation not allowed in the current state")]
    InvalidOperation,
    /// `GL_STACK_OVERFLOW`: a push onto a full matrix stack.
    #[error("GL_STACK_OVERFLOW: matrix stack is full")]
    StackOverflow,
    /// `GL_STACK_UNDERFLOW`: a pop from a stack holding one matrix.
    #[error("GL_STACK_UNDERFLOW: matrix stack holds only one matrix")]
    StackUnderflow,
    /// `GL_OUT_OF_MEMORY`: a buffer could not be allocated.
    #[error("GL_OUT_OF_MEMORY: buffer allocation failed")]
    OutOfMemory,
    /// `GL_INVALID_FRAMEBUFFER_OPERATION`: a draw, clear or read on an
    /// incomplete framebuffer object.
    #[error("GL_INVALID_FRAMEBUFFER_OPERATION: framebuffer is not complete")]
    InvalidFramebufferOperation,
}

impl GlError {
    /// The GL enum value `glGetError` returns for this error.
    pub const fn code(self) -> u32 {
        match self {
            GlError::InvalidEnum => 0x0500,
            GlError::InvalidValue => 0x0501,
            GlError::InvalidOperation => 0x0502,
            GlError::StackOverflow => 0x0503,
            GlError::StackUnderflow => 0x0504,
            GlError::OutOfMemory => 0x0505,
            GlError::InvalidFramebufferOperation => 0x0506,
        }
    }
}

/// Result of a GL call.
pub type GlResult<T = ()> = Result<T, GlError>;
