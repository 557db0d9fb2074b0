//! Framebuffer objects: the C ABI of ARB_framebuffer_object and of the EXT
//! names that map onto the same functions (EXT_framebuffer_object,
//! EXT_framebuffer_blit, EXT_framebuffer_multisample, EXT_texture_array's
//! `glFramebufferTextureLayerEXT`), a thin layer over `softgl::fbo`.
//!
//! # Design
//!
//! The Rust API holds the objects and does the work (`src/fbo.rs`: a bound
//! draw object's attachments are assembled into the context's framebuffer,
//! texture attachments are copies synced at the points GL needs them); this
//! layer decodes enumerants, checks arguments in Mesa's order
//! (`main/fbobject.c`, `main/blit.c`), and answers the queries. Object 0 is
//! the OSMesa/EGL window buffer.
//!
//! Display lists: GL 3.0 §5.4 runs the object commands at once (names,
//! binding, storage, attachments, status, `glGenerateMipmap`); only
//! `glBlitFramebuffer` is compiled, as Mesa's `dlist.c` does.

use super::texture::write;
use super::{checked, now, outside};
use crate::consts::*;
use softgl::fbo::{
    Attachment, AttachmentPoint, BlitFilter, BlitMask, FramebufferTarget, RenderbufferFormat, WindowBuffer,
    MAX_COLOR_ATTACHMENTS, MAX_RENDERBUFFER_SIZE, MAX_SAMPLES,
};
use softgl::texture::TexImageTarget;
use softgl::{ColorFormat, Context, GlError, GlResult};

pub const GL_FRAMEBUFFER: GLenum = 0x8D40;
pub const GL_READ_FRAMEBUFFER: GLenum = 0x8CA8;
pub const GL_DRAW_FRAMEBUFFER: GLenum = 0x8CA9;
pub const GL_RENDERBUFFER: GLenum = 0x8D41;
pub const GL_COLOR_ATTACHMENT0: GLenum = 0x8CE0;
pub const GL_DEPTH_ATTACHMENT: GLenum = 0x8D00;
pub const GL_STENCIL_ATTACHMENT: GLenum = 0x8D20;
pub const GL_DEPTH_STENCIL_ATTACHMENT: GLenum = 0x821A;
const GL_TEXTURE: GLenum = 0x1702;
const GL_UNSIGNED_NORMALIZED: GLenum = 0x8C17;
const GL_INDEX: GLenum = 0x8222;
const GL_FRAMEBUFFER_DEFAULT: GLenum = 0x8218;
const GL_DEPTH: GLenum = 0x1801;
const GL_STENCIL: GLenum = 0x1802;
const GL_SRGB: GLenum = 0x8C40;
const GL_LINEAR_ENUM: GLenum = 0x2601;
const GL_NEAREST_ENUM: GLenum = 0x2600;

/// `glBindFramebuffer`'s target.
fn fb_target(t: GLenum) -> GlResult<FramebufferTarget> {
    Ok(match t {
        GL_FRAMEBUFFER => FramebufferTarget::Both,
        GL_DRAW_FRAMEBUFFER => FramebufferTarget::Draw,
        GL_READ_FRAMEBUFFER => FramebufferTarget::Read,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// An attachment point; `GL_COLOR_ATTACHMENTm` past the maximum is
/// `GL_INVALID_OPERATION` (GL 3.0 §4.4.2), anything else unknown `GL_INVALID_ENUM`.
fn point(a: GLenum) -> GlResult<AttachmentPoint> {
    Ok(match a {
        GL_DEPTH_ATTACHMENT => AttachmentPoint::Depth,
        GL_STENCIL_ATTACHMENT => AttachmentPoint::Stencil,
        GL_DEPTH_STENCIL_ATTACHMENT => AttachmentPoint::DepthStencil,
        a if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + MAX_COLOR_ATTACHMENTS as u32).contains(&a) => {
            AttachmentPoint::Color(a - GL_COLOR_ATTACHMENT0)
        }
        a if (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + 32).contains(&a) => return Err(GlError::InvalidOperation),
        _ => return Err(GlError::InvalidEnum),
    })
}

/// A renderbuffer internal format (GL 3.0 table 3.16's colour formats GL
/// 1.5 has, RGB565, depth and stencil formats, and the float colour
/// formats GL 3.0 lists as colour-renderable, RGBA16F/RGB16F/RGB32F not
/// rendered: `src/fbo.rs`). Float depth (ARB_depth_buffer_float) and
/// integer colour are not here yet.
fn rb_format(f: GLenum) -> GlResult<RenderbufferFormat> {
    use RenderbufferFormat as F;
    Ok(match f {
        0x1908 => F::Rgba,
        0x8058 => F::Rgba8,
        0x1907 => F::Rgb,
        0x8051 => F::Rgb8,
        0x8D62 => F::Rgb565,
        0x8055 => F::Rgba2,
        0x8056 => F::Rgba4,
        0x8057 => F::Rgb5A1,
        0x2A10 => F::R3G3B2,
        0x804F => F::Rgb4,
        0x8050 => F::Rgb5,
        0x8052 => F::Rgb10,
        0x8059 => F::Rgb10A2,
        0x8053 => F::Rgb12,
        0x805A => F::Rgba12,
        0x8054 => F::Rgb16,
        0x805B => F::Rgba16,
        0x881A => F::Rgba16F,
        0x881B => F::Rgb16F,
        0x8814 => F::Rgba32F,
        0x8815 => F::Rgb32F,
        0x1902 => F::DepthComponent,
        0x81A5 => F::DepthComponent16,
        0x81A6 => F::DepthComponent24,
        0x81A7 => F::DepthComponent32,
        0x84F9 => F::DepthStencil,
        0x88F0 => F::Depth24Stencil8,
        0x8CAC => F::DepthComponent32F,
        0x8CAD => F::Depth32FStencil8,
        0x1901 => F::StencilIndex,
        0x8D46 => F::StencilIndex1,
        0x8D47 => F::StencilIndex4,
        0x8D48 => F::StencilIndex8,
        0x8D49 => F::StencilIndex16,
        _ => return Err(GlError::InvalidEnum),
    })
}

fn rb_format_enum(f: RenderbufferFormat) -> GLenum {
    use RenderbufferFormat as F;
    match f {
        F::Rgba => 0x1908,
        F::Rgba8 => 0x8058,
        F::Rgb => 0x1907,
        F::Rgb8 => 0x8051,
        F::Rgb565 => 0x8D62,
        F::Rgba2 => 0x8055,
        F::Rgba4 => 0x8056,
        F::Rgb5A1 => 0x8057,
        F::R3G3B2 => 0x2A10,
        F::Rgb4 => 0x804F,
        F::Rgb5 => 0x8050,
        F::Rgb10 => 0x8052,
        F::Rgb10A2 => 0x8059,
        F::Rgb12 => 0x8053,
        F::Rgba12 => 0x805A,
        F::Rgb16 => 0x8054,
        F::Rgba16 => 0x805B,
        F::Rgba16F => 0x881A,
        F::Rgb16F => 0x881B,
        F::Rgba32F => 0x8814,
        F::Rgb32F => 0x8815,
        F::DepthComponent => 0x1902,
        F::DepthComponent16 => 0x81A5,
        F::DepthComponent24 => 0x81A6,
        F::DepthComponent32 => 0x81A7,
        F::DepthStencil => 0x84F9,
        F::Depth24Stencil8 => 0x88F0,
        F::DepthComponent32F => 0x8CAC,
        F::Depth32FStencil8 => 0x8CAD,
        F::StencilIndex => 0x1901,
        F::StencilIndex1 => 0x8D46,
        F::StencilIndex4 => 0x8D47,
        F::StencilIndex8 => 0x8D48,
        F::StencilIndex16 => 0x8D49,
    }
}

/// `glGenFramebuffers`/`glGenRenderbuffers`.
///
/// # Safety
/// `out` is null or has room for `n` names.
unsafe fn gen(n: i32, out: *mut u32, f: fn(&mut Context, i32) -> GlResult<Vec<u32>>) {
    now(|_, gl| {
        outside(gl)?;
        if n < 0 {
            return Err(GlError::InvalidValue);
        }
        let names = f(gl, n)?;
        // SAFETY: room for `n` names (GL's contract).
        unsafe { write(out, &names) };
        Ok(())
    })
}

/// The names `names` points at.
///
/// # Safety
/// `names` is null or holds `n` names.
unsafe fn read_names(n: i32, names: *const u32) -> GlResult<Vec<u32>> {
    if n < 0 {
        return Err(GlError::InvalidValue);
    }
    if n == 0 || names.is_null() {
        return Ok(Vec::new());
    }
    // SAFETY: `n` readable names (the caller's contract).
    Ok(unsafe { std::slice::from_raw_parts(names, n as usize) }.to_vec())
}

/// `glFramebufferTexture{1D,2D,3D}`: `dims` the call's; the texture target
/// must be one of those dimensions (cube faces for 2D).
fn framebuffer_texture(
    target: GLenum,
    attachment: GLenum,
    textarget: Option<(GLenum, u32)>,
    texture: u32,
    level: i32,
    layer: i32,
) {
    now(|_, gl| {
        outside(gl)?;
        let t = fb_target(target)?;
        let p = point(attachment)?;
        let tt = match textarget {
            None => None,
            Some((e, dims)) => {
                let it = TexImageTarget::from_gl(e).filter(|t| !matches!(t, TexImageTarget::Proxy(_)));
                match it {
                    Some(it) if it.dims() == dims => Some(it),
                    // Mesa: a texture given with the wrong target is INVALID_OPERATION,
                    // an unknown target INVALID_ENUM; texture 0 ignores the target.
                    Some(_) if texture != 0 => return Err(GlError::InvalidOperation),
                    None if texture != 0 => return Err(GlError::InvalidEnum),
                    _ => None,
                }
            }
        };
        gl.framebuffer_texture(t, p, tt, texture, level, layer)
    })
}

/// `glDrawBuffer`: `GL_FRONT` and its aliases on the window (an OSMesa
/// context is single-buffered), `GL_COLOR_ATTACHMENTi` on an object, and
/// `GL_NONE` on either (colour writes off).
pub(super) fn draw_buffer(gl: &mut Context, mode: GLenum) -> GlResult {
    outside(gl)?;
    let object = gl.fbo_state().draw_binding() != 0;
    match mode {
        GL_NONE => gl.draw_buffer(None),
        0x8CE0..=0x8CFF if object => gl.draw_buffer(Some(mode - GL_COLOR_ATTACHMENT0)),
        0x8CE0..=0x8CFF => Err(GlError::InvalidOperation),
        GL_FRONT | GL_FRONT_LEFT | GL_LEFT | GL_FRONT_AND_BACK if !object => gl.draw_buffer_window(),
        GL_FRONT | GL_FRONT_LEFT | GL_LEFT | GL_FRONT_AND_BACK => Err(GlError::InvalidOperation),
        GL_FRONT_RIGHT | GL_BACK_LEFT | GL_BACK_RIGHT | GL_BACK | GL_RIGHT => Err(GlError::InvalidOperation),
        0x0409..=0x040C => Err(GlError::InvalidOperation),
        _ => Err(GlError::InvalidEnum),
    }
}

/// `glReadBuffer`, as [`draw_buffer`] for reads.
pub(super) fn read_buffer(gl: &mut Context, mode: GLenum) -> GlResult {
    outside(gl)?;
    let object = gl.fbo_state().read_binding() != 0;
    match mode {
        GL_NONE => gl.read_buffer(None, false),
        0x8CE0..=0x8CFF if object => gl.read_buffer(Some(mode - GL_COLOR_ATTACHMENT0), false),
        0x8CE0..=0x8CFF => Err(GlError::InvalidOperation),
        GL_FRONT | GL_FRONT_LEFT | GL_LEFT if !object => gl.read_buffer(None, true),
        GL_FRONT | GL_FRONT_LEFT | GL_LEFT => Err(GlError::InvalidOperation),
        GL_FRONT_RIGHT | GL_BACK_LEFT | GL_BACK_RIGHT | GL_BACK | GL_RIGHT | GL_FRONT_AND_BACK => {
            Err(GlError::InvalidOperation)
        }
        0x0409..=0x040C => Err(GlError::InvalidOperation),
        _ => Err(GlError::InvalidEnum),
    }
}

/// `GL_DRAW_BUFFER` and `GL_READ_BUFFER` now (what `glPushAttrib` saves
/// with `GL_COLOR_BUFFER_BIT` and `GL_PIXEL_MODE_BIT`, as Mesa's
/// `main/attrib.c`, from the bound objects).
pub(super) fn buffers(gl: &Context) -> (GLenum, GLenum) {
    let s = gl.fbo_state();
    let of = |name: u32, draw: bool| match s.framebuffer(name) {
        Some(f) => {
            let b = if draw { f.draw_buffer } else { f.read_buffer };
            b.map_or(GL_NONE, |i| GL_COLOR_ATTACHMENT0 + i)
        }
        None if (draw && s.window_draw_none()) || (!draw && s.window_read_none()) => GL_NONE,
        None => GL_FRONT,
    };
    (of(s.draw_binding(), true), of(s.read_binding(), false))
}

/// `glGetFramebufferAttachmentParameteriv`'s value.
fn attachment_param(gl: &mut Context, target: GLenum, attachment: GLenum, pname: GLenum) -> GlResult<i32> {
    let t = fb_target(target)?;
    let bound = match t {
        FramebufferTarget::Read => gl.fbo_state().read_binding(),
        _ => gl.fbo_state().draw_binding(),
    };
    if bound == 0 {
        return window_attachment_param(gl, attachment, pname);
    }
    let p = point(attachment)?;
    let a = gl.framebuffer_attachment(t, p)?;
    let bits = gl.attachment_bits(a);
    let none = a == Attachment::None;
    let err = GlError::InvalidOperation;
    Ok(match pname {
        0x8CD0 => match a {
            Attachment::None => GL_NONE as i32,
            Attachment::Renderbuffer(_) => GL_RENDERBUFFER as i32,
            Attachment::Texture { .. } => GL_TEXTURE as i32,
        },
        0x8CD1 => match a {
            Attachment::None => 0,
            Attachment::Renderbuffer(n) | Attachment::Texture { name: n, .. } => n as i32,
        },
        _ if none => return Err(err),
        0x8CD2..=0x8CD4 => match a {
            Attachment::Texture {
                name,
                level,
                face,
                layer,
            } => {
                let target = gl.textures().object(name).map(|o| o.target);
                match pname {
                    0x8CD2 => level as i32,
                    0x8CD3 if target == Some(softgl::texture::TextureTarget::Cube) => {
                        (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) as i32
                    }
                    0x8CD3 => 0,
                    _ => layer as i32,
                }
            }
            _ => return Err(GlError::InvalidEnum),
        },
        // COLOR_ENCODING
        0x8210 => {
            let srgb = match a {
                Attachment::Texture { name, level, face, .. } => gl
                    .textures()
                    .object(name)
                    .and_then(|o| o.image(level as usize, face as usize))
                    .is_some_and(|i| i.internal.storage().srgb),
                _ => false,
            };
            if srgb {
                GL_SRGB as i32
            } else {
                GL_LINEAR_ENUM as i32
            }
        }
        // COMPONENT_TYPE: not of DEPTH_STENCIL_ATTACHMENT (Mesa); stencil is an index,
        // but Z24_S8's is its format's datatype, unsigned normalized, and float depth's
        // is GL_FLOAT (`main/fbobject.c`).
        0x8211 if p == AttachmentPoint::DepthStencil => return Err(err),
        0x8211 if p == AttachmentPoint::Stencil && bits[4] > 0 && !gl.attachment_float_depth(a) => {
            GL_UNSIGNED_NORMALIZED as i32
        }
        0x8211 if p == AttachmentPoint::Stencil => GL_INDEX as i32,
        0x8211 if p == AttachmentPoint::Depth && gl.attachment_float_depth(a) => GL_FLOAT as i32,
        0x8211 if matches!(p, AttachmentPoint::Color(_)) && gl.attachment_float_color(a) => GL_FLOAT as i32,
        0x8211 => GL_UNSIGNED_NORMALIZED as i32,
        0x8212..=0x8217 => {
            if p == AttachmentPoint::DepthStencil && pname != 0x8216 && pname != 0x8217 {
                // Colour sizes of a depth-stencil image: 0.
                0
            } else {
                bits[(pname - 0x8212) as usize] as i32
            }
        }
        _ => return Err(GlError::InvalidEnum),
    })
}

/// `glGetFramebufferAttachmentParameteriv` on the window framebuffer (GL 3.0
/// §6.1.13, as Mesa's `main/fbobject.c` `get_framebuffer_attachment_parameter`
/// and `get_fb0_attachment` do for a single-buffered OSMesa window): `OBJECT_NAME`
/// is `GL_INVALID_ENUM`; `GL_FRONT`, `GL_FRONT_LEFT`, `GL_BACK`, `GL_BACK_LEFT`
/// (back is front when single-buffered) name the colour buffer, `GL_FRONT_RIGHT`
/// and `GL_BACK_RIGHT` nothing (type `GL_NONE`), `GL_DEPTH`/`GL_STENCIL` the
/// depth/stencil buffer; any other attachment is `GL_INVALID_ENUM`.
fn window_attachment_param(gl: &mut Context, attachment: GLenum, pname: GLenum) -> GlResult<i32> {
    if pname == 0x8CD1 {
        return Err(GlError::InvalidEnum);
    }
    let buffer = match attachment {
        GL_FRONT | GL_FRONT_LEFT | GL_BACK | GL_BACK_LEFT => Some(WindowBuffer::Color),
        GL_FRONT_RIGHT | GL_BACK_RIGHT => None,
        GL_DEPTH => Some(WindowBuffer::Depth),
        GL_STENCIL => Some(WindowBuffer::Stencil),
        _ => return Err(GlError::InvalidEnum),
    };
    let bits = buffer.and_then(|b| gl.window_buffer_bits(b));
    let depth_or_stencil = matches!(attachment, GL_DEPTH | GL_STENCIL);
    let Some(bits) = bits else {
        return match pname {
            0x8CD0 => Ok(GL_NONE as i32),
            // COLOR_ENCODING of an absent depth or stencil buffer: LINEAR (Mesa).
            0x8210 if depth_or_stencil => Ok(GL_LINEAR_ENUM as i32),
            0x8CD2..=0x8CD4 | 0x8210..=0x8217 => Err(GlError::InvalidOperation),
            _ => Err(GlError::InvalidEnum),
        };
    };
    Ok(match pname {
        0x8CD0 => GL_FRAMEBUFFER_DEFAULT as i32,
        0x8210 => GL_LINEAR_ENUM as i32,
        // COMPONENT_TYPE: stencil alone is S8 (an index); packed with depth
        // it is Z24_UNORM_S8_UINT's, unsigned normalized (Mesa's format table).
        0x8211 if buffer == Some(WindowBuffer::Stencil) && bits[4] == 0 => GL_INDEX as i32,
        0x8211 if buffer == Some(WindowBuffer::Color) && gl.framebuffer_pending().color_format().is_float() => {
            GL_FLOAT as i32
        }
        0x8211 => GL_UNSIGNED_NORMALIZED as i32,
        0x8212..=0x8217 => bits[(pname - 0x8212) as usize] as i32,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// `glGetRenderbufferParameteriv`'s value.
fn renderbuffer_param(gl: &mut Context, target: GLenum, pname: GLenum) -> GlResult<i32> {
    outside(gl)?;
    if target != GL_RENDERBUFFER {
        return Err(GlError::InvalidEnum);
    }
    let name = gl.fbo_state().renderbuffer_binding();
    let rb = gl.fbo_state().renderbuffer(name).ok_or(GlError::InvalidOperation)?;
    let bits = rb.format.bits();
    Ok(match pname {
        0x8D42 => rb.width as i32,
        0x8D43 => rb.height as i32,
        0x8D44 => rb_format_enum(rb.format) as i32,
        0x8D50..=0x8D55 if rb.width == 0 => 0,
        0x8D50..=0x8D55 => bits[(pname - 0x8D50) as usize] as i32,
        0x8CAB => rb.samples as i32,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// The colour bits of `format`: red, green, blue, alpha.
fn color_bits(format: ColorFormat) -> [u32; 4] {
    std::array::from_fn(|c| format.channel_bits(c))
}

/// The framebuffer-object queries of `glGet*` (`None`: not one of them);
/// the bit counts and buffers answer for the bound draw framebuffer.
pub(super) fn value(gl: &mut Context, pname: GLenum) -> Option<super::get::Val> {
    use super::get::Val;
    let s = gl.fbo_state();
    let (draw, read) = (s.draw_binding(), s.read_binding());
    let int = |v: i64| Some(Val::I(vec![v]));
    match pname {
        0x8CA6 => int(draw.into()),                     // (DRAW_)FRAMEBUFFER_BINDING
        0x8CAA => int(read.into()),                     // READ_FRAMEBUFFER_BINDING
        0x8CA7 => int(s.renderbuffer_binding().into()), // RENDERBUFFER_BINDING
        0x84E8 => int(MAX_RENDERBUFFER_SIZE.into()),    // MAX_RENDERBUFFER_SIZE
        0x8CDF => int(MAX_COLOR_ATTACHMENTS as i64),    // MAX_COLOR_ATTACHMENTS
        0x8D57 => int(MAX_SAMPLES.into()),              // MAX_SAMPLES
        0x80A9 if draw != 0 => int(gl.draw_framebuffer_samples().into()), // SAMPLES
        0x80A8 if draw != 0 => int(i64::from(gl.draw_framebuffer_samples() > 0)), // SAMPLE_BUFFERS
        0x0C01 => int(buffers(gl).0.into()),            // DRAW_BUFFER
        0x0C02 => int(buffers(gl).1.into()),            // READ_BUFFER
        0x0D52..=0x0D57 if draw != 0 => {
            // RED_BITS … STENCIL_BITS of the bound object (0 when incomplete).
            let (desc, color) = gl.draw_framebuffer_desc()?;
            let c = if color { color_bits(desc.color) } else { [0; 4] };
            let v = match pname {
                0x0D52..=0x0D55 => c[(pname - 0x0D52) as usize],
                0x0D56 => desc.depth_format().ok().flatten().map_or(0, |f| f.bits()),
                _ => desc.stencil_bits,
            };
            int(v.into())
        }
        _ => None,
    }
}

exports! {
    /// # Safety
    /// `framebuffers` has room for `n` names.
    [unsafe] fn glGenFramebuffers(n: i32, framebuffers: *mut u32) {
        // SAFETY: passed on.
        unsafe { gen(n, framebuffers, Context::gen_framebuffers) }
    }
    /// # Safety
    /// `framebuffers` is null or holds `n` names.
    [unsafe] fn glDeleteFramebuffers(n: i32, framebuffers: *const u32) {
        // SAFETY: passed on.
        let names = unsafe { read_names(n, framebuffers) };
        now(|_, gl| gl.delete_framebuffers(&names?))
    }
    [] fn glIsFramebuffer(framebuffer: u32) -> u8 {
        let mut r = 0;
        now(|_, gl| {
            outside(gl)?;
            r = u8::from(gl.is_framebuffer(framebuffer));
            Ok(())
        });
        r
    }
    [] fn glBindFramebuffer(target: GLenum, framebuffer: u32) {
        now(|_, gl| {
            outside(gl)?;
            gl.bind_framebuffer(fb_target(target)?, framebuffer)
        })
    }
    [] fn glCheckFramebufferStatus(target: GLenum) -> GLenum {
        let mut r = 0;
        now(|_, gl| {
            outside(gl)?;
            r = gl.check_framebuffer_status(fb_target(target)?)?.code();
            Ok(())
        });
        r
    }
    /// # Safety
    /// `renderbuffers` has room for `n` names.
    [unsafe] fn glGenRenderbuffers(n: i32, renderbuffers: *mut u32) {
        // SAFETY: passed on.
        unsafe { gen(n, renderbuffers, Context::gen_renderbuffers) }
    }
    /// # Safety
    /// `renderbuffers` is null or holds `n` names.
    [unsafe] fn glDeleteRenderbuffers(n: i32, renderbuffers: *const u32) {
        // SAFETY: passed on.
        let names = unsafe { read_names(n, renderbuffers) };
        now(|_, gl| gl.delete_renderbuffers(&names?))
    }
    [] fn glIsRenderbuffer(renderbuffer: u32) -> u8 {
        let mut r = 0;
        now(|_, gl| {
            outside(gl)?;
            r = u8::from(gl.is_renderbuffer(renderbuffer));
            Ok(())
        });
        r
    }
    [] fn glBindRenderbuffer(target: GLenum, renderbuffer: u32) {
        now(|_, gl| {
            outside(gl)?;
            if target != GL_RENDERBUFFER {
                return Err(GlError::InvalidEnum);
            }
            gl.bind_renderbuffer(renderbuffer)
        })
    }
    [] fn glRenderbufferStorage(target: GLenum, internalformat: GLenum, width: i32, height: i32) {
        glRenderbufferStorageMultisample(target, 0, internalformat, width, height)
    }
    /// 1 to `GL_MAX_SAMPLES` samples give a 4-sample renderbuffer (Mesa's choice on llvmpipe).
    [] fn glRenderbufferStorageMultisample(target: GLenum, samples: i32, internalformat: GLenum, width: i32, height: i32) {
        now(|_, gl| {
            outside(gl)?;
            if target != GL_RENDERBUFFER {
                return Err(GlError::InvalidEnum);
            }
            let f = rb_format(internalformat)?;
            if samples < 0 || width < 0 || height < 0 || width > MAX_RENDERBUFFER_SIZE as i32 || height > MAX_RENDERBUFFER_SIZE as i32 {
                return Err(GlError::InvalidValue);
            }
            // More samples than GL_MAX_SAMPLES: INVALID_OPERATION (ARB_framebuffer_object).
            if samples > MAX_SAMPLES as i32 {
                return Err(GlError::InvalidOperation);
            }
            gl.renderbuffer_storage(samples, f, width, height)
        })
    }
    [] fn glFramebufferRenderbuffer(target: GLenum, attachment: GLenum, renderbuffertarget: GLenum, renderbuffer: u32) {
        now(|_, gl| {
            outside(gl)?;
            let t = fb_target(target)?;
            let p = point(attachment)?;
            if renderbuffertarget != GL_RENDERBUFFER {
                return Err(GlError::InvalidEnum);
            }
            gl.framebuffer_renderbuffer(t, p, renderbuffer)
        })
    }
    [] fn glFramebufferTexture1D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: u32, level: i32) {
        framebuffer_texture(target, attachment, Some((textarget, 1)), texture, level, 0)
    }
    [] fn glFramebufferTexture2D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: u32, level: i32) {
        framebuffer_texture(target, attachment, Some((textarget, 2)), texture, level, 0)
    }
    [] fn glFramebufferTexture3D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: u32, level: i32, zoffset: i32) {
        framebuffer_texture(target, attachment, Some((textarget, 3)), texture, level, zoffset)
    }
    [] fn glFramebufferTextureLayer(target: GLenum, attachment: GLenum, texture: u32, level: i32, layer: i32) {
        framebuffer_texture(target, attachment, None, texture, level, layer)
    }
    /// # Safety
    /// `params` has room for one value.
    [unsafe] fn glGetFramebufferAttachmentParameteriv(target: GLenum, attachment: GLenum, pname: GLenum, params: *mut i32) {
        now(|_, gl| {
            outside(gl)?;
            let v = attachment_param(gl, target, attachment, pname)?;
            // SAFETY: room for one value (GL's contract).
            unsafe { write(params, &[v]) };
            Ok(())
        })
    }
    /// # Safety
    /// `params` has room for one value.
    [unsafe] fn glGetRenderbufferParameteriv(target: GLenum, pname: GLenum, params: *mut i32) {
        now(|_, gl| {
            let v = renderbuffer_param(gl, target, pname)?;
            // SAFETY: room for one value (GL's contract).
            unsafe { write(params, &[v]) };
            Ok(())
        })
    }
    /// Compiled into display lists (Mesa's `save_BlitFramebuffer`).
    [] fn glBlitFramebuffer(src_x0: i32, src_y0: i32, src_x1: i32, src_y1: i32, dst_x0: i32, dst_y0: i32, dst_x1: i32, dst_y1: i32, mask: u32, filter: GLenum) {
        checked(move |gl| {
            outside(gl)?;
            // Mesa's order (`main/blit.c`): completeness, filter, mask bits.
            if !gl.framebuffers_complete() {
                return Err(GlError::InvalidFramebufferOperation);
            }
            let filter = match filter {
                GL_NEAREST_ENUM => BlitFilter::Nearest,
                GL_LINEAR_ENUM => BlitFilter::Linear,
                _ => return Err(GlError::InvalidEnum),
            };
            if mask & !(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT) != 0 {
                return Err(GlError::InvalidValue);
            }
            let m = BlitMask {
                color: mask & GL_COLOR_BUFFER_BIT != 0,
                depth: mask & GL_DEPTH_BUFFER_BIT != 0,
                stencil: mask & GL_STENCIL_BUFFER_BIT != 0,
            };
            gl.blit_framebuffer([src_x0, src_y0, src_x1, src_y1], [dst_x0, dst_y0, dst_x1, dst_y1], m, filter)
        })
    }

    // ----- EXT names -----

    /// # Safety
    /// As `glGenFramebuffers`.
    [unsafe] fn glGenFramebuffersEXT(n: i32, framebuffers: *mut u32) {
        // SAFETY: passed on.
        unsafe { glGenFramebuffers(n, framebuffers) }
    }
    /// # Safety
    /// As `glDeleteFramebuffers`.
    [unsafe] fn glDeleteFramebuffersEXT(n: i32, framebuffers: *const u32) {
        // SAFETY: passed on.
        unsafe { glDeleteFramebuffers(n, framebuffers) }
    }
    [] fn glIsFramebufferEXT(framebuffer: u32) -> u8 {
        glIsFramebuffer(framebuffer)
    }
    [] fn glBindFramebufferEXT(target: GLenum, framebuffer: u32) {
        glBindFramebuffer(target, framebuffer)
    }
    [] fn glCheckFramebufferStatusEXT(target: GLenum) -> GLenum {
        glCheckFramebufferStatus(target)
    }
    /// # Safety
    /// As `glGenRenderbuffers`.
    [unsafe] fn glGenRenderbuffersEXT(n: i32, renderbuffers: *mut u32) {
        // SAFETY: passed on.
        unsafe { glGenRenderbuffers(n, renderbuffers) }
    }
    /// # Safety
    /// As `glDeleteRenderbuffers`.
    [unsafe] fn glDeleteRenderbuffersEXT(n: i32, renderbuffers: *const u32) {
        // SAFETY: passed on.
        unsafe { glDeleteRenderbuffers(n, renderbuffers) }
    }
    [] fn glIsRenderbufferEXT(renderbuffer: u32) -> u8 {
        glIsRenderbuffer(renderbuffer)
    }
    [] fn glBindRenderbufferEXT(target: GLenum, renderbuffer: u32) {
        glBindRenderbuffer(target, renderbuffer)
    }
    [] fn glRenderbufferStorageEXT(target: GLenum, internalformat: GLenum, width: i32, height: i32) {
        glRenderbufferStorage(target, internalformat, width, height)
    }
    [] fn glRenderbufferStorageMultisampleEXT(target: GLenum, samples: i32, internalformat: GLenum, width: i32, height: i32) {
        glRenderbufferStorageMultisample(target, samples, internalformat, width, height)
    }
    [] fn glFramebufferRenderbufferEXT(target: GLenum, attachment: GLenum, renderbuffertarget: GLenum, renderbuffer: u32) {
        glFramebufferRenderbuffer(target, attachment, renderbuffertarget, renderbuffer)
    }
    [] fn glFramebufferTexture1DEXT(target: GLenum, attachment: GLenum, textarget: GLenum, texture: u32, level: i32) {
        glFramebufferTexture1D(target, attachment, textarget, texture, level)
    }
    [] fn glFramebufferTexture2DEXT(target: GLenum, attachment: GLenum, textarget: GLenum, texture: u32, level: i32) {
        glFramebufferTexture2D(target, attachment, textarget, texture, level)
    }
    [] fn glFramebufferTexture3DEXT(target: GLenum, attachment: GLenum, textarget: GLenum, texture: u32, level: i32, zoffset: i32) {
        glFramebufferTexture3D(target, attachment, textarget, texture, level, zoffset)
    }
    [] fn glFramebufferTextureLayerEXT(target: GLenum, attachment: GLenum, texture: u32, level: i32, layer: i32) {
        glFramebufferTextureLayer(target, attachment, texture, level, layer)
    }
    /// # Safety
    /// As `glGetFramebufferAttachmentParameteriv`.
    [unsafe] fn glGetFramebufferAttachmentParameterivEXT(target: GLenum, attachment: GLenum, pname: GLenum, params: *mut i32) {
        // SAFETY: passed on.
        unsafe { glGetFramebufferAttachmentParameteriv(target, attachment, pname, params) }
    }
    /// # Safety
    /// As `glGetRenderbufferParameteriv`.
    [unsafe] fn glGetRenderbufferParameterivEXT(target: GLenum, pname: GLenum, params: *mut i32) {
        // SAFETY: passed on.
        unsafe { glGetRenderbufferParameteriv(target, pname, params) }
    }
    [] fn glBlitFramebufferEXT(src_x0: i32, src_y0: i32, src_x1: i32, src_y1: i32, dst_x0: i32, dst_y0: i32, dst_x1: i32, dst_y1: i32, mask: u32, filter: GLenum) {
        glBlitFramebuffer(src_x0, src_y0, src_x1, src_y1, dst_x0, dst_y0, dst_x1, dst_y1, mask, filter)
    }
}
