//! The one EGL device (`EGL_EXT_device_enumeration`, `EGL_EXT_device_query`,
//! `EGL_EXT_platform_device`): softgl's CPU renderer, as Mesa lists its
//! software device (`EGL_MESA_device_software`). Programs that pick a device
//! before a display (MuJoCo's `MUJOCO_GL=egl`: `eglQueryDevicesEXT`, then
//! `eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device)`) get the same
//! display as `eglGetDisplay(EGL_DEFAULT_DISPLAY)`.

use super::*;
use std::ffi::{c_char, CStr};

pub type EGLDeviceEXT = *mut c_void;

/// The device's handle: display-tagged, so it is refused as a display.
const DEVICE: usize = 2 << 4 | TAG_DISPLAY;

/// `eglQueryDeviceStringEXT(device, EGL_EXTENSIONS)`, as Mesa's software device.
const DEVICE_EXTENSIONS: &CStr = c"EGL_MESA_device_software";

pub(crate) fn device_handle() -> EGLDeviceEXT {
    DEVICE as EGLDeviceEXT
}

fn check_device(device: EGLDeviceEXT) -> EglResult<()> {
    if device as usize == DEVICE {
        Ok(())
    } else {
        Err(EGL_BAD_DEVICE_EXT)
    }
}

/// `eglQueryDevicesEXT`: the count (1) when `devices` is `NULL`, else the
/// device written to `devices[0]`; `EGL_BAD_PARAMETER` without `num_devices`
/// or with `devices` and `max_devices <= 0` (as Mesa's `_eglQueryDevicesEXT`).
///
/// # Safety
/// `devices` is `NULL` or has room for `max_devices` handles; `num_devices`
/// is `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn eglQueryDevicesEXT(
    max_devices: EGLint,
    devices: *mut EGLDeviceEXT,
    num_devices: *mut EGLint,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        if num_devices.is_null() || (!devices.is_null() && max_devices <= 0) {
            return Err(EGL_BAD_PARAMETER);
        }
        if !devices.is_null() {
            // SAFETY: room for `max_devices` >= 1 handles, by the caller's contract.
            unsafe { *devices = device_handle() };
        }
        answer(num_devices, 1)
    })
}

/// `eglQueryDeviceStringEXT`: the device's extensions; `EGL_BAD_PARAMETER`
/// for another name, `EGL_BAD_DEVICE_EXT` for another device.
#[no_mangle]
pub extern "C" fn eglQueryDeviceStringEXT(device: EGLDeviceEXT, name: EGLint) -> *const c_char {
    call(std::ptr::null(), || {
        check_device(device)?;
        match name {
            EGL_EXTENSIONS => Ok(DEVICE_EXTENSIONS.as_ptr()),
            _ => Err(EGL_BAD_PARAMETER),
        }
    })
}

/// `eglQueryDeviceAttribEXT`: the device has none of the optional attributes
/// (`EGL_BAD_ATTRIBUTE`); `EGL_BAD_DEVICE_EXT` for another device.
#[no_mangle]
pub extern "C" fn eglQueryDeviceAttribEXT(
    device: EGLDeviceEXT,
    _attribute: EGLint,
    _value: *mut EGLAttrib,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        check_device(device)?;
        Err(EGL_BAD_ATTRIBUTE)
    })
}

/// `eglQueryDisplayAttribEXT`: `EGL_DEVICE_EXT` is the device; another
/// attribute is `EGL_BAD_ATTRIBUTE`.
///
/// # Safety
/// `value` is `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn eglQueryDisplayAttribEXT(
    dpy: EGLDisplay,
    attribute: EGLint,
    value: *mut EGLAttrib,
) -> EGLBoolean {
    on_display(dpy, EGL_FALSE, |_| {
        if attribute != EGL_DEVICE_EXT {
            return Err(EGL_BAD_ATTRIBUTE);
        }
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: checked non-null; writable by the caller's contract.
        unsafe { *value = DEVICE as EGLAttrib };
        Ok(EGL_TRUE)
    })
}
