//! The raster position and bitmaps: `glRasterPos*`, `glWindowPos*` (GL 1.4,
//! and the `ARB_window_pos`/`MESA_window_pos` names), `glBitmap` (its image
//! unpacked at the call, so that a display list keeps a copy).

use super::get::Val;
use super::gl;
use super::immediate::read;
use crate::gl_state::Cmd;
use softgl::pixel_rect::BitmapImage;
use softgl::{Context, GlError};
use std::sync::Arc;

/// The `GL_CURRENT_RASTER_*` values (texture coordinates: the active unit's).
pub(super) fn value(gl: &Context, pname: u32) -> Option<Val> {
    let r = gl.raster_position();
    let fl = |v: &[f32]| Val::F(v.iter().map(|&c| f64::from(c)).collect());
    let n = |v: &[f32]| Val::N(v.iter().map(|&c| f64::from(c)).collect());
    Some(match pname {
        0x0B04 => n(&r.color.to_array()), // CURRENT_RASTER_COLOR
        0x0B05 => fl(&[r.index]),         // CURRENT_RASTER_INDEX
        0x0B06 => fl(&r.tex_coords[gl.active_texture_unit()].to_array()), // CURRENT_RASTER_TEXTURE_COORDS
        0x0B07 => fl(&r.window),          // CURRENT_RASTER_POSITION
        0x0B08 => Val::B(vec![r.valid]),  // CURRENT_RASTER_POSITION_VALID
        0x0B09 => fl(&[r.distance]),      // CURRENT_RASTER_DISTANCE
        0x845F => n(&r.secondary.to_array()), // CURRENT_RASTER_SECONDARY_COLOR
        _ => return None,
    })
}

fn raster_pos(x: f32, y: f32, z: f32, w: f32) {
    gl(move |gl| gl.raster_pos(x, y, z, w))
}

fn window_pos(x: f32, y: f32, z: f32, w: f32) {
    gl(move |gl| gl.window_pos4(x, y, z, w))
}

exports! {
    [] fn glRasterPos2s(x: i16, y: i16) {
        raster_pos(f32::from(x), f32::from(y), 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glRasterPos2sv(v: *const i16) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 2>(v) } {
            raster_pos(f32::from(v[0]), f32::from(v[1]), 0.0, 1.0)
        }
    }
    [] fn glRasterPos2i(x: i32, y: i32) {
        raster_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glRasterPos2iv(v: *const i32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 2>(v) } {
            raster_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glRasterPos2f(x: f32, y: f32) {
        raster_pos(x, y, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glRasterPos2fv(v: *const f32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 2>(v) } {
            raster_pos(v[0], v[1], 0.0, 1.0)
        }
    }
    [] fn glRasterPos2d(x: f64, y: f64) {
        raster_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glRasterPos2dv(v: *const f64) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 2>(v) } {
            raster_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glRasterPos3s(x: i16, y: i16, z: i16) {
        raster_pos(f32::from(x), f32::from(y), f32::from(z), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glRasterPos3sv(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            raster_pos(f32::from(v[0]), f32::from(v[1]), f32::from(v[2]), 1.0)
        }
    }
    [] fn glRasterPos3i(x: i32, y: i32, z: i32) {
        raster_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glRasterPos3iv(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            raster_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glRasterPos3f(x: f32, y: f32, z: f32) {
        raster_pos(x, y, z, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glRasterPos3fv(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            raster_pos(v[0], v[1], v[2], 1.0)
        }
    }
    [] fn glRasterPos3d(x: f64, y: f64, z: f64) {
        raster_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glRasterPos3dv(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            raster_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glRasterPos4s(x: i16, y: i16, z: i16, w: i16) {
        raster_pos(f32::from(x), f32::from(y), f32::from(z), f32::from(w))
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glRasterPos4sv(v: *const i16) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 4>(v) } {
            raster_pos(f32::from(v[0]), f32::from(v[1]), f32::from(v[2]), f32::from(v[3]))
        }
    }
    [] fn glRasterPos4i(x: i32, y: i32, z: i32, w: i32) {
        raster_pos(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glRasterPos4iv(v: *const i32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 4>(v) } {
            raster_pos(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glRasterPos4f(x: f32, y: f32, z: f32, w: f32) {
        raster_pos(x, y, z, w)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glRasterPos4fv(v: *const f32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 4>(v) } {
            raster_pos(v[0], v[1], v[2], v[3])
        }
    }
    [] fn glRasterPos4d(x: f64, y: f64, z: f64, w: f64) {
        raster_pos(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glRasterPos4dv(v: *const f64) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 4>(v) } {
            raster_pos(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glWindowPos2s(x: i16, y: i16) {
        window_pos(f32::from(x), f32::from(y), 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2sv(v: *const i16) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 2>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), 0.0, 1.0)
        }
    }
    [] fn glWindowPos2i(x: i32, y: i32) {
        window_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2iv(v: *const i32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 2>(v) } {
            window_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glWindowPos2f(x: f32, y: f32) {
        window_pos(x, y, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2fv(v: *const f32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 2>(v) } {
            window_pos(v[0], v[1], 0.0, 1.0)
        }
    }
    [] fn glWindowPos2d(x: f64, y: f64) {
        window_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2dv(v: *const f64) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 2>(v) } {
            window_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glWindowPos3s(x: i16, y: i16, z: i16) {
        window_pos(f32::from(x), f32::from(y), f32::from(z), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3sv(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), f32::from(v[2]), 1.0)
        }
    }
    [] fn glWindowPos3i(x: i32, y: i32, z: i32) {
        window_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3iv(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glWindowPos3f(x: f32, y: f32, z: f32) {
        window_pos(x, y, z, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3fv(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            window_pos(v[0], v[1], v[2], 1.0)
        }
    }
    [] fn glWindowPos3d(x: f64, y: f64, z: f64) {
        window_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3dv(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glWindowPos2sARB(x: i16, y: i16) {
        window_pos(f32::from(x), f32::from(y), 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2svARB(v: *const i16) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 2>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), 0.0, 1.0)
        }
    }
    [] fn glWindowPos2iARB(x: i32, y: i32) {
        window_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2ivARB(v: *const i32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 2>(v) } {
            window_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glWindowPos2fARB(x: f32, y: f32) {
        window_pos(x, y, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2fvARB(v: *const f32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 2>(v) } {
            window_pos(v[0], v[1], 0.0, 1.0)
        }
    }
    [] fn glWindowPos2dARB(x: f64, y: f64) {
        window_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2dvARB(v: *const f64) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 2>(v) } {
            window_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glWindowPos3sARB(x: i16, y: i16, z: i16) {
        window_pos(f32::from(x), f32::from(y), f32::from(z), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3svARB(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), f32::from(v[2]), 1.0)
        }
    }
    [] fn glWindowPos3iARB(x: i32, y: i32, z: i32) {
        window_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3ivARB(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glWindowPos3fARB(x: f32, y: f32, z: f32) {
        window_pos(x, y, z, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3fvARB(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            window_pos(v[0], v[1], v[2], 1.0)
        }
    }
    [] fn glWindowPos3dARB(x: f64, y: f64, z: f64) {
        window_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3dvARB(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glWindowPos2sMESA(x: i16, y: i16) {
        window_pos(f32::from(x), f32::from(y), 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2svMESA(v: *const i16) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 2>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), 0.0, 1.0)
        }
    }
    [] fn glWindowPos2iMESA(x: i32, y: i32) {
        window_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2ivMESA(v: *const i32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 2>(v) } {
            window_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glWindowPos2fMESA(x: f32, y: f32) {
        window_pos(x, y, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2fvMESA(v: *const f32) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 2>(v) } {
            window_pos(v[0], v[1], 0.0, 1.0)
        }
    }
    [] fn glWindowPos2dMESA(x: f64, y: f64) {
        window_pos(x as f32, y as f32, 0.0, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 2 values.
    [unsafe] fn glWindowPos2dvMESA(v: *const f64) {
        // SAFETY: 2 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 2>(v) } {
            window_pos(v[0] as f32, v[1] as f32, 0.0, 1.0)
        }
    }
    [] fn glWindowPos3sMESA(x: i16, y: i16, z: i16) {
        window_pos(f32::from(x), f32::from(y), f32::from(z), 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3svMESA(v: *const i16) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 3>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), f32::from(v[2]), 1.0)
        }
    }
    [] fn glWindowPos3iMESA(x: i32, y: i32, z: i32) {
        window_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3ivMESA(v: *const i32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 3>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glWindowPos3fMESA(x: f32, y: f32, z: f32) {
        window_pos(x, y, z, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3fvMESA(v: *const f32) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 3>(v) } {
            window_pos(v[0], v[1], v[2], 1.0)
        }
    }
    [] fn glWindowPos3dMESA(x: f64, y: f64, z: f64) {
        window_pos(x as f32, y as f32, z as f32, 1.0)
    }
    /// # Safety
    /// `v` is null or points to 3 values.
    [unsafe] fn glWindowPos3dvMESA(v: *const f64) {
        // SAFETY: 3 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 3>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, 1.0)
        }
    }
    [] fn glWindowPos4sMESA(x: i16, y: i16, z: i16, w: i16) {
        window_pos(f32::from(x), f32::from(y), f32::from(z), f32::from(w))
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glWindowPos4svMESA(v: *const i16) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i16, 4>(v) } {
            window_pos(f32::from(v[0]), f32::from(v[1]), f32::from(v[2]), f32::from(v[3]))
        }
    }
    [] fn glWindowPos4iMESA(x: i32, y: i32, z: i32, w: i32) {
        window_pos(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glWindowPos4ivMESA(v: *const i32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<i32, 4>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    [] fn glWindowPos4fMESA(x: f32, y: f32, z: f32, w: f32) {
        window_pos(x, y, z, w)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glWindowPos4fvMESA(v: *const f32) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f32, 4>(v) } {
            window_pos(v[0], v[1], v[2], v[3])
        }
    }
    [] fn glWindowPos4dMESA(x: f64, y: f64, z: f64, w: f64) {
        window_pos(x as f32, y as f32, z as f32, w as f32)
    }
    /// # Safety
    /// `v` is null or points to 4 values.
    [unsafe] fn glWindowPos4dvMESA(v: *const f64) {
        // SAFETY: 4 readable values by GL's contract; null is ignored.
        if let Some(v) = unsafe { read::<f64, 4>(v) } {
            window_pos(v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32)
        }
    }
    /// `glBitmap`: the image is unpacked now (a display list keeps the copy).
    ///
    /// # Safety
    /// `bitmap` is null (an empty image) or holds the image as the unpack
    /// state lays it out.
    [unsafe] fn glBitmap(width: i32, height: i32, xorig: f32, yorig: f32, xmove: f32, ymove: f32, bitmap: *const u8) {
        crate::state::with_gl((), |os, gl| {
            let image = match BitmapImage::client_bytes(width, height, &os.unpack) {
                None => Err(GlError::InvalidValue),
                Some(_) if bitmap.is_null() => Ok(BitmapImage::empty_sized(width, height)),
                Some(len) => {
                    // SAFETY: `len` readable bytes (the image under the unpack state) by GL's contract.
                    let data = unsafe { std::slice::from_raw_parts(bitmap, len) };
                    BitmapImage::unpack(width, height, data, &os.unpack)
                }
            };
            let cmd: Cmd = Arc::new(move |_, gl: &mut Context| {
                let r = image
                    .as_ref()
                    .map_err(|e| *e)
                    .and_then(|b| gl.bitmap(b, [xorig, yorig], [xmove, ymove]));
                if let Err(e) = r {
                    gl.record_error(e);
                }
            });
            super::run_or_record(os, gl, cmd);
        })
    }
}
