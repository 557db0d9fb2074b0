//! The GL entry points. Each submodule declares its exports with
//! `exports!`, which also lists them for `OSMesaGetProcAddress`.

use crate::gl_state::{Cmd, GlState};
use crate::state::{attrib, with_gl};
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

mod accum;
mod arrays;
mod attrib;
mod buffers;
mod enums;
mod eval;
mod extensions;
mod extra_attribs;
mod fbo;
mod fog;
pub(crate) mod get;
mod gl14;
mod immediate;
mod index;
mod lighting;
mod lists;
mod pixel_rect;
mod pixels;
mod queries;
mod raster_pos;
pub(crate) mod select;
mod state;
mod stipple;
mod texture;
mod texunit;
mod vertex_array_ext;

pub use accum::*;
pub use arrays::*;
pub use attrib::{glPopAttrib, glPopClientAttrib, glPushAttrib, glPushClientAttrib};
pub use buffers::*;
pub use eval::*;
pub use extra_attribs::*;
pub use fbo::*;
pub use fog::*;
pub use get::*;
pub use gl14::*;
pub use immediate::*;
pub use index::*;
pub use lighting::*;
pub use lists::*;
pub use pixel_rect::*;
pub use pixels::*;
pub use queries::*;
pub use raster_pos::*;
pub use select::*;
pub use state::*;
pub use stipple::*;
pub use texture::*;
pub use texunit::*;
pub use vertex_array_ext::*;

/// Every `gl*` export of this library: each module's `exports!` table.
fn all_exports() -> impl Iterator<Item = (&'static str, *const std::ffi::c_void)> {
    [
        accum::table,
        arrays::table,
        attrib::table,
        buffers::table,
        eval::table,
        extra_attribs::table,
        fbo::table,
        fog::table,
        fog::color_table,
        gl14::table,
        get::table,
        immediate::table,
        index::table,
        lighting::table,
        lists::table,
        pixel_rect::table,
        pixels::table,
        queries::table,
        raster_pos::table,
        select::table,
        state::table,
        stipple::table,
        texture::table,
        texunit::table,
        vertex_array_ext::table,
        texunit::multi_table,
    ]
    .into_iter()
    .flat_map(|t| t())
}

/// The address of the export called `name`.
/// The address of the export called `name`, or of the core function that
/// answers an advertised extension's entry point (`gl::extensions`).
pub(crate) fn proc_address(name: &str) -> Option<*const std::ffi::c_void> {
    let find = |name: &str| all_exports().find(|(n, _)| *n == name).map(|(_, p)| p);
    find(name).or_else(|| find(extensions::core_name(name)?))
}

/// Every `gl*` name this library exports.
pub fn exported_names() -> Vec<&'static str> {
    all_exports().map(|(n, _)| n).collect()
}

/// Runs `cmd` now, or records it in the display list being compiled (and
/// runs it too under `GL_COMPILE_AND_EXECUTE`).
pub(crate) fn run_or_record(os: &mut GlState, gl: &mut Context, cmd: Cmd) {
    match os.compiling.as_mut() {
        Some(list) => {
            // Not a vertex attribute call: a run compiled so far replays as calls.
            lists::close_run(list);
            list.cmds.push(cmd.clone());
            if list.execute {
                cmd(os, gl);
            }
        }
        None => cmd(os, gl),
    }
}

/// A GL call that display lists record: runs `f` on the current context
/// (recording the error it returns), or records it.
fn rec(f: impl Fn(&mut GlState, &mut Context) -> GlResult + Send + Sync + 'static) {
    with_gl((), |os, gl| {
        if os.compiling.is_none() {
            // The common case: no list, no allocation.
            if let Err(e) = f(os, gl) {
                gl.record_error(e);
            }
            return;
        }
        let cmd: Cmd = std::sync::Arc::new(move |os: &mut GlState, gl: &mut Context| {
            if let Err(e) = f(os, gl) {
                gl.record_error(e);
            }
        });
        run_or_record(os, gl, cmd);
    })
}

/// A vertex attribute call (`glColor`, `glVertex`, …, errors recorded by
/// the context): run at once through [`attrib`]'s fast path (no lock, no
/// `RefCell`, no `catch_unwind`: `f` must not panic), recorded while a
/// display list is compiled.
#[inline(always)]
fn attr(f: impl Fn(&mut Context) + Send + Sync + 'static) {
    if let Some(f) = attrib(f) {
        record_attr(f);
    }
}

/// [`attr`] while a display list is compiled, out of the fast path's way.
#[cold]
#[inline(never)]
fn record_attr(f: impl Fn(&mut Context) + Send + Sync + 'static) {
    rec(move |_, gl| {
        f(gl);
        Ok(())
    })
}

/// A recorded call on the GL context alone; errors are recorded by the context.
fn gl(f: impl Fn(&mut Context) -> GlResult + Send + Sync + 'static) {
    rec(move |_, gl| {
        let _ = f(gl);
        Ok(())
    })
}

/// A recorded call whose error is recorded here (checks made in this layer,
/// which the context has not seen).
fn checked(f: impl Fn(&mut Context) -> GlResult + Send + Sync + 'static) {
    rec(move |_, gl| f(gl))
}

/// A call that runs at once, never recorded in a display list (queries,
/// client state, pixel packing, list management), recording its error.
fn now(f: impl FnOnce(&mut GlState, &mut Context) -> GlResult) {
    with_gl((), |os, gl| {
        if let Err(e) = f(os, gl) {
            gl.record_error(e);
        }
    })
}

/// `GL_INVALID_OPERATION` between `glBegin` and `glEnd`, where GL allows only
/// vertex attributes, `glArrayElement`, evaluators and `glCallList(s)`.
fn outside(gl: &Context) -> GlResult {
    if gl.inside_begin() {
        return Err(GlError::InvalidOperation);
    }
    Ok(())
}

/// Records `GL_INVALID_OPERATION` and says so between `glBegin` and `glEnd`
/// (for calls that are not run through [`now`] or [`rec`]).
fn refused_inside_begin() -> bool {
    with_gl(false, |_, gl| {
        let inside = gl.inside_begin();
        if inside {
            gl.record_error(GlError::InvalidOperation);
        }
        inside
    })
}
