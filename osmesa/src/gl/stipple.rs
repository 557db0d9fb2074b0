//! Line and polygon stipple: `glLineStipple`, `glPolygonStipple` (its
//! bitmap read under the unpack state at the call, so a display list keeps
//! a copy, as GL 1.5 §5.4 says) and `glGetPolygonStipple` (written under
//! the pack state, at once even while a list is compiled).

use super::{gl, now, outside};
use crate::state::with_gl;
use softgl::raster::stipple;
use softgl::GlError;

exports! {
    /// `glLineStipple`: `factor` clamped to `[1, 256]`.
    [] fn glLineStipple(factor: i32, pattern: u16) {
        gl(move |gl| gl.line_stipple(factor, pattern))
    }

    /// `glPolygonStipple`; a null `mask` changes nothing (Mesa's
    /// `_mesa_unpack_polygon_stipple` with no pixel buffer).
    ///
    /// # Safety
    /// `mask` is null or holds a 32×32 bitmap as the unpack state lays it out.
    [unsafe] fn glPolygonStipple(mask: *const u8) {
        let Some(store) = with_gl(None, |os, _| Some(os.unpack)) else {
            return;
        };
        let rows = match stipple::bitmap_len(&store) {
            Some(_) if mask.is_null() => None,
            Some(len) => {
                // SAFETY: the caller's `mask` holds the bitmap under the unpack
                // state, `len` bytes from its start.
                let bytes = unsafe { std::slice::from_raw_parts(mask, len) };
                stipple::unpack(bytes, &store)
            }
            None => None,
        };
        gl(move |gl| match rows {
            Some(rows) => gl.polygon_stipple(rows),
            None => outside(gl),
        })
    }

    /// `glGetPolygonStipple`; a null `mask` writes nothing.
    ///
    /// # Safety
    /// `mask` is null or has room for a 32×32 bitmap as the pack state lays it out.
    [unsafe] fn glGetPolygonStipple(mask: *mut u8) {
        now(|os, gl| {
            outside(gl)?;
            let store = os.pack;
            let len = stipple::bitmap_len(&store).ok_or(GlError::InvalidValue)?;
            if mask.is_null() {
                return Ok(());
            }
            // SAFETY: the caller's `mask` has room for the bitmap under the
            // pack state, `len` bytes from its start.
            let out = unsafe { std::slice::from_raw_parts_mut(mask, len) };
            let _ = stipple::pack(&gl.state().polygon_stipple_pattern, out, &store);
            Ok(())
        })
    }
}
