//! EGL 1.5 exports for objects this surfaceless display does not have:
//! window and pixmap surfaces, client-buffer pbuffers, texture binding,
//! syncs and images. Each checks its display (and config or surface), then
//! fails with EGL's error for the argument it cannot take; none crashes.

use super::*;

/// Window surfaces: `EGL_NO_SURFACE`, `EGL_BAD_NATIVE_WINDOW` (no native window exists).
fn no_window(dpy: EGLDisplay, config: EGLConfig) -> EglResult<EGLSurface> {
    egl_state().check(dpy)?;
    config_index(config)?;
    Err(EGL_BAD_NATIVE_WINDOW)
}

/// Pixmap surfaces: `EGL_NO_SURFACE`, `EGL_BAD_NATIVE_PIXMAP`.
fn no_pixmap(dpy: EGLDisplay, config: EGLConfig) -> EglResult<EGLSurface> {
    egl_state().check(dpy)?;
    config_index(config)?;
    Err(EGL_BAD_NATIVE_PIXMAP)
}

/// `eglCreateWindowSurface`: `EGL_NO_SURFACE` and `EGL_BAD_NATIVE_WINDOW`.
#[no_mangle]
pub extern "C" fn eglCreateWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _win: EGLNativeWindowType,
    _attrib_list: *const EGLint,
) -> EGLSurface {
    call(std::ptr::null_mut(), || no_window(dpy, config))
}

/// `eglCreatePlatformWindowSurface`: `EGL_NO_SURFACE` and `EGL_BAD_NATIVE_WINDOW`.
#[no_mangle]
pub extern "C" fn eglCreatePlatformWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _native_window: *mut c_void,
    _attrib_list: *const EGLAttrib,
) -> EGLSurface {
    call(std::ptr::null_mut(), || no_window(dpy, config))
}

/// `eglCreatePixmapSurface`: `EGL_NO_SURFACE` and `EGL_BAD_NATIVE_PIXMAP`.
#[no_mangle]
pub extern "C" fn eglCreatePixmapSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _pixmap: EGLNativePixmapType,
    _attrib_list: *const EGLint,
) -> EGLSurface {
    call(std::ptr::null_mut(), || no_pixmap(dpy, config))
}

/// `eglCreatePlatformPixmapSurface`: `EGL_NO_SURFACE` and `EGL_BAD_NATIVE_PIXMAP`.
#[no_mangle]
pub extern "C" fn eglCreatePlatformPixmapSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _native_pixmap: *mut c_void,
    _attrib_list: *const EGLAttrib,
) -> EGLSurface {
    call(std::ptr::null_mut(), || no_pixmap(dpy, config))
}

/// `eglCreatePbufferFromClientBuffer`: no client buffer type (OpenVG images)
/// exists: `EGL_NO_SURFACE` and `EGL_BAD_PARAMETER`.
#[no_mangle]
pub extern "C" fn eglCreatePbufferFromClientBuffer(
    dpy: EGLDisplay,
    _buftype: EGLenum,
    _buffer: EGLClientBuffer,
    config: EGLConfig,
    _attrib_list: *const EGLint,
) -> EGLSurface {
    call(std::ptr::null_mut(), || {
        egl_state().check(dpy)?;
        config_index(config)?;
        Err(EGL_BAD_PARAMETER)
    })
}

/// `eglBindTexImage` and `eglReleaseTexImage`: `EGL_BAD_PARAMETER` for a
/// buffer other than `EGL_BACK_BUFFER`, else `EGL_BAD_MATCH` (no surface has
/// a texture format).
fn tex_image(dpy: EGLDisplay, surface: EGLSurface, buffer: EGLint) -> EglResult<EGLBoolean> {
    surface::surface_of(dpy, surface)?;
    if buffer != EGL_BACK_BUFFER {
        return Err(EGL_BAD_PARAMETER);
    }
    Err(EGL_BAD_MATCH)
}

/// `eglBindTexImage`: see `tex_image`.
#[no_mangle]
pub extern "C" fn eglBindTexImage(dpy: EGLDisplay, surface: EGLSurface, buffer: EGLint) -> EGLBoolean {
    call(EGL_FALSE, || tex_image(dpy, surface, buffer))
}

/// `eglReleaseTexImage`: see `tex_image`.
#[no_mangle]
pub extern "C" fn eglReleaseTexImage(dpy: EGLDisplay, surface: EGLSurface, buffer: EGLint) -> EGLBoolean {
    call(EGL_FALSE, || tex_image(dpy, surface, buffer))
}

/// `eglCopyBuffers`: `EGL_BAD_NATIVE_PIXMAP` (no native pixmap exists).
#[no_mangle]
pub extern "C" fn eglCopyBuffers(dpy: EGLDisplay, surface: EGLSurface, _target: EGLNativePixmapType) -> EGLBoolean {
    call(EGL_FALSE, || {
        surface::surface_of(dpy, surface)?;
        Err(EGL_BAD_NATIVE_PIXMAP)
    })
}

/// Calls on a sync or image: none can exist, so after the display check the
/// object argument is bad (`EGL_BAD_PARAMETER`).
fn no_object<R>(dpy: EGLDisplay) -> EglResult<R> {
    egl_state().check(dpy)?;
    Err(EGL_BAD_PARAMETER)
}

/// `eglCreateSync`: `EGL_NO_SYNC`, `EGL_BAD_PARAMETER` (no sync type is supported).
#[no_mangle]
pub extern "C" fn eglCreateSync(dpy: EGLDisplay, _type: EGLenum, _attrib_list: *const EGLAttrib) -> EGLSync {
    call(std::ptr::null_mut(), || no_object(dpy))
}

/// `eglDestroySync`: `EGL_BAD_PARAMETER`.
#[no_mangle]
pub extern "C" fn eglDestroySync(dpy: EGLDisplay, _sync: EGLSync) -> EGLBoolean {
    call(EGL_FALSE, || no_object(dpy))
}

/// `eglClientWaitSync`: `EGL_FALSE`, `EGL_BAD_PARAMETER`.
#[no_mangle]
pub extern "C" fn eglClientWaitSync(dpy: EGLDisplay, _sync: EGLSync, _flags: EGLint, _timeout: EGLTime) -> EGLint {
    call(EGL_FALSE as EGLint, || no_object(dpy))
}

/// `eglWaitSync`: `EGL_BAD_PARAMETER`.
#[no_mangle]
pub extern "C" fn eglWaitSync(dpy: EGLDisplay, _sync: EGLSync, _flags: EGLint) -> EGLBoolean {
    call(EGL_FALSE, || no_object(dpy))
}

/// `eglGetSyncAttrib`: `EGL_BAD_PARAMETER`.
#[no_mangle]
pub extern "C" fn eglGetSyncAttrib(
    dpy: EGLDisplay,
    _sync: EGLSync,
    _attribute: EGLint,
    _value: *mut EGLAttrib,
) -> EGLBoolean {
    call(EGL_FALSE, || no_object(dpy))
}

/// `eglCreateImage`: `EGL_NO_IMAGE`, `EGL_BAD_PARAMETER` (no image target is supported).
#[no_mangle]
pub extern "C" fn eglCreateImage(
    dpy: EGLDisplay,
    _ctx: EGLContext,
    _target: EGLenum,
    _buffer: EGLClientBuffer,
    _attrib_list: *const EGLAttrib,
) -> EGLImage {
    call(std::ptr::null_mut(), || no_object(dpy))
}

/// `eglDestroyImage`: `EGL_BAD_PARAMETER`.
#[no_mangle]
pub extern "C" fn eglDestroyImage(dpy: EGLDisplay, _image: EGLImage) -> EGLBoolean {
    call(EGL_FALSE, || no_object(dpy))
}
