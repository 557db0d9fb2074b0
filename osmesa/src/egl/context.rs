//! Contexts: `eglCreateContext` with `EGL_KHR_create_context`'s attributes
//! (desktop OpenGL, compatibility profile, up to the version softgl's
//! `GL_VERSION` reports), `eglMakeCurrent` (surfaceless too), the queries of
//! the current state, `eglDestroyContext`.

use super::*;
use crate::state::{current_handle, replace_current, share, with_context, OsContext};

/// The GL version softgl implements: the leading `major.minor` of its `GL_VERSION`.
pub(crate) fn implemented_version() -> (i32, i32) {
    let s = crate::gl::get::VERSION.to_str().unwrap_or("1.0");
    let mut parts = s.split(|c: char| !c.is_ascii_digit()).map(|p| p.parse().unwrap_or(0));
    (parts.next().unwrap_or(1), parts.next().unwrap_or(0))
}

/// Whether `major.minor` names an OpenGL version.
fn is_gl_version((major, minor): (i32, i32)) -> bool {
    match major {
        1 => (0..=5).contains(&minor),
        2 => (0..=1).contains(&minor),
        3 => (0..=3).contains(&minor),
        4 => (0..=6).contains(&minor),
        _ => false,
    }
}

/// The version `attribs` asks for, after checking every attribute
/// (`EGL_KHR_create_context` and EGL 1.5's names).
fn requested_version(attribs: &[(EGLint, EGLint)]) -> EglResult<(i32, i32)> {
    let (mut major, mut minor, mut flags) = (1, 0, 0);
    for &(name, value) in attribs {
        let boolean = || match value {
            0 | 1 => Ok(value != 0),
            _ => Err(EGL_BAD_ATTRIBUTE),
        };
        match name {
            EGL_CONTEXT_MAJOR_VERSION => major = value,
            EGL_CONTEXT_MINOR_VERSION => minor = value,
            EGL_CONTEXT_FLAGS_KHR => {
                let known = EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR
                    | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR
                    | EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
                if value & !known != 0 {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                flags |= value;
            }
            EGL_CONTEXT_OPENGL_DEBUG => {
                boolean()?;
            }
            EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE if boolean()? => {
                flags |= EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR
            }
            EGL_CONTEXT_OPENGL_ROBUST_ACCESS if boolean()? => flags |= EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR,
            EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE | EGL_CONTEXT_OPENGL_ROBUST_ACCESS => {}
            // Profiles matter from GL 3.2 on, which softgl is far below; the
            // mask must still name a profile.
            EGL_CONTEXT_OPENGL_PROFILE_MASK => {
                let known = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT | EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT;
                if value & !known != 0 {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
            }
            EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY => match value {
                EGL_NO_RESET_NOTIFICATION => {}
                // Robustness is not offered.
                EGL_LOSE_CONTEXT_ON_RESET => return Err(EGL_BAD_MATCH),
                _ => return Err(EGL_BAD_ATTRIBUTE),
            },
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
    }
    let version = (major, minor);
    if !is_gl_version(version) || version > implemented_version() {
        return Err(EGL_BAD_MATCH);
    }
    // Forward compatibility exists from GL 3.0; robust access is not offered.
    if flags & (EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR | EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR) != 0 {
        return Err(EGL_BAD_MATCH);
    }
    Ok(version)
}

/// `eglCreateContext`: a desktop OpenGL context (after `eglBindAPI(EGL_OPENGL_API)`,
/// else `EGL_BAD_MATCH`). `share_context` must be `EGL_NO_CONTEXT` or a live
/// context; sharing itself is not implemented (display lists stay per context,
/// as with `OSMesaCreateContextExt`).
///
/// # Safety
/// `attrib_list` is `NULL` or ends with `EGL_NONE`.
#[no_mangle]
pub unsafe extern "C" fn eglCreateContext(
    dpy: EGLDisplay,
    config: EGLConfig,
    share_context: EGLContext,
    attrib_list: *const EGLint,
) -> EGLContext {
    call(std::ptr::null_mut(), || {
        let mut egl = egl_state();
        egl.check(dpy)?;
        let config = config_index(config)?;
        if display::bound_api() != EGL_OPENGL_API {
            return Err(EGL_BAD_MATCH);
        }
        if !share_context.is_null() && !egl.contexts.contains_key(&(share_context as usize)) {
            return Err(EGL_BAD_CONTEXT);
        }
        // SAFETY: the caller's contract.
        let attribs = unsafe { int_attribs(attrib_list) }?;
        let version = requested_version(&attribs)?;
        let c = CONFIGS[config];
        let os = OsContext::with_framebuffer(placeholder(), c.depth, c.stencil);
        let h = new_handle(TAG_CONTEXT);
        egl.contexts.insert(
            h,
            ContextEntry {
                shared: share(os),
                config,
                version,
                current_on: None,
                viewport_set: false,
                surface: None,
            },
        );
        Ok(h as EGLContext)
    })
}

/// `eglDestroyContext`: the handle becomes invalid at once; a context current
/// on some thread lives until released there.
#[no_mangle]
pub extern "C" fn eglDestroyContext(dpy: EGLDisplay, ctx: EGLContext) -> EGLBoolean {
    on_display(dpy, EGL_FALSE, |egl| match egl.contexts.remove(&(ctx as usize)) {
        Some(_) => Ok(EGL_TRUE),
        None => Err(EGL_BAD_CONTEXT),
    })
}

/// This thread's current context handle and surface handle.
fn current_handles() -> Option<(usize, Option<usize>)> {
    with_thread(None, |t| {
        t.current.as_ref().map(|c| (c.ctx, c.surface.as_ref().map(|(h, _)| *h)))
    })
}

/// `eglMakeCurrent`: `ctx` draws into `draw` (which must equal `read`; both
/// `EGL_NO_SURFACE` for surfaceless) on this thread; `EGL_NO_CONTEXT` with no
/// surfaces releases the current context (also after `eglTerminate`).
/// `EGL_BAD_ACCESS` when `ctx` or the surface is current on another thread.
#[no_mangle]
pub extern "C" fn eglMakeCurrent(dpy: EGLDisplay, draw: EGLSurface, read: EGLSurface, ctx: EGLContext) -> EGLBoolean {
    call(EGL_FALSE, || {
        let mut egl = egl_state();
        if dpy as usize != DISPLAY {
            return Err(EGL_BAD_DISPLAY);
        }
        if ctx.is_null() {
            if !draw.is_null() || !read.is_null() {
                return Err(EGL_BAD_MATCH);
            }
            if let Some(cur) = with_thread(None, |t| t.current.take()) {
                release(&mut egl, cur);
            }
            return Ok(EGL_TRUE);
        }
        egl.check(dpy)?;
        let h = ctx as usize;
        let entry = egl.contexts.get(&h).ok_or(EGL_BAD_CONTEXT)?;
        let surface = match (draw.is_null(), read.is_null()) {
            (true, true) => None,
            (false, false) => {
                let s = egl.surfaces.get(&(draw as usize)).ok_or(EGL_BAD_SURFACE)?;
                egl.surfaces.get(&(read as usize)).ok_or(EGL_BAD_SURFACE)?;
                if draw != read {
                    // Separate read surfaces are not supported.
                    return Err(EGL_BAD_MATCH);
                }
                Some((draw as usize, s.clone()))
            }
            _ => return Err(EGL_BAD_MATCH),
        };
        let mine = current_handles();
        let my_ctx = mine.map(|(c, _)| c);
        if entry.current_on.is_some() && my_ctx != Some(h) {
            return Err(EGL_BAD_ACCESS);
        }
        if let Some((_, s)) = &surface {
            if lock(s).bound_to.is_some_and(|c| Some(c) != my_ctx) {
                return Err(EGL_BAD_ACCESS);
            }
        }
        let mut first_size = None;
        let shared = if mine == Some((h, surface.as_ref().map(|(sh, _)| *sh))) {
            // Already bound here (OSMesaMakeCurrent may have taken the slot since).
            egl.contexts.get(&h).ok_or(EGL_BAD_CONTEXT)?.shared.clone()
        } else {
            if let Some(cur) = with_thread(None, |t| t.current.take()) {
                release(&mut egl, cur);
            }
            let entry = egl.contexts.get_mut(&h).ok_or(EGL_BAD_CONTEXT)?;
            entry.current_on = Some(std::thread::current().id());
            let shared = entry.shared.clone();
            if let Some((sh, s)) = &surface {
                let mut s = lock(s);
                // (The placeholder it drew into before is dropped.)
                let swapped = with_context(&shared, |os| s.fb.take().map(|fb| os.swap_framebuffer(fb)));
                swapped.flatten().ok_or(EGL_BAD_ACCESS)?;
                s.bound_to = Some(h);
                entry.surface = Some(*sh);
                if !entry.viewport_set {
                    entry.viewport_set = true;
                    first_size = Some((s.width, s.height));
                }
            }
            with_thread((), |t| {
                t.current = Some(Current {
                    ctx: h,
                    shared: shared.clone(),
                    surface,
                })
            });
            shared
        };
        // An OSMesa context current here stops being current (its caller's
        // buffer gets its last frame, as with OSMesaMakeCurrent).
        if !replace_current(h, shared, |ph| ph & 0xF == 0) {
            return Err(EGL_BAD_ACCESS);
        }
        drop(egl);
        if let Some((w, h)) = first_size {
            // GL sets viewport and scissor to the first surface a context draws into.
            crate::state::with_gl((), |_, gl| {
                let _ = gl.viewport(0, 0, w, h);
                let _ = gl.scissor(0, 0, w, h);
            });
        }
        Ok(EGL_TRUE)
    })
}

/// `eglGetCurrentContext`: this thread's EGL context (`EGL_NO_CONTEXT` also
/// when `OSMesaMakeCurrent` replaced it).
#[no_mangle]
pub extern "C" fn eglGetCurrentContext() -> EGLContext {
    call(std::ptr::null_mut(), || {
        let Some((h, _)) = current_handles() else {
            return Ok(std::ptr::null_mut());
        };
        let in_slot = current_handle() == Some(h);
        Ok(if in_slot { h as EGLContext } else { std::ptr::null_mut() })
    })
}

/// `eglGetCurrentSurface(EGL_DRAW | EGL_READ)`: the surface of this thread's
/// context, or `EGL_NO_SURFACE`.
#[no_mangle]
pub extern "C" fn eglGetCurrentSurface(readdraw: EGLint) -> EGLSurface {
    call(std::ptr::null_mut(), || {
        if readdraw != EGL_DRAW && readdraw != EGL_READ {
            return Err(EGL_BAD_PARAMETER);
        }
        let s = current_handles().and_then(|(_, s)| s).unwrap_or(0);
        Ok(s as EGLSurface)
    })
}

/// `eglGetCurrentDisplay`: the display while this thread has a context.
#[no_mangle]
pub extern "C" fn eglGetCurrentDisplay() -> EGLDisplay {
    call(std::ptr::null_mut(), || {
        Ok(if current_handles().is_some() {
            DISPLAY as EGLDisplay
        } else {
            std::ptr::null_mut()
        })
    })
}

/// `eglQueryContext`: `EGL_CONFIG_ID`, `EGL_CONTEXT_CLIENT_TYPE`,
/// `EGL_CONTEXT_CLIENT_VERSION` (the major version), `EGL_RENDER_BUFFER`.
///
/// # Safety
/// `value` is `NULL` (`EGL_BAD_PARAMETER`) or writable.
#[no_mangle]
pub unsafe extern "C" fn eglQueryContext(
    dpy: EGLDisplay,
    ctx: EGLContext,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        let egl = egl_state();
        egl.check(dpy)?;
        let entry = egl.contexts.get(&(ctx as usize)).ok_or(EGL_BAD_CONTEXT)?;
        let v = match attribute {
            EGL_CONFIG_ID => entry.config as EGLint + 1,
            EGL_CONTEXT_CLIENT_TYPE => EGL_OPENGL_API as EGLint,
            EGL_CONTEXT_CLIENT_VERSION => entry.version.0,
            EGL_RENDER_BUFFER if entry.surface.is_some() => EGL_BACK_BUFFER,
            EGL_RENDER_BUFFER => EGL_NONE,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        };
        answer(value, v)
    })
}
