//! `glPixelStore` and `glReadPixels`.

use super::enums::decode;
use super::now;
use crate::consts::*;
use crate::gl_state::PixelStore;
use softgl::pixel_transfer::PixelState;
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
    if format == GL_DEPTH_STENCIL && !matches!(ty, GL_UNSIGNED_INT_24_8 | GL_FLOAT_32_UNSIGNED_INT_24_8_REV) {
        return Err(GlError::InvalidEnum);
    }
    if ty == GL_FLOAT_32_UNSIGNED_INT_24_8_REV {
        // Two 4-byte elements: the depth float and the stencil word.
        return if format == GL_DEPTH_STENCIL {
            Ok((8, 4))
        } else {
            Err(GlError::InvalidOperation)
        };
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
/// `clamp`: a deep colour buffer's values are clamped to [0, 1]
/// (`GL_CLAMP_READ_COLOR`'s `GL_FIXED_ONLY` for a fixed-point framebuffer).
///
/// `transfer`: the pixel transfer operations, when not the identity (GL 1.5
/// §4.3.2, as Mesa's `read_rgba_pixels` and `_mesa_pack_depth_span` /
/// `_mesa_pack_stencil_span` apply them): colours as f32 through scale,
/// bias and maps, clamped, before the luminance sum; depth scaled, biased
/// and clamped; stencil indices shifted, offset and mapped.
fn read_pixel(
    fb: &Framebuffer,
    (src, clamp): (Source, bool),
    (x, y): (i64, i64),
    transfer: Option<&PixelState>,
    out: &mut Vec<f64>,
) -> Option<()> {
    let (x, y) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
    out.clear();
    match src {
        Source::Color(channels) => {
            // `c * (1/255)` in f32: Mesa's unorm8-to-float, bit for bit; the
            // deep formats' values as floats (a float buffer's unclamped).
            // Mesa 22 clamps reads of its float OSMesa buffer to [0, 1] (its
            // window-system framebuffer counts as fixed-point for
            // GL_CLAMP_READ_COLOR: docs/llvmpipe-facts.md, "Deep colour buffers").
            // A float framebuffer object is read unclamped (§41).
            let p = if fb.color_format().is_deep() {
                fb.pixel_f32(x, y)?.map(|c| {
                    f64::from(match clamp {
                        true if c.is_nan() => 0.0,
                        true => c.clamp(0.0, 1.0),
                        false => c,
                    })
                })
            } else {
                fb.pixel(x, y)?.map(|c| f64::from(f32::from(c) * (1.0 / 255.0)))
            };
            let p = match transfer {
                Some(t) => t.cpu_colour(p.map(|c| c as f32)).map(f64::from),
                None => p,
            };
            let luminance = |p: [f64; 4]| {
                let l = p[0] + p[1] + p[2];
                if clamp {
                    l.min(1.0)
                } else {
                    l
                }
            };
            out.extend(channels.iter().map(|c| c.map_or(luminance(p), |c| p[c])));
        }
        Source::Depth if fb.depth_format()? == softgl::DepthFormat::D32F => {
            // The stored float, and as Mesa's `z32_float_to_z32_unorm` the
            // 32-bit value the integer types narrow (`u_format_zs.c`).
            let z = f64::from(f32::from_bits(fb.depth_at(x, y)?));
            match transfer {
                Some(t) => out.extend([f64::from(t.depth(z as f32)), -1.0]),
                None => out.extend([z, f64::from((z * 4_294_967_295.0) as u32)]),
            }
        }
        Source::Depth => {
            let max = fb.depth_format()?.max_value();
            let d = f64::from(fb.depth_at(x, y)?) / f64::from(max);
            match transfer {
                Some(t) => {
                    let d = t.depth(d as f32);
                    out.push(f64::from(d));
                    // The integer types then take it as a float (not bit-replicated).
                    out.push(-1.0);
                }
                None => {
                    out.push(d);
                    // The stored value too, for the integer types' bit replication.
                    out.push(f64::from(fb.depth_at(x, y)?));
                }
            }
        }
        Source::Stencil => {
            let s = i64::from(fb.stencil_at(x, y)?);
            out.push(transfer.map_or(s, |t| t.stencil(s)) as f64);
        }
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
    let rgb_of_rgba = bpp == 4 && at == [Some(0), Some(1), Some(2)];
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
        if rgb_of_rgba {
            // MuJoCo's read (`GL_RGB` of RGBA8): ~20 instructions a pixel
            // through the general loop below, 1.6 M a 320×240 frame.
            for (o, p) in out.as_chunks_mut::<3>().0.iter_mut().zip(src.as_chunks::<4>().0) {
                *o = [p[0], p[1], p[2]];
            }
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

/// `glReadPixels` of depth as `GL_FLOAT` row by row, when the rectangle is
/// inside the framebuffer (`z / max` in f64, as the general path; float
/// depth as stored). `false` when not taken. (Colour bytes: [`read_bytes`].)
#[allow(clippy::too_many_arguments)]
fn read_depth_rows(
    fb: &Framebuffer,
    src: Source,
    (x, y, w, h): (i32, i32, usize, usize),
    ty: GLenum,
    pack: &PixelStore,
    dst: &mut [u8],
    start: usize,
    stride: usize,
) -> bool {
    let (Ok(x0), Ok(y0)) = (u32::try_from(x), u32::try_from(y)) else {
        return false;
    };
    let (Ok(wu), Ok(hu)) = (u32::try_from(w), u32::try_from(h)) else {
        return false;
    };
    let (Some(x1), Some(y1)) = (x0.checked_add(wu), y0.checked_add(hu)) else {
        return false;
    };
    if x1 > fb.width() || y1 > fb.height() || pack.swap_bytes {
        return false;
    }
    match (src, ty) {
        (Source::Depth, GL_FLOAT) => {
            let (Some(d), Some(format)) = (fb.depth_buffer(), fb.depth_format()) else {
                return false;
            };
            let max = f64::from(format.max_value());
            let width = fb.width() as usize;
            for j in 0..h {
                let Some(row) = dst.get_mut(start + j * stride..start + j * stride + w * 4) else {
                    return false;
                };
                let from = (y0 as usize + j) * width + x0 as usize;
                let mut put_row = |z: &mut dyn Iterator<Item = u32>| {
                    for (o, z) in row.chunks_exact_mut(4).zip(z) {
                        o.copy_from_slice(&((f64::from(z) / max) as f32).to_ne_bytes());
                    }
                };
                match d {
                    softgl::framebuffer::DepthBuffer::D32F(v) => {
                        // The stored floats as they are (the general path's f32 → f64 → f32).
                        for (o, &z) in row.chunks_exact_mut(4).zip(&v[from..from + w]) {
                            o.copy_from_slice(&f32::from_bits(z).to_ne_bytes());
                        }
                    }
                    softgl::framebuffer::DepthBuffer::D16(v) => {
                        put_row(&mut v[from..from + w].iter().map(|&z| u32::from(z)))
                    }
                    softgl::framebuffer::DepthBuffer::D24(v) | softgl::framebuffer::DepthBuffer::D32(v) => {
                        put_row(&mut v[from..from + w].iter().copied())
                    }
                }
            }
            true
        }
        _ => false,
    }
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
    // GL_FLOAT_32_UNSIGNED_INT_24_8_REV (ARB_depth_buffer_float) likewise.
    if format == GL_DEPTH_STENCIL && !matches!(ty, GL_UNSIGNED_INT_24_8 | GL_FLOAT_32_UNSIGNED_INT_24_8_REV) {
        return Err(GlError::InvalidEnum);
    }
    let src = source(format)?;
    let size: usize = match ty {
        GL_UNSIGNED_INT_24_8 if format == GL_DEPTH_STENCIL => 4,
        GL_FLOAT_32_UNSIGNED_INT_24_8_REV if format == GL_DEPTH_STENCIL => 8,
        GL_UNSIGNED_INT_24_8 | GL_FLOAT_32_UNSIGNED_INT_24_8_REV => return Err(GlError::InvalidOperation),
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        // GL_BITMAP: colour-index and stencil reads only (GL 1.5 §4.3.2).
        0x1A00 => return Err(GlError::InvalidOperation),
        // Packed colour types (GL 1.2): the format must have their components.
        0x8032..=0x8036 | 0x8362..=0x8368 if matches!(src, Source::Color(_)) => pixel_size(format, ty)?.0,
        0x8032..=0x8036 | 0x8362..=0x8368 => return Err(GlError::InvalidOperation),
        _ => return Err(GlError::InvalidEnum),
    };
    let packed = packed_fields(ty);
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
    let pixel_bytes = if packed.is_some() { size } else { comps * size };
    // The layout of a format with as many components (stencil: one).
    // (Float depth and stencil: eight bytes, aligned as two `GL_UNSIGNED_INT`s.)
    let (like, like_ty) = match ty {
        GL_FLOAT_32_UNSIGNED_INT_24_8_REV => (PixelFormat::LuminanceAlpha, PixelType::UnsignedInt),
        _ => (
            decode::<PixelFormat>(format).unwrap_or(PixelFormat::Red),
            decode::<PixelType>(ty)?,
        ),
    };
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
    // Without pixel transfer operations (they take the general path).
    if gl.pixel_state().is_identity() {
        if let Source::Color(channels) = src {
            if ty == GL_UNSIGNED_BYTE && read_bytes(fb, channels, (x, y, w, h), dst, start, stride) {
                return Ok(());
            }
        }
        if read_depth_rows(fb, src, (x, y, w, h), ty, pack, dst, start, stride) {
            return Ok(());
        }
    }
    let stencil = matches!(src, Source::Stencil);
    let float_src = matches!(src, Source::Color(_)) && fb.color_format().is_float();
    let depth_format = fb.depth_format();
    let depth_bits = depth_format.map_or(0, |f| f.bits());
    let float_depth = depth_format == Some(softgl::DepthFormat::D32F);
    // Mesa's `_AllColorBuffersFixedPoint`: its OSMesa buffer counts as
    // fixed-point whatever its type, a float object does not.
    let clamp = !(float_src && gl.fbo_state().read_binding() != 0);
    // Checked once: the identity reads as before.
    let transfer = Some(gl.pixel_state()).filter(|t| !t.is_identity());
    let mut vals = Vec::with_capacity(4);
    for j in 0..h {
        for i in 0..w {
            let at = (i64::from(x) + i as i64, i64::from(y) + j as i64);
            if read_pixel(fb, (src, clamp), at, transfer, &mut vals).is_none() {
                continue;
            }
            let at = start + j * stride + i * pixel_bytes;
            if let (Source::DepthStencil, GL_FLOAT_32_UNSIGNED_INT_24_8_REV) = (src, ty) {
                // The depth as f32, then a word with the stencil index in its low 8 bits
                // (Mesa's `struct z32f_x24s8`; unorm depth through f64, `u_format_zs.c`).
                let z = match depth_format {
                    Some(softgl::DepthFormat::D32F) => f32::from_bits(vals[0] as u32),
                    f => (vals[0] * (1.0 / f64::from(f.map_or(1, |f| f.max_value())))) as f32,
                };
                put(&mut dst[at..], GL_FLOAT, f64::from(z), false, pack.swap_bytes);
                put(&mut dst[at + 4..], GL_UNSIGNED_INT, vals[1], true, pack.swap_bytes);
                continue;
            }
            if let Some((fields, rev)) = packed {
                let word = pack_color(&vals, fields, rev, !fb.color_format().is_deep());
                // The packed unit in native byte order (swapped with GL_PACK_SWAP_BYTES).
                let mut out = [0u8; 4];
                match size {
                    1 => out[0] = word as u8,
                    2 => out[..2].copy_from_slice(&(word as u16).to_ne_bytes()),
                    _ => out = word.to_ne_bytes(),
                }
                if pack.swap_bytes {
                    out[..size].reverse();
                }
                dst[at..at + size].copy_from_slice(&out[..size]);
                continue;
            }
            if let Source::DepthStencil = src {
                // Z24 in the top 24 bits, the stencil index in the low 8
                // (from float depth: `(uint32_t)(z · 0xffffff)`, u_format_zs.c).
                let z = if float_depth {
                    (f64::from(f32::from_bits(vals[0] as u32)) * 16_777_215.0) as u32 & 0xff_ffff
                } else {
                    replicate(vals[0] as u32, depth_bits, 24)
                };
                let v = (z << 8) | (vals[1] as u32 & 0xff);
                put(&mut dst[at..], GL_UNSIGNED_INT, f64::from(v), true, pack.swap_bytes);
                continue;
            }
            let replicated = matches!(src, Source::Depth) && vals[1] >= 0.0;
            if let (Source::Depth, GL_UNSIGNED_INT | GL_UNSIGNED_SHORT, true) = (src, ty, replicated) {
                if float_depth && ty == GL_UNSIGNED_SHORT {
                    // Float depth to a short: the general float path (Mesa's `_mesa_pack_depth_span`).
                    put(&mut dst[at..], ty, vals[0], false, pack.swap_bytes);
                    continue;
                }
                let raw = replicate(vals[1] as u32, depth_bits, 8 * size as u32);
                put(&mut dst[at..], ty, f64::from(raw), true, pack.swap_bytes);
                continue;
            }
            for (k, &v) in vals.iter().take(comps).enumerate() {
                if stencil && transfer.is_some() {
                    // Mesa packs the index's low bits (`_mesa_pack_stencil_span`).
                    let bits = 8 * size as u32;
                    let v = (v as i64 & ((1i64 << bits) - 1)) as f64;
                    put(&mut dst[at + k * size..], ty, v, true, pack.swap_bytes);
                    continue;
                }
                if (float_src || transfer.is_some()) && matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT) {
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

/// The bit widths of a packed type's components, in the format's order, and
/// whether the first sits in the lowest bits (`_REV`) rather than the highest
/// (GL 1.5 §3.6.4, table 3.8); `None` for other types.
fn packed_fields(ty: GLenum) -> Option<(&'static [u32], bool)> {
    Some(match ty {
        0x8032 => (&[3, 3, 2], false),       // UNSIGNED_BYTE_3_3_2
        0x8362 => (&[3, 3, 2], true),        // UNSIGNED_BYTE_2_3_3_REV
        0x8363 => (&[5, 6, 5], false),       // UNSIGNED_SHORT_5_6_5
        0x8364 => (&[5, 6, 5], true),        // UNSIGNED_SHORT_5_6_5_REV
        0x8033 => (&[4, 4, 4, 4], false),    // UNSIGNED_SHORT_4_4_4_4
        0x8365 => (&[4, 4, 4, 4], true),     // UNSIGNED_SHORT_4_4_4_4_REV
        0x8034 => (&[5, 5, 5, 1], false),    // UNSIGNED_SHORT_5_5_5_1
        0x8366 => (&[5, 5, 5, 1], true),     // UNSIGNED_SHORT_1_5_5_5_REV
        0x8035 => (&[8, 8, 8, 8], false),    // UNSIGNED_INT_8_8_8_8
        0x8367 => (&[8, 8, 8, 8], true),     // UNSIGNED_INT_8_8_8_8_REV
        0x8036 => (&[10, 10, 10, 2], false), // UNSIGNED_INT_10_10_10_2
        0x8368 => (&[10, 10, 10, 2], true),  // UNSIGNED_INT_2_10_10_10_REV
        _ => return None,
    })
}

/// Components `vals` (in `[0, 1]`, the format's order) packed into `fields`,
/// as Mesa converts a read: from an 8-bit buffer, `(x · max + 127) / 255` of
/// the byte `x` for fields of 8 bits or fewer (`_mesa_unorm_to_unorm`), and
/// for wider ones the float `x · (1/255)` rounded to even (`_mesa_float_to_unorm`,
/// the float path of `_mesa_format_convert`); from a deep buffer, the float rounded.
fn pack_color(vals: &[f64], fields: &[u32], rev: bool, eight_bit: bool) -> u32 {
    let total: u32 = fields.iter().sum();
    let mut word = 0u32;
    let mut low = 0u32;
    for (k, &width) in fields.iter().enumerate() {
        let max = (1u32 << width) - 1;
        let v = vals.get(k).copied().unwrap_or(1.0);
        let f = v as f32;
        let c = if eight_bit {
            let x = (v * 255.0).round() as u32;
            if width <= 8 {
                (x * max + 127) / 255
            } else {
                (x as f32 * (1.0f32 / 255.0) * max as f32).round_ties_even() as u32
            }
        } else {
            (f.clamp(0.0, 1.0) * max as f32).round_ties_even() as u32
        };
        let shift = if rev { low } else { total - low - width };
        word |= c.min(max) << shift;
        low += width;
    }
    word
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
