//! The OSMesa entry points of `GL/osmesa.h`.

use crate::consts::*;
use crate::state::*;
use softgl::GlError;
use std::ffi::{c_char, c_void, CStr};

/// `OSMesaContext`: an opaque handle (never dereferenced by either side).
pub type OSMesaContext = *mut c_void;

/// `OSMESAproc`.
pub type OSMesaProc = Option<unsafe extern "C" fn()>;

fn handle(ctx: OSMesaContext) -> usize {
    ctx as usize
}

/// `OSMesaCreateContext(format, sharelist)`: 24 depth and 8 stencil bits, as Mesa's.
#[no_mangle]
pub extern "C" fn OSMesaCreateContext(format: GLenum, sharelist: OSMesaContext) -> OSMesaContext {
    OSMesaCreateContextExt(format, 24, 8, 0, sharelist)
}

/// `OSMesaCreateContextExt`: `NULL` for an unknown format or negative sizes.
/// Any accumulation bits give an RGBA buffer of 16 bits a channel, as
/// Mesa's (`GL_ACCUM_RED_BITS` 16). `sharelist` is ignored:
/// softgl has no shareable objects (textures, display lists) yet.
#[no_mangle]
pub extern "C" fn OSMesaCreateContextExt(
    format: GLenum,
    depth_bits: i32,
    stencil_bits: i32,
    accum_bits: i32,
    _sharelist: OSMesaContext,
) -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        let known = matches!(
            format,
            OSMESA_RGBA | OSMESA_BGRA | OSMESA_ARGB | OSMESA_RGB | OSMESA_BGR | OSMESA_RGB_565
        );
        if !known || depth_bits < 0 || stencil_bits < 0 || accum_bits < 0 {
            return std::ptr::null_mut();
        }
        create_context(format, depth_bits, stencil_bits, accum_bits) as OSMesaContext
    })
}

/// `OSMesaCreateContextAttribs`: a zero-terminated list of pairs. `NULL` for
/// an unknown attribute, the core profile or a version above 1.x.
///
/// # Safety
/// `attrib_list` is `NULL` or points to pairs ending with a 0 attribute.
#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextAttribs(
    attrib_list: *const i32,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    let (mut format, mut depth, mut stencil, mut accum) = (OSMESA_RGBA, 0, 0, 0);
    let mut i = 0;
    while !attrib_list.is_null() {
        // SAFETY: the caller's list holds pairs up to a 0 attribute, which ends the loop.
        let (attr, value) = unsafe { (*attrib_list.add(i), *attrib_list.add(i + 1)) };
        if attr == 0 {
            break;
        }
        match attr {
            OSMESA_FORMAT => format = value as GLenum,
            OSMESA_DEPTH_BITS => depth = value,
            OSMESA_STENCIL_BITS => stencil = value,
            OSMESA_ACCUM_BITS => accum = value,
            OSMESA_PROFILE if value == OSMESA_COMPAT_PROFILE => {}
            OSMESA_CONTEXT_MAJOR_VERSION if value == 1 => {}
            OSMESA_CONTEXT_MINOR_VERSION if (0..=1).contains(&value) => {}
            _ => return std::ptr::null_mut(),
        }
        i += 2;
    }
    OSMesaCreateContextExt(format, depth, stencil, accum, sharelist)
}

/// `OSMesaDestroyContext`: unknown handles are ignored. A context current on
/// this thread stops being current; one current elsewhere stays alive until
/// that thread makes another current.
#[no_mangle]
pub extern "C" fn OSMesaDestroyContext(ctx: OSMesaContext) {
    guard((), || {
        destroy_context(handle(ctx));
    })
}

/// `OSMesaMakeCurrent`: binds `buffer` (`width` × `height` pixels of `format`
/// and `type`) to `ctx` and makes it current on this thread. `GL_FALSE` for an
/// unknown context, a null buffer, a size outside `1..=16384`, a format and
/// type Mesa refuses, or a context current on another thread (GL allows one
/// thread at a time; Mesa lets both race on it); the current context is then
/// unchanged.
/// `OSMesaMakeCurrent(NULL, NULL, …)` releases this thread's current context
/// and returns `GL_TRUE`, as Mesa 22 does (whatever the type and size); a null
/// context with a buffer is `GL_FALSE`.
///
/// # Safety
/// `buffer` must hold `width` × `height` pixels (rows of `OSMESA_ROW_LENGTH`
/// pixels when set) and stay valid while bound, as OSMesa requires.
#[no_mangle]
pub unsafe extern "C" fn OSMesaMakeCurrent(
    ctx: OSMesaContext,
    buffer: *mut c_void,
    ty: GLenum,
    width: i32,
    height: i32,
) -> u8 {
    guard(GL_FALSE, || {
        if ctx.is_null() && buffer.is_null() {
            release_current();
            return GL_TRUE;
        }
        // SAFETY: OSMesaMakeCurrent's contract on `buffer`, passed on.
        match unsafe { make_current(handle(ctx), buffer.cast(), ty, width, height) } {
            Ok(()) => GL_TRUE,
            Err(_) => GL_FALSE,
        }
    })
}

/// `OSMesaGetCurrentContext`: this thread's current context, or `NULL`.
#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        current_handle().map_or(std::ptr::null_mut(), |h| h as OSMesaContext)
    })
}

/// `OSMesaPixelStore(OSMESA_ROW_LENGTH | OSMESA_Y_UP, value)` on the current
/// context. A negative row length, or one shorter than the buffer's width,
/// is `GL_INVALID_VALUE` and changes nothing; an unknown name is `GL_INVALID_ENUM`.
#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: i32, value: i32) {
    with_current((), |os| {
        let (row_length, y_up) = os.layout();
        let layout = match pname {
            OSMESA_ROW_LENGTH => os.set_layout(value, y_up),
            OSMESA_Y_UP => os.set_layout(row_length, value != 0),
            _ => Err(GlError::InvalidEnum),
        };
        if let Err(e) = layout {
            os.error(e);
        }
    })
}

/// `OSMesaGetIntegerv` on the current context; unknown names leave `*value` alone.
///
/// # Safety
/// `value` is `NULL` or points to a writable `GLint`.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: i32, value: *mut i32) {
    if value.is_null() {
        return;
    }
    with_current((), |os| {
        let b = os.binding();
        let (row_length, y_up) = os.layout();
        let v = match pname {
            OSMESA_WIDTH => b.map_or(0, |b| b.width),
            OSMESA_HEIGHT => b.map_or(0, |b| b.height),
            OSMESA_FORMAT => os.format() as i32,
            OSMESA_TYPE => b.map_or(0, |b| b.ty as i32),
            OSMESA_ROW_LENGTH => row_length,
            OSMESA_Y_UP => i32::from(y_up),
            OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => MAX_SIZE,
            _ => return,
        };
        // SAFETY: checked non-null; the caller passes a writable GLint.
        unsafe { *value = v };
    })
}

/// Writes `v` through `p` when it is not null.
///
/// # Safety
/// `p` is `NULL` or writable.
unsafe fn put<T>(p: *mut T, v: T) {
    if !p.is_null() {
        // SAFETY: non-null, and writable by the caller's contract.
        unsafe { *p = v };
    }
}

/// `OSMesaGetDepthBuffer`: the layout of Mesa 22's llvmpipe OSMesa (Z16 for 1-16
/// bits without stencil, else Z24 in 32 bits, Z24S8 with stencil; see
/// `OsContext::depth_buffer`).
/// Without a depth buffer (or before the first `OSMesaMakeCurrent`):
/// `GL_FALSE`, and zeros and `NULL` written to the outputs, as Mesa 22.3.6
/// answers (measured for every depth and stencil size; Mesa itself crashes
/// when asked before the first `OSMesaMakeCurrent`). The same for a context
/// current on another thread: only that thread may touch it then.
///
/// # Safety
/// Each output pointer is `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetDepthBuffer(
    ctx: OSMesaContext,
    width: *mut i32,
    height: *mut i32,
    bytes_per_value: *mut i32,
    buffer: *mut *mut c_void,
) -> u8 {
    let r = guard(None, || {
        with_context(&lookup(handle(ctx))?, OsContext::depth_buffer).flatten()
    });
    let v = r.unwrap_or(DepthView {
        width: 0,
        height: 0,
        bytes_per_value: 0,
        ptr: std::ptr::null_mut(),
    });
    // SAFETY: the caller's output pointers are NULL or writable.
    unsafe {
        put(width, v.width);
        put(height, v.height);
        put(bytes_per_value, v.bytes_per_value);
        put(buffer, v.ptr.cast());
    }
    u8::from(r.is_some())
}

/// `OSMesaGetColorBuffer`: the caller's buffer bound to `ctx`, its size and
/// OSMesa format; `GL_FALSE` and zeros before the first `OSMesaMakeCurrent`
/// and for a context current on another thread.
///
/// # Safety
/// Each output pointer is `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetColorBuffer(
    ctx: OSMesaContext,
    width: *mut i32,
    height: *mut i32,
    format: *mut i32,
    buffer: *mut *mut c_void,
) -> u8 {
    let r = guard(None, || {
        with_context(&lookup(handle(ctx))?, |os| {
            // The buffer is handed out to be read: what was drawn must be in it.
            os.flush();
            os.binding()
                .map(|b| (b.width, b.height, os.format() as i32, b.ptr.cast::<c_void>()))
        })
        .flatten()
    });
    let (w, h, f, p) = r.unwrap_or((0, 0, 0, std::ptr::null_mut()));
    // SAFETY: the caller's output pointers are NULL or writable.
    unsafe {
        put(width, w);
        put(height, h);
        put(format, f);
        put(buffer, p);
    }
    if r.is_some() {
        GL_TRUE
    } else {
        GL_FALSE
    }
}

/// `OSMesaGetProcAddress`: any `gl*` or `OSMesa*` function this library
/// exports, or `NULL`.
///
/// # Safety
/// `name` is `NULL` or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(name: *const c_char) -> OSMesaProc {
    if name.is_null() {
        return None;
    }
    // SAFETY: a NUL-terminated string, by the caller's contract.
    let name = unsafe { CStr::from_ptr(name) };
    guard(None, || {
        let name = name.to_str().ok()?;
        let p = crate::gl::proc_address(name).or_else(|| osmesa_proc(name))?;
        // SAFETY: `p` is the address of an `extern "C"` function of this
        // library; C casts it back to its real signature before calling.
        Some(unsafe { std::mem::transmute::<*const c_void, unsafe extern "C" fn()>(p) })
    })
}

fn osmesa_proc(name: &str) -> Option<*const c_void> {
    let p = match name {
        "OSMesaCreateContext" => OSMesaCreateContext as *const c_void,
        "OSMesaCreateContextExt" => OSMesaCreateContextExt as *const c_void,
        "OSMesaCreateContextAttribs" => OSMesaCreateContextAttribs as *const c_void,
        "OSMesaDestroyContext" => OSMesaDestroyContext as *const c_void,
        "OSMesaMakeCurrent" => OSMesaMakeCurrent as *const c_void,
        "OSMesaGetCurrentContext" => OSMesaGetCurrentContext as *const c_void,
        "OSMesaPixelStore" => OSMesaPixelStore as *const c_void,
        "OSMesaGetIntegerv" => OSMesaGetIntegerv as *const c_void,
        "OSMesaGetDepthBuffer" => OSMesaGetDepthBuffer as *const c_void,
        "OSMesaGetColorBuffer" => OSMesaGetColorBuffer as *const c_void,
        "OSMesaGetProcAddress" => OSMesaGetProcAddress as *const c_void,
        "OSMesaColorClamp" => OSMesaColorClamp as *const c_void,
        "OSMesaPostprocess" => OSMesaPostprocess as *const c_void,
        _ => return None,
    };
    Some(p)
}

/// `OSMesaColorClamp`: recorded, without effect, as in Mesa 22.3.6: fragment
/// colours in a `GL_FLOAT` buffer are unclamped whatever it says (see
/// `OsContext::set_clamp`).
#[no_mangle]
pub extern "C" fn OSMesaColorClamp(enable: u8) {
    with_current((), |os| os.set_clamp(enable != 0))
}

/// `OSMesaPostprocess`: Mesa's gallium post-processing filters do not exist
/// in softgl; the call is accepted and has no effect.
///
/// # Safety
/// `filter` is unused.
#[no_mangle]
pub unsafe extern "C" fn OSMesaPostprocess(_ctx: OSMesaContext, _filter: *const c_char, _enable_value: u32) {}
