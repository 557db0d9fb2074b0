//! The GLX exports of a `libGL.so.1`, for programs that load this library
//! under that name (piglit's `libpiglitutil_gl` binds these at load time and
//! looks every GL function up with `glXGetProcAddressARB`, even on EGL).
//! There is no X server: the lookups answer, everything else is inert
//! (`NULL`, `False`, no configs).

use std::ffi::{c_char, c_int, c_ulong, c_void};

/// `glXGetProcAddressARB`: every `gl*` function this library exports, else `NULL`.
///
/// # Safety
/// `name` is `NULL` or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddressARB(name: *const u8) -> Option<unsafe extern "C" fn()> {
    // SAFETY: the caller's contract.
    unsafe { crate::api::OSMesaGetProcAddress(name.cast()) }
}

/// `glXGetProcAddress`: as `glXGetProcAddressARB`.
///
/// # Safety
/// `name` is `NULL` or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddress(name: *const u8) -> Option<unsafe extern "C" fn()> {
    // SAFETY: the caller's contract.
    unsafe { glXGetProcAddressARB(name) }
}

/// `glXChooseVisual`: `NULL` (no X visuals).
#[no_mangle]
pub extern "C" fn glXChooseVisual(_dpy: *mut c_void, _screen: c_int, _attrib_list: *mut c_int) -> *mut c_void {
    std::ptr::null_mut()
}

/// `glXCreateContext`: `NULL`.
#[no_mangle]
pub extern "C" fn glXCreateContext(
    _dpy: *mut c_void,
    _vis: *mut c_void,
    _share: *mut c_void,
    _direct: c_int,
) -> *mut c_void {
    std::ptr::null_mut()
}

/// `glXCreateNewContext`: `NULL`.
#[no_mangle]
pub extern "C" fn glXCreateNewContext(
    _dpy: *mut c_void,
    _config: *mut c_void,
    _render_type: c_int,
    _share: *mut c_void,
    _direct: c_int,
) -> *mut c_void {
    std::ptr::null_mut()
}

/// `glXCreatePixmap`: `None` (0).
#[no_mangle]
pub extern "C" fn glXCreatePixmap(
    _dpy: *mut c_void,
    _config: *mut c_void,
    _pixmap: c_ulong,
    _attribs: *const c_int,
) -> c_ulong {
    0
}

/// `glXDestroyContext`: nothing to destroy.
#[no_mangle]
pub extern "C" fn glXDestroyContext(_dpy: *mut c_void, _ctx: *mut c_void) {}

/// `glXGetCurrentContext`: `NULL`.
#[no_mangle]
pub extern "C" fn glXGetCurrentContext() -> *mut c_void {
    std::ptr::null_mut()
}

/// `glXGetCurrentDisplay`: `NULL`.
#[no_mangle]
pub extern "C" fn glXGetCurrentDisplay() -> *mut c_void {
    std::ptr::null_mut()
}

/// `glXGetCurrentDrawable`: `None` (0).
#[no_mangle]
pub extern "C" fn glXGetCurrentDrawable() -> c_ulong {
    0
}

/// `GLX_NO_EXTENSION`: what GLX calls return without a GLX server.
const GLX_NO_EXTENSION: c_int = 3;

/// `glXGetFBConfigAttrib`: `GLX_NO_EXTENSION`.
#[no_mangle]
pub extern "C" fn glXGetFBConfigAttrib(
    _dpy: *mut c_void,
    _config: *mut c_void,
    _attribute: c_int,
    _value: *mut c_int,
) -> c_int {
    GLX_NO_EXTENSION
}

/// `glXGetFBConfigs`: `NULL`, 0 configs.
///
/// # Safety
/// `nelements` is `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigs(_dpy: *mut c_void, _screen: c_int, nelements: *mut c_int) -> *mut c_void {
    if !nelements.is_null() {
        // SAFETY: non-null, writable by the caller's contract.
        unsafe { *nelements = 0 };
    }
    std::ptr::null_mut()
}

/// `glXGetVisualFromFBConfig`: `NULL`.
#[no_mangle]
pub extern "C" fn glXGetVisualFromFBConfig(_dpy: *mut c_void, _config: *mut c_void) -> *mut c_void {
    std::ptr::null_mut()
}

/// `glXMakeCurrent`: `False`.
#[no_mangle]
pub extern "C" fn glXMakeCurrent(_dpy: *mut c_void, _drawable: c_ulong, _ctx: *mut c_void) -> c_int {
    0
}

/// `glXQueryExtension`: `False` (no GLX on any display).
#[no_mangle]
pub extern "C" fn glXQueryExtension(_dpy: *mut c_void, _error_base: *mut c_int, _event_base: *mut c_int) -> c_int {
    0
}

/// `glXQueryExtensionsString`: empty.
#[no_mangle]
pub extern "C" fn glXQueryExtensionsString(_dpy: *mut c_void, _screen: c_int) -> *const c_char {
    c"".as_ptr()
}

/// `glXQueryVersion`: `False`.
#[no_mangle]
pub extern "C" fn glXQueryVersion(_dpy: *mut c_void, _major: *mut c_int, _minor: *mut c_int) -> c_int {
    0
}

/// `glXSwapBuffers`: nothing to present.
#[no_mangle]
pub extern "C" fn glXSwapBuffers(_dpy: *mut c_void, _drawable: c_ulong) {}
