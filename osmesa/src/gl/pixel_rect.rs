//! Pixel rectangles: `glDrawPixels`, `glCopyPixels`, `glPixelZoom`,
//! `glPixelTransfer`, `glPixelMap` and `glGetPixelMap`. `glDrawPixels`
//! reads the client's image at the call (a display list keeps a copy).

use super::enums::decode;
use super::get::Val;
use super::pixels::pixel_size;
use super::{gl, now, run_or_record};
use crate::consts::*;
use crate::gl_state::Cmd;
use softgl::pixel_rect::{CopyKind, DrawKind};
use softgl::pixel_transfer::{PixelMapName, PixelTransferParam, MAX_PIXEL_MAP_TABLE};
use softgl::texture::unpack::ClientLayout;
use softgl::texture::{PixelData, PixelFormat, PixelType};
use softgl::{Context, GlError, GlResult};
use std::ffi::c_void;
use std::sync::Arc;

const GL_COLOR: GLenum = 0x1800;
const GL_DEPTH: GLenum = 0x1801;
const GL_STENCIL: GLenum = 0x1802;

/// The `glGet` values of the pixel state: zoom, transfer, map sizes.
pub(super) fn value(gl: &Context, pname: GLenum) -> Option<Val> {
    let p = gl.pixel_state();
    let f = |v: f32| Val::F(vec![f64::from(v)]);
    let i = |v: i64| Val::I(vec![v]);
    Some(match pname {
        0x0D10 => Val::B(vec![p.map_color]),   // MAP_COLOR
        0x0D11 => Val::B(vec![p.map_stencil]), // MAP_STENCIL
        0x0D12 => i(p.index_shift.into()),     // INDEX_SHIFT
        0x0D13 => i(p.index_offset.into()),    // INDEX_OFFSET
        0x0D14 => f(p.scale[0]),               // RED_SCALE
        0x0D15 => f(p.bias[0]),
        0x0D16 => f(p.zoom[0]), // ZOOM_X
        0x0D17 => f(p.zoom[1]),
        0x0D18 => f(p.scale[1]), // GREEN_SCALE
        0x0D19 => f(p.bias[1]),
        0x0D1A => f(p.scale[2]),
        0x0D1B => f(p.bias[2]),
        0x0D1C => f(p.scale[3]),
        0x0D1D => f(p.bias[3]),
        0x0D1E => f(p.depth_scale), // DEPTH_SCALE
        0x0D1F => f(p.depth_bias),
        0x0D34 => i(MAX_PIXEL_MAP_TABLE as i64), // MAX_PIXEL_MAP_TABLE
        0x0CB0..=0x0CB9 => i(p.maps[(pname - 0x0CB0) as usize].len() as i64), // PIXEL_MAP_*_SIZE
        _ => return None,
    })
}

fn transfer(pname: GLenum, v: f32) {
    let p = match pname {
        0x0D10 => Ok(PixelTransferParam::MapColor(v != 0.0)),
        0x0D11 => Ok(PixelTransferParam::MapStencil(v != 0.0)),
        0x0D12 => Ok(PixelTransferParam::IndexShift(v as i32)),
        0x0D13 => Ok(PixelTransferParam::IndexOffset(v as i32)),
        0x0D14 | 0x0D18 | 0x0D1A | 0x0D1C => Ok(PixelTransferParam::Scale(component(pname), v)),
        0x0D15 | 0x0D19 | 0x0D1B | 0x0D1D => Ok(PixelTransferParam::Bias(component(pname), v)),
        0x0D1E => Ok(PixelTransferParam::DepthScale(v)),
        0x0D1F => Ok(PixelTransferParam::DepthBias(v)),
        _ => Err(GlError::InvalidEnum),
    };
    super::checked(move |gl| {
        super::outside(gl)?;
        gl.pixel_transfer(p?)
    })
}

/// The colour component of a scale or bias name.
fn component(pname: GLenum) -> usize {
    match pname {
        0x0D14 | 0x0D15 => 0,
        0x0D18 | 0x0D19 => 1,
        0x0D1A | 0x0D1B => 2,
        _ => 3,
    }
}

/// `glPixelMap*v`: `values` read now (`n` of them), converted by `conv`.
fn pixel_map(map: GLenum, n: i32, read: impl FnOnce(usize) -> Option<Vec<f32>>) {
    let name = PixelMapName::from_gl(map).ok_or(GlError::InvalidEnum);
    let values = match name {
        Err(e) => Err(e),
        Ok(_) if !(1..=MAX_PIXEL_MAP_TABLE as i32).contains(&n) => Err(GlError::InvalidValue),
        Ok(_) => read(n as usize).ok_or(GlError::InvalidValue),
    };
    super::checked(move |gl| {
        super::outside(gl)?;
        gl.pixel_map(name?, values.as_deref().map_err(|e| *e)?)
    })
}

/// `glGetPixelMap*v`: the map's values, converted by `conv`, written through `out`.
fn get_pixel_map<T: Copy>(map: GLenum, out: *mut T, conv: impl Fn(f32, bool) -> T) {
    now(|_, gl| {
        super::outside(gl)?;
        let name = PixelMapName::from_gl(map).ok_or(GlError::InvalidEnum)?;
        let vals: Vec<T> = gl
            .pixel_state()
            .map(name)
            .iter()
            .map(|&v| conv(v, name.colour()))
            .collect();
        if !out.is_null() {
            // SAFETY: room for the map's size by GL's contract (`GL_PIXEL_MAP_*_SIZE`).
            unsafe { std::ptr::copy_nonoverlapping(vals.as_ptr(), out, vals.len()) };
        }
        Ok(())
    })
}

/// What `glDrawPixels` draws from `format` and `ty`, checked as Mesa checks
/// them, and the bytes of a `width`×`height` image under `store`.
fn draw_format(
    format: GLenum,
    ty: GLenum,
    width: i32,
    height: i32,
    store: &crate::gl_state::PixelStore,
) -> GlResult<(DrawKind, PixelFormat, PixelType, usize)> {
    if width < 0 || height < 0 {
        return Err(GlError::InvalidValue);
    }
    pixel_size(format, ty)?;
    let (kind, pf) = match format {
        GL_STENCIL_INDEX => (DrawKind::Stencil, PixelFormat::DepthComponent),
        GL_DEPTH_COMPONENT => (DrawKind::Depth, PixelFormat::DepthComponent),
        crate::consts::GL_DEPTH_STENCIL => (DrawKind::DepthStencil, PixelFormat::DepthStencil),
        GL_COLOR_INDEX => (DrawKind::Index, PixelFormat::DepthComponent),
        f => (DrawKind::Color, decode::<PixelFormat>(f)?),
    };
    let ty = decode::<PixelType>(ty)?;
    let layout =
        ClientLayout::new(pf, ty, store, 2, [width as usize, height as usize, 1]).ok_or(GlError::InvalidValue)?;
    Ok((kind, pf, ty, layout.len))
}

const GL_BITMAP: GLenum = 0x1A00;

/// `glDrawPixels` of type `GL_BITMAP` (colour or stencil indices of one bit),
/// the image unpacked now.
///
/// # Safety
/// `pixels` is null (nothing drawn) or holds the bitmap as the unpack state lays it out.
unsafe fn draw_bitmap_pixels(width: i32, height: i32, format: GLenum, pixels: *const u8) {
    use softgl::pixel_rect::BitmapImage;
    crate::state::with_gl((), |os, gl| {
        let image = match (format, BitmapImage::client_bytes(width, height, &os.unpack)) {
            (_, None) => Err(GlError::InvalidValue),
            (GL_COLOR_INDEX | GL_STENCIL_INDEX, Some(_)) if pixels.is_null() => Ok(None),
            (GL_COLOR_INDEX | GL_STENCIL_INDEX, Some(len)) => {
                // SAFETY: `len` readable bytes (the bitmap under the unpack state) by GL's contract.
                let data = unsafe { std::slice::from_raw_parts(pixels, len) };
                BitmapImage::unpack(width, height, data, &os.unpack).map(Some)
            }
            _ => Err(GlError::InvalidEnum),
        };
        let kind = if format == GL_STENCIL_INDEX {
            DrawKind::Stencil
        } else {
            DrawKind::Index
        };
        let cmd: Cmd = Arc::new(move |_, gl: &mut Context| {
            let r = match &image {
                Err(e) => Err(*e),
                Ok(Some(b)) => gl.draw_pixels_bitmap(b, kind),
                Ok(None) => super::outside(gl),
            };
            if let Err(e) = r {
                gl.record_error(e);
            }
        });
        run_or_record(os, gl, cmd);
    })
}

exports! {
    [] fn glPixelZoom(xfactor: f32, yfactor: f32) {
        gl(move |gl| gl.pixel_zoom(xfactor, yfactor))
    }
    [] fn glPixelTransferf(pname: GLenum, param: f32) {
        transfer(pname, param)
    }
    [] fn glPixelTransferi(pname: GLenum, param: i32) {
        transfer(pname, param as f32)
    }
    /// # Safety
    /// `values` is null or holds `size` values.
    [unsafe] fn glPixelMapfv(map: GLenum, size: i32, values: *const f32) {
        // SAFETY: `n` readable values by GL's contract; null is refused.
        pixel_map(map, size, |n| (!values.is_null()).then(|| unsafe { std::slice::from_raw_parts(values, n) }.to_vec()))
    }
    /// # Safety
    /// `values` is null or holds `size` values.
    [unsafe] fn glPixelMapuiv(map: GLenum, size: i32, values: *const u32) {
        let colour = PixelMapName::from_gl(map).is_some_and(|m| m.colour());
        pixel_map(map, size, |n| {
            // SAFETY: `n` readable values by GL's contract; null is refused.
            let v = (!values.is_null()).then(|| unsafe { std::slice::from_raw_parts(values, n) })?;
            Some(v.iter().map(|&x| if colour { (f64::from(x) / f64::from(u32::MAX)) as f32 } else { x as f32 }).collect())
        })
    }
    /// # Safety
    /// `values` is null or holds `size` values.
    [unsafe] fn glPixelMapusv(map: GLenum, size: i32, values: *const u16) {
        let colour = PixelMapName::from_gl(map).is_some_and(|m| m.colour());
        pixel_map(map, size, |n| {
            // SAFETY: `n` readable values by GL's contract; null is refused.
            let v = (!values.is_null()).then(|| unsafe { std::slice::from_raw_parts(values, n) })?;
            Some(v.iter().map(|&x| if colour { f32::from(x) / 65535.0 } else { f32::from(x) }).collect())
        })
    }
    /// # Safety
    /// `values` is null or has room for the map's size.
    [unsafe] fn glGetPixelMapfv(map: GLenum, values: *mut f32) {
        get_pixel_map(map, values, |v, _| v)
    }
    /// # Safety
    /// `values` is null or has room for the map's size.
    [unsafe] fn glGetPixelMapuiv(map: GLenum, values: *mut u32) {
        // Colours times the largest value, truncated (Mesa's `FLOAT_TO_UINT`).
        get_pixel_map(map, values, |v, colour| if colour { (f64::from(v) * f64::from(u32::MAX)) as u32 } else { v as u32 })
    }
    /// # Safety
    /// `values` is null or has room for the map's size.
    [unsafe] fn glGetPixelMapusv(map: GLenum, values: *mut u16) {
        get_pixel_map(map, values, |v, colour| if colour { (v * 65535.0) as u16 } else { v as u16 })
    }
    /// `glDrawPixels`: the image is read now (a display list keeps a copy).
    ///
    /// # Safety
    /// `pixels` is null (nothing drawn) or holds the image as the unpack state lays it out.
    [unsafe] fn glDrawPixels(width: i32, height: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        if ty == GL_BITMAP {
            // SAFETY: as the caller's contract says.
            return unsafe { draw_bitmap_pixels(width, height, format, pixels.cast()) };
        }
        crate::state::with_gl((), |os, gl| {
            let store = os.unpack;
            let copy = draw_format(format, ty, width, height, &store).map(|(kind, pf, t, len)| {
                // SAFETY: `len` readable bytes (the image under the unpack state) by GL's contract.
                let bytes = (!pixels.is_null()).then(|| unsafe { std::slice::from_raw_parts(pixels.cast::<u8>(), len) }.to_vec());
                (kind, pf, t, bytes)
            });
            let cmd: Cmd = Arc::new(move |_, gl: &mut Context| {
                let r = match &copy {
                    Err(e) => Err(*e),
                    Ok((kind, pf, t, Some(bytes))) => {
                        let data = PixelData { format: *pf, ty: *t, store, bytes };
                        gl.draw_pixels(width, height, *kind, &data)
                    }
                    Ok((_, _, _, None)) => super::outside(gl),
                };
                if let Err(e) = r {
                    gl.record_error(e);
                }
            });
            run_or_record(os, gl, cmd);
        })
    }
    [] fn glCopyPixels(x: i32, y: i32, width: i32, height: i32, ty: GLenum) {
        let kind = match ty {
            GL_COLOR => Ok(CopyKind::Color),
            GL_DEPTH => Ok(CopyKind::Depth),
            GL_STENCIL => Ok(CopyKind::Stencil),
            crate::consts::GL_DEPTH_STENCIL => Ok(CopyKind::DepthStencil),
            _ => Err(GlError::InvalidEnum),
        };
        super::checked(move |gl| {
            super::outside(gl)?;
            if width < 0 || height < 0 {
                return Err(GlError::InvalidValue);
            }
            gl.copy_pixels(x, y, width, height, kind?)
        })
    }
}
