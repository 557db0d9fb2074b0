//! Texturing: texture objects, images and their parameters, the active
//! unit and the `glGet` values of textures (GL 1.0–1.4 and the `ARB`/`EXT`
//! names programs and GLU look up); the units' environment, coordinate
//! generation and multitexture coordinates are in `texunit.rs`.
//!
//! The client's pixels are sized before they are read: `format`, `type` and
//! the unpack state (alignment, row length, skips, image height) give the
//! bytes from the pointer to the image's last pixel (softgl's
//! [`ClientLayout`]), and only those are handed to softgl as [`PixelData`].
//! Compiled into a display list, an upload copies them at once, with the
//! unpack state of that moment (GL 1.5 §5.4); proxy uploads are never
//! compiled. Errors are checked in Mesa's order where this layer sees them
//! first (target, level, border, sizes, format and type, internal format),
//! the rest by softgl. Colour indices become (0, 0, 0, 0) through GL's
//! default pixel maps, as in Mesa.

use super::enums::decode;
use super::get::Val;
use super::immediate::Norm;
use super::pixels::pixel_size;
use super::{checked, now, outside, run_or_record};
use crate::consts::*;
use crate::gl_state::{Cmd, GlState, MAX_UNITS};
use crate::state::with_gl;
use softgl::texture::api::{check_format_type, MAX_3D_TEXTURE_SIZE, MAX_RECTANGLE_TEXTURE_SIZE, MAX_TEXTURE_SIZE};
use softgl::texture::index::{index_image_bytes, index_image_rgba8, IndexType};
use softgl::texture::unpack::ClientLayout;
use softgl::texture::{
    min_filter_from_gl, min_filter_to_gl, DepthMode, InternalFormat, MipFilter, PixelData, PixelFormat, PixelStore,
    PixelType, TexImageTarget, TexLevelParamName, TexParam, TexParamName, TextureTarget,
};
use softgl::{CompareFunc, Context, GlEnum, GlError, GlResult};
use std::ffi::c_void;
use std::sync::Arc;

/// `GL_MAX_TEXTURE_SIZE` and `GL_MAX_CUBE_MAP_TEXTURE_SIZE`: the largest
/// level 0 softgl keeps (Mesa's llvmpipe reports 16384).
pub const MAX_SIZE: i32 = MAX_TEXTURE_SIZE as i32;
/// `GL_MAX_3D_TEXTURE_SIZE`.
pub const MAX_3D_SIZE: i32 = MAX_3D_TEXTURE_SIZE as i32;

const GL_COMPARE_R_TO_TEXTURE: GLenum = 0x884E;
const GL_TEXTURE_COMPRESSED_IMAGE_SIZE: GLenum = 0x86A0;
const GL_TEXTURE_BORDER_COLOR: GLenum = 0x1004;

// ----- enumerants -----

/// The target of `glBindTexture`, `glTexParameter`, `glGenerateMipmap`.
pub(super) fn target(t: GLenum) -> GlResult<TextureTarget> {
    decode(t)
}

/// Which image targets a call takes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Takes {
    /// `glTexImage`, `glGetTexLevelParameter`: the proxies too.
    WithProxies,
    /// `glTexSubImage`, `glCopyTex*`, `glGetTexImage`.
    Images,
}

/// The image target `t` of a `dims`-dimensional call (`None`: any, as
/// `glGetTexImage` and `glGetTexLevelParameter` take).
fn image_target(t: GLenum, dims: Option<u32>, takes: Takes) -> GlResult<TexImageTarget> {
    let target = TexImageTarget::from_gl(t).ok_or(GlError::InvalidEnum)?;
    let proxy = matches!(target, TexImageTarget::Proxy(_));
    if dims.is_some_and(|n| n != target.dims()) || (proxy && takes == Takes::Images) {
        return Err(GlError::InvalidEnum);
    }
    Ok(target)
}

/// An internal format argument (GLint in C: 1–4 or an enumerant): an
/// unknown one is `GL_INVALID_VALUE` (GL 1.5 §3.8.1, as Mesa).
fn internal_format(v: i32) -> GlResult<InternalFormat> {
    InternalFormat::from_gl(v as u32).ok_or(GlError::InvalidValue)
}

// ----- texture parameters -----

/// A parameter's values as `glTexParameter*` and `glGetTexParameter*` carry
/// them: enumerants, numbers (truncated to integers), numbers rounded to
/// integers, or a colour (normalized as integers).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Value {
    Enum(GLenum),
    Num(f64),
    Rounded(f64),
    Color([f32; 4]),
}

/// How many values `pname` has (1 for unknown names: the call then fails on the name).
fn param_count(pname: GLenum) -> usize {
    if pname == GL_TEXTURE_BORDER_COLOR {
        4
    } else {
        1
    }
}

/// Four values as a colour: integers (`ints`) normalized as GL 1.x says.
pub(super) fn color(v: &[f64], ints: bool) -> [f32; 4] {
    std::array::from_fn(|k| if ints { (v[k] as i32).norm() } else { v[k] as f32 })
}

/// The parameter `pname` set to `v` (`v[0]` alone but for the border colour).
fn tex_param(pname: GLenum, v: &[f64], ints: bool) -> GlResult<TexParam> {
    let e = v[0] as i64 as GLenum;
    let x = v[0] as f32;
    Ok(match decode::<TexParamName>(pname)? {
        TexParamName::MinFilter => {
            let (f, mip) = min_filter_from_gl(e).ok_or(GlError::InvalidEnum)?;
            TexParam::MinFilter(f, mip)
        }
        TexParamName::MagFilter => TexParam::MagFilter(decode(e)?),
        TexParamName::WrapS => TexParam::WrapS(decode(e)?),
        TexParamName::WrapT => TexParam::WrapT(decode(e)?),
        TexParamName::WrapR => TexParam::WrapR(decode(e)?),
        TexParamName::BorderColor => TexParam::BorderColor(color(v, ints)),
        TexParamName::MinLod => TexParam::MinLod(x),
        TexParamName::MaxLod => TexParam::MaxLod(x),
        TexParamName::BaseLevel => TexParam::BaseLevel(v[0] as i32),
        TexParamName::MaxLevel => TexParam::MaxLevel(v[0] as i32),
        TexParamName::LodBias => TexParam::LodBias(x),
        TexParamName::Priority => TexParam::Priority(x),
        TexParamName::GenerateMipmap => TexParam::GenerateMipmap(v[0] != 0.0),
        TexParamName::CompareMode => TexParam::CompareMode(match e {
            GL_NONE => false,
            GL_COMPARE_R_TO_TEXTURE => true,
            _ => return Err(GlError::InvalidEnum),
        }),
        TexParamName::CompareFunc => TexParam::CompareFunc(decode::<CompareFunc>(e)?),
        TexParamName::DepthMode => TexParam::DepthMode(decode::<DepthMode>(e)?),
        // Read-only.
        TexParamName::Resident => return Err(GlError::InvalidEnum),
    })
}

/// A parameter's value as the queries return it.
fn param_value(p: TexParam) -> Value {
    match p {
        TexParam::MinFilter(f, mip) => Value::Enum(min_filter_to_gl(f, mip)),
        TexParam::MagFilter(f) => Value::Enum(min_filter_to_gl(f, MipFilter::None)),
        TexParam::WrapS(w) | TexParam::WrapT(w) | TexParam::WrapR(w) => Value::Enum(w.to_gl()),
        TexParam::BorderColor(c) => Value::Color(c),
        // Mesa: `lroundf`, clamped to the integers (texparam.c `LCLAMPF`).
        TexParam::MinLod(x) | TexParam::MaxLod(x) | TexParam::LodBias(x) => Value::Rounded(f64::from(x)),
        // Mesa's FLOAT_TO_INT for the integer query of the priority.
        TexParam::Priority(x) => Value::Color([x; 4]),
        TexParam::BaseLevel(l) | TexParam::MaxLevel(l) => Value::Num(f64::from(l)),
        TexParam::GenerateMipmap(b) | TexParam::Resident(b) => Value::Enum(u32::from(b)),
        TexParam::CompareMode(on) => Value::Enum(if on { GL_COMPARE_R_TO_TEXTURE } else { GL_NONE }),
        TexParam::CompareFunc(f) => Value::Enum(f.to_gl()),
        TexParam::DepthMode(m) => Value::Enum(m.to_gl()),
    }
}

/// Records `glTexParameter` with values `v`.
fn tex_parameter(target_enum: GLenum, pname: GLenum, v: [f64; 4], ints: bool) {
    checked(move |gl| {
        outside(gl)?;
        let t = target(target_enum)?;
        gl.tex_parameter(t, tex_param(pname, &v, ints)?)
    })
}

/// Reads `glTexParameter*v`'s values through `p` (as many as `pname` takes).
///
/// # Safety
/// `p` is null or holds the values `pname` takes.
unsafe fn tex_parameter_v<T: Copy + Into<f64>>(target: GLenum, pname: GLenum, p: *const T, ints: bool) {
    // SAFETY: passed on.
    unsafe { with_values(p, param_count(pname), |v| tex_parameter(target, pname, v, ints)) }
}

/// Reads up to 4 values through `p` into doubles and hands them to `f`; a
/// null pointer is `GL_INVALID_VALUE` (recorded as `f`'s call would be).
///
/// # Safety
/// `p` is null or points to `n` readable values.
pub(super) unsafe fn with_values<T: Copy + Into<f64>>(p: *const T, n: usize, f: impl FnOnce([f64; 4])) {
    if p.is_null() {
        return checked(|_| Err(GlError::InvalidValue));
    }
    let mut v = [0.0; 4];
    for (k, out) in v.iter_mut().enumerate().take(n.min(4)) {
        // SAFETY: `n` readable values (the caller's contract).
        *out = unsafe { p.add(k).read_unaligned() }.into();
    }
    f(v)
}

/// The values of a query, converted to the caller's type and written.
///
/// # Safety
/// `out` is null or has room for the values.
pub(super) unsafe fn write<T: Copy>(out: *mut T, v: &[T]) {
    if !out.is_null() {
        // SAFETY: room for every value, by GL's contract.
        unsafe { std::ptr::copy_nonoverlapping(v.as_ptr(), out, v.len()) };
    }
}

/// A value as floats.
pub(super) fn floats(v: Value) -> Vec<f32> {
    match v {
        Value::Enum(e) => vec![e as f32],
        Value::Num(x) | Value::Rounded(x) => vec![x as f32],
        Value::Color(c) => c.to_vec(),
    }
}

/// A value as integers: colours by Mesa's `FLOAT_TO_INT`, numbers truncated
/// (Mesa's `(GLint)` casts) or rounded half away from zero (`lroundf`),
/// saturating.
pub(super) fn ints(v: Value) -> Vec<i32> {
    match v {
        Value::Enum(e) => vec![e as i32],
        Value::Num(x) => vec![x as i32],
        Value::Rounded(x) => vec![x.round() as i32],
        Value::Color(c) => c.iter().map(|&x| (2147483647.0 * f64::from(x)) as i32).collect(),
    }
}

/// `glGetTexParameter*v`: `conv` turns the value into the caller's values.
fn get_tex_parameter<T: Copy>(target_enum: GLenum, pname: GLenum, out: *mut T, conv: fn(Value) -> Vec<T>) {
    now(|_, gl| {
        outside(gl)?;
        let t = target(target_enum)?;
        let value = param_value(gl.get_tex_parameter(t, decode(pname)?)?);
        // SAFETY: room for the parameter's values (GL's contract).
        unsafe { write(out, &conv(value)) };
        Ok(())
    })
}

/// `glGetTexLevelParameter*v`.
fn get_level_parameter(target: GLenum, level: i32, pname: GLenum) -> GlResult<i32> {
    with_gl(Err(GlError::InvalidOperation), |_, gl| {
        let r = outside(gl)
            .and_then(|()| image_target(target, None, Takes::WithProxies))
            .and_then(|t| {
                if level < 0 {
                    return Err(GlError::InvalidValue);
                }
                // No compressed format exists in softgl: no image has a compressed size.
                if pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE {
                    return Err(GlError::InvalidOperation);
                }
                gl.get_tex_level_parameter(t, level, decode(pname)?)
            });
        if let Err(e) = r {
            gl.record_error(e);
        }
        r
    })
}

// ----- images -----

/// The client pixels of an upload or a read, checked and sized.
#[derive(Clone, Copy, Debug)]
struct Client {
    format: PixelFormat,
    ty: PixelType,
    /// Bytes from the pointer to the end of the image's last pixel.
    len: usize,
    /// Colour indices (`GL_COLOR_INDEX`) of this type, which the `I_TO_*`
    /// pixel maps turn into RGBA8 (`softgl::texture::index`): `format` and
    /// `ty` then describe that RGBA8 image, handed to softgl tight.
    index: Option<IndexType>,
}

/// Checks `format` and `ty` and sizes the `dims`-dimensional image `size`
/// under `store`. Stencil indices are no texture's: `GL_INVALID_OPERATION`
/// (Mesa's "incompatible format"); colour indices are read as zeros.
fn client(format: GLenum, ty: GLenum, dims: u32, size: [i32; 3], store: &PixelStore) -> GlResult<Client> {
    const GL_BITMAP: GLenum = 0x1A00;
    if !(format == GL_COLOR_INDEX && ty == GL_BITMAP) {
        pixel_size(format, ty)?;
    }
    match format {
        GL_STENCIL_INDEX => return Err(GlError::InvalidOperation),
        GL_COLOR_INDEX => {
            let ity = match ty {
                GL_BITMAP => IndexType::Bitmap,
                _ => IndexType::Type(decode::<PixelType>(ty)?),
            };
            let size = size.map(|s| usize::try_from(s).unwrap_or(0));
            let len = index_image_bytes(ity, store, dims, size).ok_or(GlError::InvalidValue)?;
            return Ok(Client {
                format: PixelFormat::Rgba,
                ty: PixelType::UnsignedByte,
                len,
                index: Some(ity),
            });
        }
        _ => {}
    }
    let (format, ty) = (decode::<PixelFormat>(format)?, decode::<PixelType>(ty)?);
    let size = size.map(|s| usize::try_from(s).unwrap_or(0));
    let layout = ClientLayout::new(format, ty, store, dims, size).ok_or(GlError::InvalidValue)?;
    Ok(Client {
        format,
        ty,
        len: layout.len,
        index: None,
    })
}

/// The checks Mesa makes before the format and type (`texture_error_check`):
/// a negative level, a border other than 0 or 1, a negative size.
fn image_args(level: i32, border: i32, size: [i32; 3]) -> GlResult {
    if level < 0 || !(0..=1).contains(&border) || size.iter().any(|&s| s < 0) {
        return Err(GlError::InvalidValue);
    }
    Ok(())
}

/// [`image_args`] for an image of `t`: a rectangle texture has level 0 only
/// and no border (Mesa's `texture_error_check` finds both before the pixels'
/// format and type).
fn target_args(t: TexImageTarget, level: i32, border: i32, size: [i32; 3]) -> GlResult {
    image_args(level, border, size)?;
    if t.texture_target() == TextureTarget::Rect && (level != 0 || border != 0) {
        return Err(GlError::InvalidValue);
    }
    Ok(())
}

/// What an upload does with the client's pixels once they are checked: it
/// gets them (`None` for a null pointer) and their format and type.
type UploadFn = dyn Fn(&mut Context, Option<PixelData<'_>>, (PixelFormat, PixelType)) -> GlResult + Send + Sync;

/// Runs (or compiles) an upload of `pixels` (`format`, `ty`, a `dims`-dimensional
/// `size` under the unpack state): `pre` is the arguments' check, made before
/// the pixel checks. Compiled into a list, the bytes are copied now, with the
/// unpack state of now; `proxy` uploads run at once even then (GL 1.5 §5.4).
///
/// # Safety
/// `pixels` is null or holds the image as the unpack state lays it out.
unsafe fn upload(
    pre: GlResult,
    proxy: bool,
    (format, ty, dims, size): (GLenum, GLenum, u32, [i32; 3]),
    pixels: *const c_void,
    f: Arc<UploadFn>,
) {
    with_gl((), |os, gl| {
        let store = os.unpack;
        let checked = pre.and_then(|()| client(format, ty, dims, size, &store));
        let run = move |gl: &mut Context, c: Client, bytes: Option<&[u8]>| {
            let rgba = match (c.index, bytes) {
                (Some(ity), Some(bytes)) => {
                    let size = size.map(|s| usize::try_from(s).unwrap_or(0));
                    let image = index_image_rgba8(gl.pixel_state(), bytes, ity, &store, dims, size);
                    Some(image.ok_or(GlError::InvalidOperation)?)
                }
                _ => None,
            };
            let (bytes, store) = match &rgba {
                Some(image) => (
                    Some(&image[..]),
                    PixelStore {
                        alignment: 1,
                        ..PixelStore::DEFAULT
                    },
                ),
                None => (bytes, store),
            };
            let data = bytes.map(|bytes| PixelData {
                format: c.format,
                ty: c.ty,
                store,
                bytes,
            });
            f(gl, data, (c.format, c.ty))
        };
        if os.compiling.is_none() || proxy {
            let r = outside(gl).and(checked).and_then(|c| {
                // SAFETY: the caller's contract: `pixels` holds the image,
                // which ends `c.len` bytes after it.
                run(gl, c, unsafe { client_bytes(pixels, c.len) })
            });
            if let Err(e) = r {
                gl.record_error(e);
            }
            return;
        }
        // SAFETY: as above; copied now, as GL compiles an upload.
        let copy = checked.map(|c| (c, unsafe { client_bytes(pixels, c.len) }.map(<[u8]>::to_vec)));
        let cmd: Cmd = Arc::new(move |_, gl: &mut Context| {
            let r = outside(gl).and_then(|()| match &copy {
                Ok((c, bytes)) => run(gl, *c, bytes.as_deref()),
                Err(e) => Err(*e),
            });
            if let Err(e) = r {
                gl.record_error(e);
            }
        });
        run_or_record(os, gl, cmd);
    })
}

/// The `len` bytes of the client's image at `pixels`, `None` for a null pointer.
///
/// # Safety
/// `pixels` is null or readable for `len` bytes.
unsafe fn client_bytes<'a>(pixels: *const c_void, len: usize) -> Option<&'a [u8]> {
    // SAFETY: readable for `len` bytes by the caller's contract.
    (!pixels.is_null()).then(|| unsafe { std::slice::from_raw_parts(pixels.cast::<u8>(), len) })
}

/// `glTexImage{1,2,3}D`.
///
/// # Safety
/// `pixels` is null or holds the image as the unpack state lays it out.
#[allow(clippy::too_many_arguments)]
unsafe fn tex_image(
    dims: u32,
    target: GLenum,
    level: i32,
    internal: i32,
    size: [i32; 3],
    border: i32,
    (format, ty): (GLenum, GLenum),
    pixels: *const c_void,
) {
    let t = image_target(target, Some(dims), Takes::WithProxies);
    let proxy = matches!(t, Ok(TexImageTarget::Proxy(_)));
    let pre = t.and_then(|t| target_args(t, level, border, size));
    // The internal format is checked after the pixels' format and type.
    let f: Arc<UploadFn> = Arc::new(move |gl, data, (format, ty)| {
        let internal = internal_format(internal)?;
        if data.is_none() {
            check_format_type(internal, format, ty)?;
        }
        gl.tex_image(t?, level, internal, size, border, data)
    });
    // SAFETY: passed on from the caller.
    unsafe { upload(pre, proxy, (format, ty, dims, size), pixels, f) }
}

/// `glTexSubImage{1,2,3}D`; a null `pixels` changes nothing (Mesa).
///
/// # Safety
/// `pixels` is null or holds the image as the unpack state lays it out.
unsafe fn tex_sub_image(
    dims: u32,
    target: GLenum,
    level: i32,
    offset: [i32; 3],
    size: [i32; 3],
    (format, ty): (GLenum, GLenum),
    pixels: *const c_void,
) {
    let t = image_target(target, Some(dims), Takes::Images);
    let pre = t.and_then(|t| target_args(t, level, 0, size));
    let f: Arc<UploadFn> = Arc::new(move |gl, data, format_type| match data {
        Some(data) => gl.tex_sub_image(t?, level, offset, size, data),
        None => gl.tex_sub_image_errors(t?, level, offset, size, format_type),
    });
    // SAFETY: passed on from the caller.
    unsafe { upload(pre, false, (format, ty, dims, size), pixels, f) }
}

/// `glCopyTexImage{1,2}D`.
fn copy_tex_image(dims: u32, target: GLenum, level: i32, internal: GLenum, xy: [i32; 2], size: [i32; 2], border: i32) {
    checked(move |gl| {
        outside(gl)?;
        let t = image_target(target, Some(dims), Takes::Images)?;
        target_args(t, level, border, [size[0], size[1], 1])?;
        // Unknown internal formats are GL_INVALID_ENUM here (Mesa's copytexture_error_check).
        let internal = InternalFormat::from_gl(internal).ok_or(GlError::InvalidEnum)?;
        gl.copy_tex_image(t, level, internal, xy, size, border)
    })
}

/// `glCopyTexSubImage{1,2,3}D`.
fn copy_tex_sub_image(dims: u32, target: GLenum, level: i32, offset: [i32; 3], xy: [i32; 2], size: [i32; 2]) {
    checked(move |gl| {
        outside(gl)?;
        let t = image_target(target, Some(dims), Takes::Images)?;
        target_args(t, level, 0, [size[0], size[1], 1])?;
        gl.copy_tex_sub_image(t, level, offset, xy, size)
    })
}

/// `glGetTexImage`: the pack state lays the image out in `pixels`.
///
/// # Safety
/// `pixels` has room for the image as the pack state lays it out.
unsafe fn get_tex_image(target: GLenum, level: i32, format: GLenum, ty: GLenum, pixels: *mut c_void) {
    now(|os, gl| {
        outside(gl)?;
        let t = image_target(target, None, Takes::Images)?;
        if level < 0 {
            return Err(GlError::InvalidValue);
        }
        let size = [
            TexLevelParamName::Width,
            TexLevelParamName::Height,
            TexLevelParamName::Depth,
        ]
        .map(|n| gl.get_tex_level_parameter(t, level, n).unwrap_or(0));
        let pack = os.pack;
        let c = client(format, ty, t.dims(), size, &pack)?;
        if c.index.is_some() {
            // Indices are written only by an index texture, which softgl has not.
            return Err(GlError::InvalidOperation);
        }
        if pixels.is_null() {
            // Nothing to write into (Mesa: not an error without a buffer object).
            return Ok(());
        }
        // SAFETY: GL's contract: `pixels` has room for the image as the pack
        // state lays it out, which ends `c.len` bytes after it.
        let out = unsafe { std::slice::from_raw_parts_mut(pixels.cast::<u8>(), c.len) };
        gl.get_tex_image(t, level, c.format, c.ty, &pack, out)
    })
}

// ----- texture objects -----

/// Reads `n` names at `names`; `InvalidValue` for a negative count.
///
/// # Safety
/// `names` is null or holds `n` values.
unsafe fn names(n: i32, names: *const u32) -> GlResult<Vec<u32>> {
    if n < 0 {
        return Err(GlError::InvalidValue);
    }
    if n == 0 || names.is_null() {
        return Ok(Vec::new());
    }
    // SAFETY: `n` readable names (the caller's contract).
    Ok(unsafe { std::slice::from_raw_parts(names, n as usize) }.to_vec())
}

/// `glActiveTexture`: the unit `GL_TEXTUREi` names (its range is checked by softgl).
fn active_texture(texture: GLenum) {
    checked(move |gl| {
        outside(gl)?;
        gl.active_texture(texture.wrapping_sub(GL_TEXTURE0))
    })
}

exports! {
    [] fn glActiveTexture(texture: GLenum) {
        active_texture(texture)
    }
    [] fn glActiveTextureARB(texture: GLenum) {
        active_texture(texture)
    }

    // ----- objects -----
    /// # Safety
    /// `textures` is null or has room for `n` names.
    [unsafe] fn glGenTextures(n: i32, textures: *mut u32) {
        now(|_, gl| {
            outside(gl)?;
            if n < 0 {
                return Err(GlError::InvalidValue);
            }
            let names = gl.gen_textures(n)?;
            // SAFETY: room for `n` names (GL's contract).
            unsafe { write(textures, &names) };
            Ok(())
        })
    }
    /// # Safety
    /// `textures` is null or holds `n` names.
    [unsafe] fn glDeleteTextures(n: i32, textures: *const u32) {
        // SAFETY: passed on.
        let names = unsafe { names(n, textures) };
        now(|_, gl| {
            outside(gl)?;
            gl.delete_textures(&names?);
            Ok(())
        })
    }
    [] fn glBindTexture(target_enum: GLenum, texture: u32) {
        checked(move |gl| {
            outside(gl)?;
            gl.bind_texture(target(target_enum)?, texture)
        })
    }
    [] fn glIsTexture(texture: u32) -> u8 {
        with_gl(GL_FALSE, |_, gl| match outside(gl) {
            Ok(()) => u8::from(gl.is_texture(texture)),
            Err(e) => {
                gl.record_error(e);
                GL_FALSE
            }
        })
    }
    /// `GL_TRUE` when all are resident (always, for names of textures), and
    /// then `residences` is left as it was (GL 1.5 §3.8.12).
    ///
    /// # Safety
    /// `textures` holds `n` names; `residences` is null or has room for `n` values.
    [unsafe] fn glAreTexturesResident(n: i32, textures: *const u32, residences: *mut u8) -> u8 {
        // SAFETY: passed on.
        let names = unsafe { names(n, textures) };
        with_gl(GL_FALSE, |_, gl| {
            let r = outside(gl).and(names).and_then(|names| gl.are_textures_resident(&names));
            match r {
                Ok(all) if all.iter().all(|&b| b) => GL_TRUE,
                Ok(each) => {
                    let v: Vec<u8> = each.iter().map(|&b| u8::from(b)).collect();
                    // SAFETY: room for `n` values (GL's contract).
                    unsafe { write(residences, &v) };
                    GL_FALSE
                }
                Err(e) => {
                    gl.record_error(e);
                    GL_FALSE
                }
            }
        })
    }
    /// # Safety
    /// `textures` and `priorities` are null or hold `n` values each.
    [unsafe] fn glPrioritizeTextures(n: i32, textures: *const u32, priorities: *const f32) {
        // SAFETY: passed on; `n` priorities too.
        let (names, prios) = unsafe { (names(n, textures), names(n, priorities.cast::<u32>())) };
        let prios = prios.map(|p| p.into_iter().map(f32::from_bits).collect::<Vec<_>>());
        checked(move |gl| {
            outside(gl)?;
            gl.prioritize_textures(&names.clone()?, &prios.clone()?);
            Ok(())
        })
    }
    /// # Safety
    /// `textures` is null or has room for `n` names.
    [unsafe] fn glGenTexturesEXT(n: i32, textures: *mut u32) {
        // SAFETY: passed on.
        unsafe { glGenTextures(n, textures) }
    }
    /// # Safety
    /// `textures` is null or holds `n` names.
    [unsafe] fn glDeleteTexturesEXT(n: i32, textures: *const u32) {
        // SAFETY: passed on.
        unsafe { glDeleteTextures(n, textures) }
    }
    [] fn glBindTextureEXT(target: GLenum, texture: u32) {
        glBindTexture(target, texture)
    }
    [] fn glIsTextureEXT(texture: u32) -> u8 {
        glIsTexture(texture)
    }
    /// # Safety
    /// As `glAreTexturesResident`.
    [unsafe] fn glAreTexturesResidentEXT(n: i32, textures: *const u32, residences: *mut u8) -> u8 {
        // SAFETY: passed on.
        unsafe { glAreTexturesResident(n, textures, residences) }
    }
    /// # Safety
    /// As `glPrioritizeTextures`.
    [unsafe] fn glPrioritizeTexturesEXT(n: i32, textures: *const u32, priorities: *const f32) {
        // SAFETY: passed on.
        unsafe { glPrioritizeTextures(n, textures, priorities) }
    }

    // ----- images -----
    /// # Safety
    /// `pixels` is null or holds the image as the unpack state lays it out.
    [unsafe] fn glTexImage1D(target: GLenum, level: i32, internal_format: i32, width: i32, border: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { tex_image(1, target, level, internal_format, [width, 1, 1], border, (format, ty), pixels) }
    }
    /// # Safety
    /// `pixels` is null or holds the image as the unpack state lays it out.
    [unsafe] fn glTexImage2D(target: GLenum, level: i32, internal_format: i32, width: i32, height: i32, border: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { tex_image(2, target, level, internal_format, [width, height, 1], border, (format, ty), pixels) }
    }
    /// # Safety
    /// `pixels` is null or holds the image as the unpack state lays it out.
    [unsafe] fn glTexImage3D(target: GLenum, level: i32, internal_format: i32, width: i32, height: i32, depth: i32, border: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { tex_image(3, target, level, internal_format, [width, height, depth], border, (format, ty), pixels) }
    }
    /// # Safety
    /// As `glTexImage3D`.
    [unsafe] fn glTexImage3DEXT(target: GLenum, level: i32, internal_format: i32, width: i32, height: i32, depth: i32, border: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { glTexImage3D(target, level, internal_format, width, height, depth, border, format, ty, pixels) }
    }
    /// # Safety
    /// `pixels` is null or holds the image as the unpack state lays it out.
    [unsafe] fn glTexSubImage1D(target: GLenum, level: i32, xoffset: i32, width: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { tex_sub_image(1, target, level, [xoffset, 0, 0], [width, 1, 1], (format, ty), pixels) }
    }
    /// # Safety
    /// `pixels` is null or holds the image as the unpack state lays it out.
    [unsafe] fn glTexSubImage2D(target: GLenum, level: i32, xoffset: i32, yoffset: i32, width: i32, height: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { tex_sub_image(2, target, level, [xoffset, yoffset, 0], [width, height, 1], (format, ty), pixels) }
    }
    /// # Safety
    /// `pixels` is null or holds the image as the unpack state lays it out.
    [unsafe] fn glTexSubImage3D(target: GLenum, level: i32, xoffset: i32, yoffset: i32, zoffset: i32, width: i32, height: i32, depth: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { tex_sub_image(3, target, level, [xoffset, yoffset, zoffset], [width, height, depth], (format, ty), pixels) }
    }
    /// # Safety
    /// As `glTexSubImage3D`.
    [unsafe] fn glTexSubImage3DEXT(target: GLenum, level: i32, xoffset: i32, yoffset: i32, zoffset: i32, width: i32, height: i32, depth: i32, format: GLenum, ty: GLenum, pixels: *const c_void) {
        // SAFETY: passed on.
        unsafe { glTexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format, ty, pixels) }
    }
    [] fn glCopyTexImage1D(target: GLenum, level: i32, internal_format: GLenum, x: i32, y: i32, width: i32, border: i32) {
        copy_tex_image(1, target, level, internal_format, [x, y], [width, 1], border)
    }
    [] fn glCopyTexImage2D(target: GLenum, level: i32, internal_format: GLenum, x: i32, y: i32, width: i32, height: i32, border: i32) {
        copy_tex_image(2, target, level, internal_format, [x, y], [width, height], border)
    }
    [] fn glCopyTexSubImage1D(target: GLenum, level: i32, xoffset: i32, x: i32, y: i32, width: i32) {
        copy_tex_sub_image(1, target, level, [xoffset, 0, 0], [x, y], [width, 1])
    }
    [] fn glCopyTexSubImage2D(target: GLenum, level: i32, xoffset: i32, yoffset: i32, x: i32, y: i32, width: i32, height: i32) {
        copy_tex_sub_image(2, target, level, [xoffset, yoffset, 0], [x, y], [width, height])
    }
    [] fn glCopyTexSubImage3D(target: GLenum, level: i32, xoffset: i32, yoffset: i32, zoffset: i32, x: i32, y: i32, width: i32, height: i32) {
        copy_tex_sub_image(3, target, level, [xoffset, yoffset, zoffset], [x, y], [width, height])
    }
    [] fn glCopyTexSubImage3DEXT(target: GLenum, level: i32, xoffset: i32, yoffset: i32, zoffset: i32, x: i32, y: i32, width: i32, height: i32) {
        glCopyTexSubImage3D(target, level, xoffset, yoffset, zoffset, x, y, width, height)
    }
    /// # Safety
    /// `pixels` has room for the image as the pack state lays it out.
    [unsafe] fn glGetTexImage(target: GLenum, level: i32, format: GLenum, ty: GLenum, pixels: *mut c_void) {
        // SAFETY: passed on.
        unsafe { get_tex_image(target, level, format, ty, pixels) }
    }
    /// # Safety
    /// `params` is null or writable.
    [unsafe] fn glGetTexLevelParameteriv(target: GLenum, level: i32, pname: GLenum, params: *mut i32) {
        if let Ok(v) = get_level_parameter(target, level, pname) {
            // SAFETY: one writable value (GL's contract).
            unsafe { write(params, &[v]) }
        }
    }
    /// # Safety
    /// `params` is null or writable.
    [unsafe] fn glGetTexLevelParameterfv(target: GLenum, level: i32, pname: GLenum, params: *mut f32) {
        if let Ok(v) = get_level_parameter(target, level, pname) {
            // SAFETY: one writable value (GL's contract).
            unsafe { write(params, &[v as f32]) }
        }
    }
    /// `glGenerateMipmap` (GL 3.0, ARB/EXT_framebuffer_object; MuJoCo and
    /// PyOpenGL programs call it on GL 1.x contexts too): run at once.
    [] fn glGenerateMipmap(target_enum: GLenum) {
        now(|_, gl| {
            outside(gl)?;
            gl.generate_mipmap(target(target_enum)?)
        })
    }
    [] fn glGenerateMipmapEXT(target: GLenum) {
        glGenerateMipmap(target)
    }

    // ----- parameters -----
    [] fn glTexParameterf(target: GLenum, pname: GLenum, param: f32) {
        tex_parameter(target, pname, [f64::from(param), 0.0, 0.0, 0.0], false)
    }
    [] fn glTexParameteri(target: GLenum, pname: GLenum, param: i32) {
        tex_parameter(target, pname, [f64::from(param), 0.0, 0.0, 0.0], true)
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const f32) {
        // SAFETY: passed on.
        unsafe { tex_parameter_v(target, pname, params, false) }
    }
    /// # Safety
    /// `params` is null or holds the values `pname` takes.
    [unsafe] fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const i32) {
        // SAFETY: passed on.
        unsafe { tex_parameter_v(target, pname, params, true) }
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut f32) {
        get_tex_parameter(target, pname, params, floats)
    }
    /// # Safety
    /// `params` is null or has room for the values of `pname`.
    [unsafe] fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut i32) {
        get_tex_parameter(target, pname, params, ints)
    }

    // ----- compressed images (GL 1.3): softgl has no compressed format -----
    /// No internal format is compressed: `GL_INVALID_ENUM`.
    [] fn glCompressedTexImage1D(_target: GLenum, _level: i32, _internal_format: GLenum, _width: i32, _border: i32, _size: i32, _data: *const c_void) {
        checked(|gl| outside(gl).and(Err(GlError::InvalidEnum)))
    }
    /// No internal format is compressed: `GL_INVALID_ENUM`.
    [] fn glCompressedTexImage2D(_target: GLenum, _level: i32, _internal_format: GLenum, _width: i32, _height: i32, _border: i32, _size: i32, _data: *const c_void) {
        checked(|gl| outside(gl).and(Err(GlError::InvalidEnum)))
    }
    /// No internal format is compressed: `GL_INVALID_ENUM`.
    [] fn glCompressedTexImage3D(_target: GLenum, _level: i32, _internal_format: GLenum, _width: i32, _height: i32, _depth: i32, _border: i32, _size: i32, _data: *const c_void) {
        checked(|gl| outside(gl).and(Err(GlError::InvalidEnum)))
    }
    /// No format is compressed: `GL_INVALID_ENUM`.
    [] fn glCompressedTexSubImage1D(_target: GLenum, _level: i32, _xoffset: i32, _width: i32, _format: GLenum, _size: i32, _data: *const c_void) {
        checked(|gl| outside(gl).and(Err(GlError::InvalidEnum)))
    }
    /// No format is compressed: `GL_INVALID_ENUM`.
    [] fn glCompressedTexSubImage2D(_target: GLenum, _level: i32, _xoffset: i32, _yoffset: i32, _width: i32, _height: i32, _format: GLenum, _size: i32, _data: *const c_void) {
        checked(|gl| outside(gl).and(Err(GlError::InvalidEnum)))
    }
    /// No format is compressed: `GL_INVALID_ENUM`.
    [] fn glCompressedTexSubImage3D(_target: GLenum, _level: i32, _xoffset: i32, _yoffset: i32, _zoffset: i32, _width: i32, _height: i32, _depth: i32, _format: GLenum, _size: i32, _data: *const c_void) {
        checked(|gl| outside(gl).and(Err(GlError::InvalidEnum)))
    }
    /// No image is compressed: `GL_INVALID_OPERATION`.
    [] fn glGetCompressedTexImage(_target: GLenum, _level: i32, _img: *mut c_void) {
        now(|_, gl| outside(gl).and(Err(GlError::InvalidOperation)))
    }
}

/// The `glGet` value of the texture state, if `pname` is one: bindings and
/// the active units, limits, the client active unit's coordinate array.
pub(super) fn value(os: &GlState, gl: &Context, pname: GLenum) -> Option<Val> {
    let one = |v: i64| Val::I(vec![v]);
    let unit = gl.active_texture_unit();
    if let Some(t) = TARGETS.iter().find(|t| t.2 == pname) {
        return Some(one(gl.texture_binding(unit, t.0).into()));
    }
    let a = os.tex_coord();
    Some(match pname {
        GL_ACTIVE_TEXTURE => one(i64::from(GL_TEXTURE0) + unit as i64),
        GL_CLIENT_ACTIVE_TEXTURE => one(i64::from(GL_TEXTURE0) + os.client_active as i64),
        GL_MAX_TEXTURE_UNITS => one(MAX_UNITS as i64),
        GL_MAX_TEXTURE_SIZE | GL_MAX_CUBE_MAP_TEXTURE_SIZE => one(MAX_SIZE.into()),
        GL_MAX_3D_TEXTURE_SIZE => one(MAX_3D_SIZE.into()),
        GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB => one(MAX_RECTANGLE_TEXTURE_SIZE.into()),
        // llvmpipe's PIPE_CAPF_MAX_TEXTURE_LOD_BIAS.
        GL_MAX_TEXTURE_LOD_BIAS => Val::F(vec![16.0]),
        GL_NUM_COMPRESSED_TEXTURE_FORMATS => one(0),
        GL_COMPRESSED_TEXTURE_FORMATS => Val::I(Vec::new()),
        GL_TEXTURE_COORD_ARRAY => Val::B(vec![a.enabled]),
        GL_TEXTURE_COORD_ARRAY_SIZE => one(a.size.into()),
        GL_TEXTURE_COORD_ARRAY_TYPE => one(a.ty.into()),
        GL_TEXTURE_COORD_ARRAY_STRIDE => one(a.stride.into()),
        _ => return None,
    })
}

/// Every texture target with its `glEnable` and binding enumerants.
pub(super) const TARGETS: [(TextureTarget, GLenum, GLenum); crate::gl_state::TEXTURE_TARGETS] = [
    (TextureTarget::D1, GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D),
    (TextureTarget::D2, GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D),
    (TextureTarget::D3, GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D),
    (TextureTarget::Cube, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP),
    (
        TextureTarget::Rect,
        GL_TEXTURE_RECTANGLE_ARB,
        GL_TEXTURE_BINDING_RECTANGLE_ARB,
    ),
];
