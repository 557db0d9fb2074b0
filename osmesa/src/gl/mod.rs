//! The GL entry points. Each submodule declares its exports with
//! [`exports!`], which also lists them for `OSMesaGetProcAddress`.

use crate::state::{with_gl, OsContext};
use softgl::{Context, GlError, GlResult};

/// Declares `extern "C"` exports and a `table()` of their names and addresses.
/// `[unsafe]` before `fn` marks the ones that read or write through pointers.
macro_rules! exports {
    ($( $(#[$m:meta])* [$($q:tt)*] fn $name:ident ( $($a:ident : $t:ty),* $(,)? ) $(-> $r:ty)? $body:block )*) => {
        $(
            $(#[$m])*
            #[no_mangle]
            pub $($q)* extern "C" fn $name($($a: $t),*) $(-> $r)? $body
        )*
        /// This module's exports, by name.
        pub(crate) fn table() -> Vec<(&'static str, *const std::ffi::c_void)> {
            vec![$((stringify!($name), $name as *const std::ffi::c_void)),*]
        }
    };
}

mod arrays;
pub(crate) mod attrib;
mod enums;
mod get;
mod immediate;
mod missing;
mod pixels;
mod state;

pub use arrays::*;
pub use attrib::{glPopAttrib, glPopClientAttrib, glPushAttrib, glPushClientAttrib};
pub use get::*;
pub use immediate::*;
pub use missing::*;
pub use pixels::*;
pub use state::*;

/// The address of the export called `name`.
pub(crate) fn proc_address(name: &str) -> Option<*const std::ffi::c_void> {
    [
        arrays::table,
        attrib::table,
        get::table,
        immediate::table,
        missing::table,
        pixels::table,
        state::table,
    ]
    .iter()
    .flat_map(|t| t())
    .find(|(n, _)| *n == name)
    .map(|(_, p)| p)
}

/// Every `gl*` name this library exports.
pub fn exported_names() -> Vec<&'static str> {
    [
        arrays::table,
        attrib::table,
        get::table,
        immediate::table,
        missing::table,
        pixels::table,
        state::table,
    ]
    .iter()
    .flat_map(|t| t())
    .map(|(n, _)| n)
    .collect()
}

/// Runs `f` on the current GL context; errors are recorded by the context.
fn gl(f: impl FnOnce(&mut Context) -> GlResult) {
    with_gl((), |_, gl| {
        let _ = f(gl);
    })
}

/// Runs `f` with the OSMesa context too.
fn os(f: impl FnOnce(&mut OsContext, &mut Context) -> GlResult) {
    with_gl((), |os, gl| {
        if let Err(e) = f(os, gl) {
            gl.record_error(e);
        }
    })
}

/// Runs `f` on the current GL context, recording the error it returns (for
/// checks made in this layer, which the context has not seen).
fn checked(f: impl FnOnce(&mut Context) -> GlResult) {
    with_gl((), |_, gl| {
        if let Err(e) = f(gl) {
            gl.record_error(e);
        }
    })
}

/// A function softgl does not implement yet: `GL_INVALID_OPERATION`.
fn missing() {
    checked(|_| Err(GlError::InvalidOperation))
}
