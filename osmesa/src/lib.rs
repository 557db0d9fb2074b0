//! softgl as a drop-in `libOSMesa.so.8`: Mesa's OSMesa C API (`GL/osmesa.h`)
//! and the GL 1.x entry points, over [`softgl::Context`].
//!
//! - Contexts live in a registry keyed by the handle C sees; a handle that was
//!   destroyed (or never existed) is refused, not dereferenced.
//! - Each thread has at most one current context, and a context is current
//!   on at most one thread (the thread holds its lock meanwhile, so GL calls
//!   lock nothing; see `state`); GL calls without one do nothing, as in Mesa.
//! - No panic crosses into C: every export runs its body under
//!   `catch_unwind`, except the vertex attribute calls (`glColor`,
//!   `glVertex`, …), plain stores and `Vec` pushes that cannot panic, which
//!   take a lock-free path of a few instructions (`state::attrib`).
//! - The colour formats softgl draws natively (RGBA, BGRA, RGB bytes and
//!   RGB 5-6-5) are rendered straight into the caller's buffer, honouring
//!   `OSMESA_ROW_LENGTH` and `OSMESA_Y_UP`; the others (ARGB, BGR, 16-bit and
//!   float channels) are rendered into softgl's own RGBA8 buffer and converted
//!   into the caller's at `glFlush`, `glFinish` and when the context stops
//!   being current, which is when Mesa's gallium OSMesa copies too.
//!
//! - The same library is also an EGL 1.5 `libEGL.so.1` and a `libGL.so.1`
//!   (see [`egl`]): an EGL context is an OSMesa context drawing into a pbuffer.
//!
//! `unsafe` lives in this crate only, one `// SAFETY:` line per block.
#![allow(non_snake_case)]

mod api;
pub mod consts;
mod convert;
pub mod egl;
mod gl;
mod gl_state;
mod state;

pub use api::*;
pub use gl::*;
