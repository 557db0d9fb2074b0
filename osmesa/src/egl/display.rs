//! The display and the per-thread calls: getting and initializing the
//! display, its strings, `eglGetError`, `eglBindAPI`, `eglReleaseThread`,
//! `eglGetProcAddress`.

use super::*;
use std::ffi::{c_char, CStr};

/// `eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)`.
const CLIENT_EXTENSIONS: &CStr = c"EGL_EXT_client_extensions EGL_EXT_device_base EGL_EXT_device_enumeration \
    EGL_EXT_device_query EGL_EXT_platform_base EGL_EXT_platform_device EGL_MESA_platform_surfaceless";
/// The display's extensions.
const DISPLAY_EXTENSIONS: &CStr = c"EGL_KHR_create_context EGL_KHR_get_all_proc_addresses EGL_KHR_surfaceless_context";
const VENDOR: &CStr = c"softgl";
const VERSION: &CStr = c"1.5 softgl";
const CLIENT_VERSION: &CStr = c"1.5";
const CLIENT_APIS: &CStr = c"OpenGL";

fn display_handle() -> EGLDisplay {
    DISPLAY as EGLDisplay
}

/// `eglGetDisplay`: the surfaceless display for `EGL_DEFAULT_DISPLAY`;
/// `EGL_NO_DISPLAY` for a native display (there are none on this platform).
#[no_mangle]
pub extern "C" fn eglGetDisplay(display_id: EGLNativeDisplayType) -> EGLDisplay {
    call(std::ptr::null_mut(), || {
        if display_id.is_null() {
            Ok(display_handle())
        } else {
            Err(EGL_BAD_PARAMETER)
        }
    })
}

/// The display for `platform`: `EGL_PLATFORM_SURFACELESS_MESA` with
/// `EGL_DEFAULT_DISPLAY`, or `EGL_PLATFORM_DEVICE_EXT` with the device, and
/// no attributes.
fn platform_display(platform: EGLenum, native: *mut c_void, attribs: &[(EGLint, i64)]) -> EglResult<EGLDisplay> {
    let known = match platform {
        EGL_PLATFORM_SURFACELESS_MESA => native.is_null(),
        EGL_PLATFORM_DEVICE_EXT => native == device_handle(),
        _ => false,
    };
    if !known {
        return Err(EGL_BAD_PARAMETER);
    }
    if !attribs.is_empty() {
        return Err(EGL_BAD_ATTRIBUTE);
    }
    Ok(display_handle())
}

/// `eglGetPlatformDisplay` (EGL 1.5).
///
/// # Safety
/// `attrib_list` is `NULL` or ends with `EGL_NONE`.
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplay(
    platform: EGLenum,
    native_display: *mut c_void,
    attrib_list: *const EGLAttrib,
) -> EGLDisplay {
    call(std::ptr::null_mut(), || {
        // SAFETY: the caller's contract.
        let attribs = unsafe { super::attrib_list(attrib_list, |a: EGLAttrib| a as i64) }?;
        platform_display(platform, native_display, &attribs)
    })
}

/// `eglGetPlatformDisplayEXT` (`EGL_EXT_platform_base`): the same with an `EGLint` list.
///
/// # Safety
/// `attrib_list` is `NULL` or ends with `EGL_NONE`.
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplayEXT(
    platform: EGLenum,
    native_display: *mut c_void,
    attrib_list: *const EGLint,
) -> EGLDisplay {
    call(std::ptr::null_mut(), || {
        // SAFETY: the caller's contract.
        let attribs = unsafe { super::attrib_list(attrib_list, i64::from) }?;
        platform_display(platform, native_display, &attribs)
    })
}

/// `eglInitialize`: EGL 1.5.
///
/// # Safety
/// `major` and `minor` are each `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn eglInitialize(dpy: EGLDisplay, major: *mut EGLint, minor: *mut EGLint) -> EGLBoolean {
    call(EGL_FALSE, || {
        if dpy as usize != DISPLAY {
            return Err(EGL_BAD_DISPLAY);
        }
        egl_state().initialized = true;
        for (p, v) in [(major, 1), (minor, 5)] {
            if !p.is_null() {
                // SAFETY: non-null, writable by the caller's contract.
                unsafe { *p = v };
            }
        }
        Ok(EGL_TRUE)
    })
}

/// `eglTerminate`: every surface and context handle becomes invalid; those
/// current on some thread live until released there.
#[no_mangle]
pub extern "C" fn eglTerminate(dpy: EGLDisplay) -> EGLBoolean {
    call(EGL_FALSE, || {
        if dpy as usize != DISPLAY {
            return Err(EGL_BAD_DISPLAY);
        }
        let mut egl = egl_state();
        egl.initialized = false;
        egl.contexts.clear();
        egl.surfaces.clear();
        Ok(EGL_TRUE)
    })
}

/// `eglQueryString`. With `EGL_NO_DISPLAY`: the client extensions
/// (`EGL_EXTENSIONS`) and version (`EGL_VERSION`).
#[no_mangle]
pub extern "C" fn eglQueryString(dpy: EGLDisplay, name: EGLint) -> *const c_char {
    call(std::ptr::null(), || {
        if dpy.is_null() {
            return match name {
                EGL_EXTENSIONS => Ok(CLIENT_EXTENSIONS.as_ptr()),
                EGL_VERSION => Ok(CLIENT_VERSION.as_ptr()),
                _ => Err(EGL_BAD_DISPLAY),
            };
        }
        egl_state().check(dpy)?;
        let s = match name {
            EGL_VENDOR => VENDOR,
            EGL_VERSION => VERSION,
            EGL_EXTENSIONS => DISPLAY_EXTENSIONS,
            EGL_CLIENT_APIS => CLIENT_APIS,
            _ => return Err(EGL_BAD_PARAMETER),
        };
        Ok(s.as_ptr())
    })
}

/// `eglGetError`: this thread's last error, then `EGL_SUCCESS`.
#[no_mangle]
pub extern "C" fn eglGetError() -> EGLint {
    guard(EGL_SUCCESS, || {
        with_thread(EGL_SUCCESS, |t| std::mem::replace(&mut t.error, EGL_SUCCESS))
    })
}

/// `eglBindAPI`: `EGL_OPENGL_API` only (`EGL_BAD_PARAMETER` for OpenGL ES,
/// OpenVG or another value).
#[no_mangle]
pub extern "C" fn eglBindAPI(api: EGLenum) -> EGLBoolean {
    call(EGL_FALSE, || {
        if api != EGL_OPENGL_API {
            return Err(EGL_BAD_PARAMETER);
        }
        with_thread((), |t| t.api = api);
        Ok(EGL_TRUE)
    })
}

/// `eglQueryAPI`: `EGL_NONE` until `eglBindAPI(EGL_OPENGL_API)` (EGL's
/// initial value when OpenGL ES is not supported).
#[no_mangle]
pub extern "C" fn eglQueryAPI() -> EGLenum {
    call(EGL_NONE as EGLenum, || Ok(bound_api()))
}

/// This thread's bound API (`EGL_NONE` when none).
pub(crate) fn bound_api() -> EGLenum {
    with_thread(EGL_NONE as EGLenum, |t| t.api)
}

/// `eglReleaseThread`: releases this thread's context and returns its EGL
/// state to the initial one.
#[no_mangle]
pub extern "C" fn eglReleaseThread() -> EGLBoolean {
    call(EGL_FALSE, || {
        let cur = with_thread(None, |t| {
            t.api = EGL_NONE as EGLenum;
            t.current.take()
        });
        if let Some(cur) = cur {
            release(&mut egl_state(), cur);
        }
        Ok(EGL_TRUE)
    })
}

/// `eglWaitClient`: softgl's drawing is done when each call returns.
#[no_mangle]
pub extern "C" fn eglWaitClient() -> EGLBoolean {
    call(EGL_FALSE, || Ok(EGL_TRUE))
}

/// `eglWaitGL`: as `eglWaitClient`.
#[no_mangle]
pub extern "C" fn eglWaitGL() -> EGLBoolean {
    eglWaitClient()
}

/// `eglWaitNative`: there is no native renderer.
#[no_mangle]
pub extern "C" fn eglWaitNative(_engine: EGLint) -> EGLBoolean {
    call(EGL_FALSE, || Ok(EGL_TRUE))
}

/// `eglGetProcAddress`: every function this library exports
/// (`EGL_KHR_get_all_proc_addresses`: `egl*` and `gl*`), else `NULL`.
///
/// # Safety
/// `procname` is `NULL` or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn eglGetProcAddress(procname: *const c_char) -> EGLProc {
    if procname.is_null() {
        return None;
    }
    // SAFETY: a NUL-terminated string, by the caller's contract.
    let name = unsafe { CStr::from_ptr(procname) };
    match guard(None, || name.to_str().ok().and_then(egl_proc)) {
        // SAFETY: `p` is the address of an `extern "C"` function of this
        // library; C casts it back to its real signature before calling.
        Some(p) => Some(unsafe { std::mem::transmute::<*const c_void, unsafe extern "C" fn()>(p) }),
        // SAFETY: the same string (OSMesa's lookup answers the gl* names).
        None => unsafe { crate::api::OSMesaGetProcAddress(procname) },
    }
}

/// The address of the `egl*` export called `name`.
fn egl_proc(name: &str) -> Option<*const c_void> {
    let p = match name {
        "eglBindAPI" => eglBindAPI as *const c_void,
        "eglBindTexImage" => eglBindTexImage as *const c_void,
        "eglChooseConfig" => eglChooseConfig as *const c_void,
        "eglClientWaitSync" => eglClientWaitSync as *const c_void,
        "eglCopyBuffers" => eglCopyBuffers as *const c_void,
        "eglCreateContext" => eglCreateContext as *const c_void,
        "eglCreateImage" => eglCreateImage as *const c_void,
        "eglCreatePbufferFromClientBuffer" => eglCreatePbufferFromClientBuffer as *const c_void,
        "eglCreatePbufferSurface" => eglCreatePbufferSurface as *const c_void,
        "eglCreatePixmapSurface" => eglCreatePixmapSurface as *const c_void,
        "eglCreatePlatformPixmapSurface" => eglCreatePlatformPixmapSurface as *const c_void,
        "eglCreatePlatformWindowSurface" => eglCreatePlatformWindowSurface as *const c_void,
        "eglCreateSync" => eglCreateSync as *const c_void,
        "eglCreateWindowSurface" => eglCreateWindowSurface as *const c_void,
        "eglDestroyContext" => eglDestroyContext as *const c_void,
        "eglDestroyImage" => eglDestroyImage as *const c_void,
        "eglDestroySurface" => eglDestroySurface as *const c_void,
        "eglDestroySync" => eglDestroySync as *const c_void,
        "eglGetConfigAttrib" => eglGetConfigAttrib as *const c_void,
        "eglGetConfigs" => eglGetConfigs as *const c_void,
        "eglGetCurrentContext" => eglGetCurrentContext as *const c_void,
        "eglGetCurrentDisplay" => eglGetCurrentDisplay as *const c_void,
        "eglGetCurrentSurface" => eglGetCurrentSurface as *const c_void,
        "eglGetDisplay" => eglGetDisplay as *const c_void,
        "eglGetError" => eglGetError as *const c_void,
        "eglGetPlatformDisplay" => eglGetPlatformDisplay as *const c_void,
        "eglGetPlatformDisplayEXT" => eglGetPlatformDisplayEXT as *const c_void,
        "eglGetProcAddress" => eglGetProcAddress as *const c_void,
        "eglGetSyncAttrib" => eglGetSyncAttrib as *const c_void,
        "eglInitialize" => eglInitialize as *const c_void,
        "eglMakeCurrent" => eglMakeCurrent as *const c_void,
        "eglQueryAPI" => eglQueryAPI as *const c_void,
        "eglQueryContext" => eglQueryContext as *const c_void,
        "eglQueryDeviceAttribEXT" => eglQueryDeviceAttribEXT as *const c_void,
        "eglQueryDevicesEXT" => eglQueryDevicesEXT as *const c_void,
        "eglQueryDeviceStringEXT" => eglQueryDeviceStringEXT as *const c_void,
        "eglQueryDisplayAttribEXT" => eglQueryDisplayAttribEXT as *const c_void,
        "eglQueryString" => eglQueryString as *const c_void,
        "eglQuerySurface" => eglQuerySurface as *const c_void,
        "eglReleaseTexImage" => eglReleaseTexImage as *const c_void,
        "eglReleaseThread" => eglReleaseThread as *const c_void,
        "eglSurfaceAttrib" => eglSurfaceAttrib as *const c_void,
        "eglSwapBuffers" => eglSwapBuffers as *const c_void,
        "eglSwapInterval" => eglSwapInterval as *const c_void,
        "eglTerminate" => eglTerminate as *const c_void,
        "eglWaitClient" => eglWaitClient as *const c_void,
        "eglWaitGL" => eglWaitGL as *const c_void,
        "eglWaitNative" => eglWaitNative as *const c_void,
        "eglWaitSync" => eglWaitSync as *const c_void,
        _ => return None,
    };
    Some(p)
}
