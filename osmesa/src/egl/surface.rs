//! Pbuffer surfaces: softgl allocates and owns each one's buffer (colour,
//! and the depth and stencil its config has). `eglSwapBuffers` on a pbuffer
//! has nothing to show and leaves the buffer as it is.

use super::*;
use crate::consts::MAX_SIZE;

const EGL_TEXTURE_RGB: EGLint = 0x305D;
const EGL_TEXTURE_RGBA: EGLint = 0x305E;
const EGL_TEXTURE_2D: EGLint = 0x305F;
const EGL_BUFFER_DESTROYED: EGLint = 0x3095;
const EGL_MULTISAMPLE_RESOLVE_BOX: EGLint = 0x309B;
const EGL_GL_COLORSPACE_SRGB: EGLint = 0x3089;

/// Width, height and `EGL_LARGEST_PBUFFER` of a pbuffer's attribute list.
fn pbuffer_size(attribs: &[(EGLint, EGLint)]) -> EglResult<(i32, i32, bool)> {
    let (mut width, mut height, mut largest) = (0, 0, false);
    for &(name, value) in attribs {
        match name {
            EGL_WIDTH | EGL_HEIGHT if value < 0 => return Err(EGL_BAD_PARAMETER),
            EGL_WIDTH => width = value,
            EGL_HEIGHT => height = value,
            EGL_LARGEST_PBUFFER => largest = value != 0,
            EGL_MIPMAP_TEXTURE => {}
            // No config binds to textures: only "no texture" matches.
            EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET => match value {
                EGL_NO_TEXTURE => {}
                EGL_TEXTURE_RGB | EGL_TEXTURE_RGBA | EGL_TEXTURE_2D => return Err(EGL_BAD_MATCH),
                _ => return Err(EGL_BAD_ATTRIBUTE),
            },
            // Linear RGBA8 only (EGL_VG_COLORSPACE is EGL_COLORSPACE's value too).
            EGL_GL_COLORSPACE | EGL_VG_COLORSPACE => match value {
                EGL_GL_COLORSPACE_LINEAR => {}
                EGL_GL_COLORSPACE_SRGB => return Err(EGL_BAD_MATCH),
                _ => return Err(EGL_BAD_ATTRIBUTE),
            },
            EGL_VG_ALPHA_FORMAT => match value {
                EGL_VG_ALPHA_FORMAT_NONPRE => {}
                _ => return Err(EGL_BAD_MATCH),
            },
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
    }
    if width > MAX_SIZE || height > MAX_SIZE {
        if !largest {
            return Err(EGL_BAD_ALLOC);
        }
        (width, height) = (width.min(MAX_SIZE), height.min(MAX_SIZE));
    }
    Ok((width, height, largest))
}

/// `eglCreatePbufferSurface`: a `EGL_WIDTH` × `EGL_HEIGHT` buffer (0 × 0 by
/// default, as EGL says; such a surface draws into a 1 × 1 buffer nobody sees).
///
/// # Safety
/// `attrib_list` is `NULL` or ends with `EGL_NONE`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePbufferSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    attrib_list: *const EGLint,
) -> EGLSurface {
    call(std::ptr::null_mut(), || {
        let mut egl = egl_state();
        egl.check(dpy)?;
        let config = config_index(config)?;
        // SAFETY: the caller's contract.
        let attribs = unsafe { int_attribs(attrib_list) }?;
        let (width, height, largest) = pbuffer_size(&attribs)?;
        let desc = framebuffer_desc(config, width.max(1) as u32, height.max(1) as u32);
        let fb = Framebuffer::new_multisample_window(desc, framebuffer_samples(config)).map_err(|_| EGL_BAD_ALLOC)?;
        let h = new_handle(TAG_SURFACE);
        let surface = Surface {
            config,
            width,
            height,
            largest,
            mipmap_level: 0,
            fb: Some(fb),
            bound_to: None,
        };
        egl.surfaces.insert(h, Arc::new(Mutex::new(surface)));
        Ok(h as EGLSurface)
    })
}

/// `eglDestroySurface`: the handle becomes invalid at once; a surface bound
/// to a current context keeps its buffer until released.
#[no_mangle]
pub extern "C" fn eglDestroySurface(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    on_display(dpy, EGL_FALSE, |egl| match egl.surfaces.remove(&(surface as usize)) {
        Some(_) => Ok(EGL_TRUE),
        None => Err(EGL_BAD_SURFACE),
    })
}

/// The live surface `surface` (after checking `dpy`).
pub(crate) fn surface_of(dpy: EGLDisplay, surface: EGLSurface) -> EglResult<Arc<Mutex<Surface>>> {
    let egl = egl_state();
    egl.check(dpy)?;
    egl.surfaces.get(&(surface as usize)).cloned().ok_or(EGL_BAD_SURFACE)
}

/// `eglQuerySurface`.
///
/// # Safety
/// `value` is `NULL` (`EGL_BAD_PARAMETER`) or writable.
#[no_mangle]
pub unsafe extern "C" fn eglQuerySurface(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        let s = surface_of(dpy, surface)?;
        let s = lock(&s);
        let v = match attribute {
            EGL_WIDTH => s.width,
            EGL_HEIGHT => s.height,
            EGL_CONFIG_ID => s.config as EGLint + 1,
            EGL_LARGEST_PBUFFER => EGLint::from(s.largest),
            EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET => EGL_NO_TEXTURE,
            EGL_MIPMAP_TEXTURE => EGL_FALSE as EGLint,
            EGL_MIPMAP_LEVEL => s.mipmap_level,
            EGL_RENDER_BUFFER => EGL_BACK_BUFFER,
            EGL_SWAP_BEHAVIOR => EGL_BUFFER_PRESERVED,
            EGL_MULTISAMPLE_RESOLVE => EGL_MULTISAMPLE_RESOLVE_DEFAULT,
            EGL_HORIZONTAL_RESOLUTION | EGL_VERTICAL_RESOLUTION | EGL_PIXEL_ASPECT_RATIO => EGL_UNKNOWN,
            EGL_GL_COLORSPACE | EGL_VG_COLORSPACE => EGL_GL_COLORSPACE_LINEAR,
            EGL_VG_ALPHA_FORMAT => EGL_VG_ALPHA_FORMAT_NONPRE,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        };
        answer(value, v)
    })
}

/// `eglSurfaceAttrib`: `EGL_MIPMAP_LEVEL` is recorded; `EGL_SWAP_BEHAVIOR`
/// and `EGL_MULTISAMPLE_RESOLVE` take their one meaningful value for a pbuffer.
#[no_mangle]
pub extern "C" fn eglSurfaceAttrib(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: EGLint,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        let s = surface_of(dpy, surface)?;
        let mut s = lock(&s);
        match (attribute, value) {
            (EGL_MIPMAP_LEVEL, _) => s.mipmap_level = value,
            (EGL_SWAP_BEHAVIOR, EGL_BUFFER_PRESERVED | EGL_BUFFER_DESTROYED) => {}
            (EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_DEFAULT) => {}
            (EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_BOX) => return Err(EGL_BAD_MATCH),
            (EGL_SWAP_BEHAVIOR | EGL_MULTISAMPLE_RESOLVE, _) => return Err(EGL_BAD_PARAMETER),
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
        Ok(EGL_TRUE)
    })
}

/// `eglSwapBuffers`: `surface` must be bound to this thread's current
/// context (`EGL_BAD_SURFACE` otherwise); a pbuffer keeps its contents.
#[no_mangle]
pub extern "C" fn eglSwapBuffers(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    call(EGL_FALSE, || {
        surface_of(dpy, surface)?;
        let bound_here = with_thread(false, |t| {
            t.current
                .as_ref()
                .is_some_and(|c| c.surface.as_ref().is_some_and(|(h, _)| *h == surface as usize))
        });
        if !bound_here {
            return Err(EGL_BAD_SURFACE);
        }
        Ok(EGL_TRUE)
    })
}

/// `eglSwapInterval`: accepted without effect while a context is current
/// (`EGL_BAD_CONTEXT` otherwise); pbuffers are never presented.
#[no_mangle]
pub extern "C" fn eglSwapInterval(dpy: EGLDisplay, _interval: EGLint) -> EGLBoolean {
    call(EGL_FALSE, || {
        egl_state().check(dpy)?;
        if with_thread(false, |t| t.current.is_none()) {
            return Err(EGL_BAD_CONTEXT);
        }
        Ok(EGL_TRUE)
    })
}
