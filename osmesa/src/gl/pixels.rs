//! `glPixelStore` and `glReadPixels`.

use super::enums::decode;
use super::now;
use crate::consts::*;
use crate::gl_state::PixelStore;
use softgl::texture::unpack::ClientLayout;
use softgl::texture::{PixelFormat, PixelType};
use softgl::{Context, Framebuffer, GlError, GlResult};
use std::ffi::c_void;

fn pixel_store(pname: GLenum, param: i32) {
    now(|os, gl| {
        if gl.inside_begin() {
            return Err(GlError::InvalidOperation);
        }
        let pack = matches!(
            pname,
            GL_PACK_SWAP_BYTES..=GL_PACK_ALIGNMENT | GL_PACK_SKIP_IMAGES | GL_PACK_IMAGE_HEIGHT
        );
        let unpack = matches!(
            pname,
            GL_UNPACK_SWAP_BYTES..=GL_UNPACK_ALIGNMENT | GL_UNPACK_SKIP_IMAGES | GL_UNPACK_IMAGE_HEIGHT
        );
        let s: &mut PixelStore = match (pack, unpack) {
            (true, _) => &mut os.pack,
            (_, true) => &mut os.unpack,
            _ => return Err(GlError::InvalidEnum),
        };
        let base = if pack { GL_PACK_SWAP_BYTES } else { GL_UNPACK_SWAP_BYTES };
        let field = match pname {
            GL_PACK_SKIP_IMAGES | GL_UNPACK_SKIP_IMAGES => 6,
            GL_PACK_IMAGE_HEIGHT | GL_UNPACK_IMAGE_HEIGHT => 7,
            p => p - base,
        };
        match field {
            0 => s.swap_bytes = param != 0,
            1 => s.lsb_first = param != 0,
            5 if matches!(param, 1 | 2 | 4 | 8) => s.alignment = param,
            5 => return Err(GlError::InvalidValue),
            _ if param < 0 => return Err(GlError::InvalidValue),
            2 => s.row_length = param,
            3 => s.skip_rows = param,
            4 => s.skip_pixels = param,
            6 => s.skip_images = param,
            _ => s.image_height = param,
        }
        Ok(())
    })
}

/// Bytes of one pixel of `format` and `ty` in client memory, and of the
/// element the alignment counts in (a component; the whole pixel for the
/// packed types), checked in Mesa's order (`_mesa_error_check_format_and_type`):
/// a packed type whose components are not the format's is
/// `GL_INVALID_OPERATION`, whatever the format; any other unknown type or
/// format `GL_INVALID_ENUM` (`GL_BITMAP` too: no texture or colour format takes it).
pub(super) fn pixel_size(format: GLenum, ty: GLenum) -> GlResult<(usize, usize)> {
    // GL_DEPTH_STENCIL takes GL_UNSIGNED_INT_24_8 only, checked first (GL 3.0 §4.3.1).
    if format == GL_DEPTH_STENCIL && ty != GL_UNSIGNED_INT_24_8 {
        return Err(GlError::InvalidEnum);
    }
    let packed = match ty {
        GL_UNSIGNED_INT_24_8 => Some((4, [GL_DEPTH_STENCIL, GL_DEPTH_STENCIL])),
        0x8032 | 0x8362 => Some((1, [GL_RGB, GL_RGB])), // UNSIGNED_BYTE_3_3_2, _2_3_3_REV
        0x8363 | 0x8364 => Some((2, [GL_RGB, GL_RGB])), // UNSIGNED_SHORT_5_6_5, _REV
        // UNSIGNED_SHORT_4_4_4_4, _5_5_5_1, _4_4_4_4_REV, _1_5_5_5_REV
        0x8033 | 0x8034 | 0x8365 | 0x8366 => Some((2, [GL_RGBA, GL_BGRA])),
        // UNSIGNED_INT_8_8_8_8, _10_10_10_2, _8_8_8_8_REV, _2_10_10_10_REV
        0x8035 | 0x8036 | 0x8367 | 0x8368 => Some((4, [GL_RGBA, GL_BGRA])),
        _ => None,
    };
    if let Some((bytes, formats)) = packed {
        return if formats.contains(&format) {
            Ok((bytes, bytes))
        } else {
            Err(GlError::InvalidOperation)
        };
    }
    let size = match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        _ => return Err(GlError::InvalidEnum),
    };
    let comps = match format {
        GL_RGBA | GL_BGRA => 4,
        GL_RGB | GL_BGR => 3,
        GL_LUMINANCE_ALPHA => 2,
        GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_LUMINANCE | GL_DEPTH_COMPONENT | GL_COLOR_INDEX
        | GL_STENCIL_INDEX => 1,
        _ => return Err(GlError::InvalidEnum),
    };
    Ok((comps * size, size))
}

/// What `glReadPixels` reads per pixel.
#[derive(Clone, Copy)]
enum Source {
    /// Colour components, as indices into RGBA; `None` is luminance (R+G+B).
    Color(&'static [Option<usize>]),
    Depth,
    Stencil,
    /// `GL_DEPTH_STENCIL` (EXT_packed_depth_stencil): the stored depth and the stencil index.
    DepthStencil,
}

fn source(format: GLenum) -> GlResult<Source> {
    Ok(match format {
        GL_RGBA => Source::Color(&[Some(0), Some(1), Some(2), Some(3)]),
        GL_BGRA => Source::Color(&[Some(2), Some(1), Some(0), Some(3)]),
        GL_RGB => Source::Color(&[Some(0), Some(1), Some(2)]),
        GL_BGR => Source::Color(&[Some(2), Some(1), Some(0)]),
        GL_RED => Source::Color(&[Some(0)]),
        GL_GREEN => Source::Color(&[Some(1)]),
        GL_BLUE => Source::Color(&[Some(2)]),
        GL_ALPHA => Source::Color(&[Some(3)]),
        GL_LUMINANCE => Source::Color(&[None]),
        GL_LUMINANCE_ALPHA => Source::Color(&[None, Some(3)]),
        GL_DEPTH_COMPONENT => Source::Depth,
        GL_STENCIL_INDEX => Source::Stencil,
        GL_DEPTH_STENCIL => Source::DepthStencil,
        // Colour-index reads: no colour-index mode in an RGBA context.
        GL_COLOR_INDEX => return Err(GlError::InvalidOperation),
        _ => return Err(GlError::InvalidEnum),
    })
}

/// Component values in [0, 1] (colour, depth) or raw (stencil) for pixel `(x, y)`;
/// `None` outside the framebuffer, which leaves the caller's bytes untouched.
fn read_pixel(fb: &Framebuffer, src: Source, x: i64, y: i64, out: &mut Vec<f64>) -> Option<()> {
    let (x, y) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
    out.clear();
    match src {
        Source::Color(channels) => {
            // `c * (1/255)` in f32: Mesa's unorm8-to-float, bit for bit; the
            // deep formats' values as floats (a float buffer's unclamped).
            // Mesa 22 clamps reads of its float OSMesa buffer to [0, 1] (its
            // window-system framebuffer counts as fixed-point for
            // GL_CLAMP_READ_COLOR: docs/llvmpipe-facts.md, "Deep colour buffers").
            let p = if fb.color_format().is_deep() {
                fb.pixel_f32(x, y)?
                    .map(|c| f64::from(if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) }))
            } else {
                fb.pixel(x, y)?.map(|c| f64::from(f32::from(c) * (1.0 / 255.0)))
            };
            out.extend(
                channels
                    .iter()
                    .map(|c| c.map_or((p[0] + p[1] + p[2]).min(1.0), |c| p[c])),
            );
        }
        Source::Depth => {
            let max = fb.depth_format()?.max_value();
            out.push(f64::from(fb.depth_at(x, y)?) / f64::from(max));
            // The stored value too, for the integer types' bit replication.
            out.push(f64::from(fb.depth_at(x, y)?));
        }
        Source::Stencil => out.push(f64::from(fb.stencil_at(x, y)?)),
        Source::DepthStencil => {
            out.push(f64::from(fb.depth_at(x, y)?));
            out.push(f64::from(fb.stencil_at(x, y)?));
        }
    }
    Some(())
}

/// `glReadPixels` of `GL_UNSIGNED_BYTE` components (`channels`, none of
/// them luminance) from an 8-bit colour buffer, a row at a time: the bytes
/// as stored, which is what the general path's `c · (1/255)` in f32, then
/// `round(v · 255)`, gives back for every byte (tested). The general path
/// spent 520 instructions a pixel (a MuJoCo frame's 320×240 `GL_RGB` read:
/// 40 M, a tenth of the frame; callgrind); this one about 10. False (and
/// nothing written) for a format it does not read.
fn read_bytes(
    fb: &Framebuffer,
    channels: &[Option<usize>],
    (x, y, w, h): (i32, i32, usize, usize),
    dst: &mut [u8],
    start: usize,
    stride: usize,
) -> bool {
    use softgl::ColorFormat;
    // Where each of R, G, B, A is in a stored pixel (`None`: A of an RGB buffer, 255).
    let (bpp, from): (usize, [Option<usize>; 4]) = match fb.color_format() {
        ColorFormat::Rgba8 => (4, [Some(0), Some(1), Some(2), Some(3)]),
        ColorFormat::Bgra8 => (4, [Some(2), Some(1), Some(0), Some(3)]),
        ColorFormat::Rgb8 => (3, [Some(0), Some(1), Some(2), None]),
        _ => return false,
    };
    let mut at = [None; 4];
    for (a, c) in at.iter_mut().zip(channels) {
        match c.and_then(|c| from.get(c).copied()) {
            Some(f) => *a = f,
            None if c.is_some() => {}
            None => return false,
        }
    }
    let comps = channels.len();
    let at = &at[..comps];
    let (width, height) = (i64::from(fb.width()), i64::from(fb.height()));
    let (x, y) = (i64::from(x), i64::from(y));
    // The columns inside the buffer: the others' bytes are left as they are.
    let (i0, i1) = ((-x).clamp(0, w as i64), (width - x).clamp(0, w as i64));
    if i0 >= i1 {
        return true;
    }
    let (i0, i1) = (i0 as usize, i1 as usize);
    let bytes = fb.color_bytes();
    let same = comps == bpp && at.iter().enumerate().all(|(k, a)| *a == Some(k));
    for j in 0..h {
        let fy = y + j as i64;
        if fy < 0 || fy >= height {
            continue;
        }
        let row = if fb.color_top_down() { height - 1 - fy } else { fy } as usize;
        let first = row * fb.color_stride() + (x + i0 as i64) as usize * bpp;
        let (Some(src), Some(out)) = (
            bytes.get(first..first + (i1 - i0) * bpp),
            dst.get_mut(start + j * stride + i0 * comps..start + j * stride + i1 * comps),
        ) else {
            continue;
        };
        if same {
            out.copy_from_slice(src);
            continue;
        }
        for (o, p) in out.chunks_exact_mut(comps).zip(src.chunks_exact(bpp)) {
            for (o, a) in o.iter_mut().zip(at) {
                *o = a.map_or(255, |a| p[a]);
            }
        }
    }
    true
}

/// `v`, a `from`-bit unsigned value, widened or narrowed to `to` bits by bit
/// replication (Mesa's Z24 to `GL_UNSIGNED_INT`: `z << 8 | z >> 16`).
fn replicate(v: u32, from: u32, to: u32) -> u32 {
    if from >= to {
        return v >> (from - to);
    }
    let mut out = 0u64;
    let mut filled = 0;
    while filled < to {
        out = (out << from) | u64::from(v);
        filled += from;
    }
    (out >> (filled - to)) as u32
}

/// Stores component `v` as `ty` at `dst` (stencil values are stored as integers).
fn put(dst: &mut [u8], ty: GLenum, v: f64, stencil: bool, swap: bool) {
    let mut bytes = [0u8; 4];
    let n = match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => {
            bytes[0] = if stencil {
                v as u8
            } else if ty == GL_BYTE {
                (v * 127.0).round() as i8 as u8
            } else {
                (v * 255.0).round() as u8
            };
            1
        }
        GL_UNSIGNED_SHORT | GL_SHORT => {
            let x = if stencil {
                v as u16
            } else if ty == GL_SHORT {
                (v * 32767.0).round() as i16 as u16
            } else {
                (v * 65535.0).round() as u16
            };
            bytes[..2].copy_from_slice(&x.to_ne_bytes());
            2
        }
        GL_UNSIGNED_INT | GL_INT => {
            let x = if stencil {
                v as u32
            } else if ty == GL_INT {
                (v * 2147483647.0).round() as i32 as u32
            } else {
                (v * 4294967295.0).round() as u32
            };
            bytes.copy_from_slice(&x.to_ne_bytes());
            4
        }
        _ => {
            bytes.copy_from_slice(&(v as f32).to_ne_bytes());
            4
        }
    };
    if swap {
        bytes[..n].reverse();
    }
    dst[..n].copy_from_slice(&bytes[..n]);
}

/// `glReadPixels`, with the pack alignment, row length and skips honoured.
///
/// # Safety
/// `pixels` has room for the image as the pack state lays it out.
unsafe fn read_pixels(
    gl: &mut Context,
    pack: &PixelStore,
    (x, y, w, h): (i32, i32, i32, i32),
    format: GLenum,
    ty: GLenum,
    pixels: *mut c_void,
) -> GlResult {
    // GL_DEPTH_STENCIL takes GL_UNSIGNED_INT_24_8 only (INVALID_ENUM, checked
    // first), which no other format takes (INVALID_OPERATION): GL 3.0 §4.3.1.
    if format == GL_DEPTH_STENCIL && ty != GL_UNSIGNED_INT_24_8 {
        return Err(GlError::InvalidEnum);
    }
    let src = source(format)?;
    let size: usize = match ty {
        GL_UNSIGNED_INT_24_8 if format == GL_DEPTH_STENCIL => 4,
        GL_UNSIGNED_INT_24_8 => return Err(GlError::InvalidOperation),
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        // Packed and bitmap types exist in GL 1.2 and 1.0 but not in softgl yet.
        0x1A00 | 0x8032..=0x8036 | 0x8362..=0x8368 => return Err(GlError::InvalidOperation),
        _ => return Err(GlError::InvalidEnum),
    };
    if w < 0 || h < 0 {
        return Err(GlError::InvalidValue);
    }
    if gl.inside_begin() {
        return Err(GlError::InvalidOperation);
    }
    let view = gl.read_framebuffer(matches!(src, Source::Color(_)))?;
    let fb = gl.read_view(&view);
    match src {
        Source::Depth if fb.depth_format().is_none() => return Err(GlError::InvalidOperation),
        Source::Stencil if !fb.has_stencil() => return Err(GlError::InvalidOperation),
        Source::DepthStencil if fb.depth_format().is_none() || !fb.has_stencil() => {
            return Err(GlError::InvalidOperation)
        }
        _ => {}
    }
    if w == 0 || h == 0 {
        return Ok(());
    }
    if pixels.is_null() {
        return Err(GlError::InvalidValue);
    }
    let comps = match src {
        Source::Color(c) => c.len(),
        Source::Depth | Source::Stencil | Source::DepthStencil => 1,
    };
    let pixel_bytes = comps * size;
    // The layout of a format with as many components (stencil: one).
    let like = decode::<PixelFormat>(format).unwrap_or(PixelFormat::Red);
    let like_ty = decode::<PixelType>(ty)?;
    let (w, h) = (w as usize, h as usize);
    let ClientLayout {
        row_stride: stride,
        start,
        len,
        ..
    } = ClientLayout::new(like, like_ty, pack, 2, [w, h, 1]).ok_or(GlError::InvalidValue)?;
    // SAFETY: GL's contract: `pixels` holds the image as the pack state lays it out,
    // which is exactly `len` bytes from `pixels`.
    let dst = unsafe { std::slice::from_raw_parts_mut(pixels.cast::<u8>(), len) };
    if let Source::Color(channels) = src {
        if ty == GL_UNSIGNED_BYTE && read_bytes(fb, channels, (x, y, w, h), dst, start, stride) {
            return Ok(());
        }
    }
    let stencil = matches!(src, Source::Stencil);
    let float_src = matches!(src, Source::Color(_)) && fb.color_format() == softgl::ColorFormat::Rgba32F;
    let depth_bits = fb.depth_format().map_or(0, |f| f.max_value().count_ones());
    let mut vals = Vec::with_capacity(4);
    for j in 0..h {
        for i in 0..w {
            if read_pixel(fb, src, i64::from(x) + i as i64, i64::from(y) + j as i64, &mut vals).is_none() {
                continue;
            }
            let at = start + j * stride + i * pixel_bytes;
            if let Source::DepthStencil = src {
                // Z24 in the top 24 bits, the stencil index in the low 8.
                let z = replicate(vals[0] as u32, depth_bits, 24);
                let v = (z << 8) | (vals[1] as u32 & 0xff);
                put(&mut dst[at..], GL_UNSIGNED_INT, f64::from(v), true, pack.swap_bytes);
                continue;
            }
            if let (Source::Depth, GL_UNSIGNED_INT | GL_UNSIGNED_SHORT) = (src, ty) {
                let raw = replicate(vals[1] as u32, depth_bits, 8 * size as u32);
                put(&mut dst[at..], ty, f64::from(raw), true, pack.swap_bytes);
                continue;
            }
            for (k, &v) in vals.iter().take(comps).enumerate() {
                if float_src && matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT) {
                    // Mesa's `_mesa_float_to_unorm`: f32 product, rounded half to even.
                    let max = if ty == GL_UNSIGNED_BYTE { 255.0f32 } else { 65535.0 };
                    let v = v as f32;
                    let raw = if v < 0.0 {
                        0.0
                    } else if v > 1.0 {
                        max
                    } else {
                        (v * max).round_ties_even()
                    };
                    put(&mut dst[at + k * size..], ty, f64::from(raw), true, pack.swap_bytes);
                    continue;
                }
                put(&mut dst[at + k * size..], ty, v, stencil, pack.swap_bytes);
            }
        }
    }
    Ok(())
}

exports! {
    [] fn glPixelStorei(pname: GLenum, param: i32) {
        pixel_store(pname, param)
    }
    [] fn glPixelStoref(pname: GLenum, param: f32) {
        pixel_store(pname, param.round() as i32)
    }
    /// # Safety
    /// `pixels` has room for the image as the pack state lays it out.
    [unsafe] fn glReadPixels(x: i32, y: i32, width: i32, height: i32, format: GLenum, ty: GLenum, pixels: *mut c_void) {
        now(|os, gl| {
            let pack = os.pack;
            // SAFETY: GL's contract on `pixels`, passed on.
            unsafe { read_pixels(gl, &pack, (x, y, width, height), format, ty, pixels) }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stored_bytes_are_what_the_general_path_reads() {
        for c in 0..=255u8 {
            let v = f64::from(f32::from(c) * (1.0 / 255.0));
            let mut out = [0u8; 1];
            put(&mut out, GL_UNSIGNED_BYTE, v, false, false);
            assert_eq!(out[0], c);
        }
    }

    #[test]
    fn pixel_sizes_and_mesas_error_order() {
        assert_eq!(pixel_size(GL_RGBA, GL_UNSIGNED_BYTE), Ok((4, 1)));
        assert_eq!(pixel_size(GL_BGR, GL_SHORT), Ok((6, 2)));
        assert_eq!(pixel_size(GL_LUMINANCE_ALPHA, GL_FLOAT), Ok((8, 4)));
        assert_eq!(pixel_size(GL_RGB, GL_UNSIGNED_SHORT_5_6_5), Ok((2, 2)));
        assert_eq!(pixel_size(GL_BGRA, 0x8367), Ok((4, 4)));
        assert_eq!(pixel_size(GL_RGB, 0x8032), Ok((1, 1)));
        // A packed type with the wrong components, even an unknown format.
        assert_eq!(
            pixel_size(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5),
            Err(GlError::InvalidOperation)
        );
        assert_eq!(pixel_size(0x1234, 0x8033), Err(GlError::InvalidOperation));
        assert_eq!(pixel_size(GL_RGBA, 0x1A00), Err(GlError::InvalidEnum)); // GL_BITMAP
        assert_eq!(pixel_size(GL_RGBA, GL_DOUBLE), Err(GlError::InvalidEnum));
        assert_eq!(pixel_size(0x8049, GL_UNSIGNED_BYTE), Err(GlError::InvalidEnum));
        // GL_INTENSITY
    }
}
