//! The OSMesa entry points of `GL/osmesa.h`.

use crate::consts::*;
use crate::convert::UserFormat;
use crate::state::*;
use softgl::framebuffer::DepthBuffer;
use softgl::{Context, Framebuffer, GlError};
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
/// Accumulation bits are accepted and ignored; softgl has no accumulation
/// buffer yet (`glAccum` is `GL_INVALID_OPERATION`). `sharelist` is ignored:
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
        register(OsContext::new(format, depth_bits, stencil_bits)) as OSMesaContext
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
        let h = handle(ctx);
        if unregister(h).is_some() {
            CURRENT.with(|cur| {
                let mut cur = cur.borrow_mut();
                if cur.as_ref().is_some_and(|(c, _)| *c == h) {
                    *cur = None;
                }
            });
        }
    })
}

/// `OSMesaMakeCurrent`: binds `buffer` (`width` × `height` pixels of `format`
/// and `type`) to `ctx` and makes it current on this thread. `GL_FALSE` for a
/// null or unknown context, a null buffer, a size outside `1..=16384` or a
/// format and type Mesa refuses; the current context is then unchanged.
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
        let Some(shared) = lookup(handle(ctx)) else {
            return GL_FALSE;
        };
        let size_ok = |s: i32| (1..=MAX_SIZE).contains(&s);
        if buffer.is_null() || !size_ok(width) || !size_ok(height) {
            return GL_FALSE;
        }
        let mut os = lock(&shared);
        let Some(format) = UserFormat::new(os.format, ty) else {
            return GL_FALSE;
        };
        let binding = Binding {
            ptr: buffer.cast(),
            ty,
            width,
            height,
            format,
        };
        if bind(&mut os, binding).is_err() {
            return GL_FALSE;
        }
        drop(os);
        // Stop the previous context: its caller's buffer gets its last frame.
        // (Its lock is taken after this one's is released: no lock-order cycle.)
        let previous = CURRENT.with(|cur| cur.borrow_mut().take());
        if let Some((h, prev)) = previous {
            if h != handle(ctx) {
                lock(&prev).flush();
            }
        }
        CURRENT.with(|cur| *cur.borrow_mut() = Some((handle(ctx), shared)));
        GL_TRUE
    })
}

/// Points `os` at `binding`, making its GL context at the first call.
fn bind(os: &mut OsContext, binding: Binding) -> Result<(), GlError> {
    let desc = os.desc_for(&binding);
    let len = binding.len(os.row_length);
    let stride = binding.stride(os.row_length);
    let same = os.gl.as_ref().is_some_and(|gl| *gl.framebuffer().desc() == desc);
    let fb = if binding.format.is_direct() {
        // SAFETY: OSMesaMakeCurrent's contract: `buffer` holds the image
        // (`len` bytes for this size and row length) while bound.
        let mem = unsafe { UserMemory::new(binding.ptr, len) };
        if same {
            let gl = os.gl.as_mut().expect("checked above");
            gl.framebuffer_mut().set_color_memory(Box::new(mem), stride, !os.y_up)?;
            None
        } else {
            Some(Framebuffer::with_color_memory(desc, Box::new(mem), stride, !os.y_up)?)
        }
    } else if same && os.binding.is_some_and(|b| !b.format.is_direct()) {
        // softgl's own buffer already: keep it (and depth, stencil).
        None
    } else {
        // Not the previous caller's memory: a buffer of softgl's own.
        Some(Framebuffer::new(desc)?)
    };
    if let Some(fb) = fb {
        match &mut os.gl {
            Some(gl) => {
                gl.replace_framebuffer(fb);
            }
            None => os.gl = Some(Box::new(Context::with_framebuffer(fb))),
        }
    }
    os.binding = Some(binding);
    Ok(())
}

/// `OSMesaGetCurrentContext`: this thread's current context, or `NULL`.
#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        CURRENT.with(|cur| {
            cur.borrow()
                .as_ref()
                .map_or(std::ptr::null_mut(), |(h, _)| *h as OSMesaContext)
        })
    })
}

/// Runs `f` on this thread's current OSMesa context, if any.
fn with_current(f: impl FnOnce(&mut OsContext)) {
    guard((), || {
        CURRENT.with(|cur| {
            if let Some((_, shared)) = cur.borrow().as_ref() {
                f(&mut lock(shared));
            }
        })
    })
}

/// `OSMesaPixelStore(OSMESA_ROW_LENGTH | OSMESA_Y_UP, value)` on the current
/// context. A negative row length, or one shorter than the buffer's width,
/// is `GL_INVALID_VALUE` and changes nothing; an unknown name is `GL_INVALID_ENUM`.
#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: i32, value: i32) {
    with_current(|os| {
        let old = (os.row_length, os.y_up);
        match pname {
            OSMESA_ROW_LENGTH if value >= 0 => os.row_length = value,
            OSMESA_ROW_LENGTH => return os.error(GlError::InvalidValue),
            OSMESA_Y_UP => os.y_up = value != 0,
            _ => return os.error(GlError::InvalidEnum),
        }
        if let Err(e) = os.relayout() {
            (os.row_length, os.y_up) = old;
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
    with_current(|os| {
        let b = os.binding;
        let v = match pname {
            OSMESA_WIDTH => b.map_or(0, |b| b.width),
            OSMESA_HEIGHT => b.map_or(0, |b| b.height),
            OSMESA_FORMAT => os.format as i32,
            OSMESA_TYPE => b.map_or(0, |b| b.ty as i32),
            OSMESA_ROW_LENGTH => os.row_length,
            OSMESA_Y_UP => i32::from(os.y_up),
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

/// `OSMesaGetDepthBuffer`, laid out as Mesa 22's llvmpipe OSMesa does: for
/// 1-16 bits without stencil, 2 bytes per value (Z16); otherwise 4 bytes,
/// Z24 in the low bits and, when the context has a stencil buffer, the
/// stencil in the high byte (Z24S8). Rows bottom-up whatever `OSMESA_Y_UP` says.
/// Without a depth buffer: `GL_FALSE`, the outputs untouched (as Mesa 22). Without stencil the
/// pointer is softgl's live depth buffer; with stencil it is a copy made at
/// this call (and refreshed by `glFlush`/`glFinish`).
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
        let shared = lookup(handle(ctx))?;
        let mut os = lock(&shared);
        depth_pointer(&mut os)
    });
    let Some((w, h, bpv, p)) = r else {
        return GL_FALSE;
    };
    // SAFETY: the caller's output pointers are NULL or writable.
    unsafe {
        put(width, w);
        put(height, h);
        put(bytes_per_value, bpv);
        put(buffer, p);
    }
    GL_TRUE
}

/// Width, height, bytes per value and pointer of `os`'s depth buffer.
pub(crate) fn depth_pointer(os: &mut OsContext) -> Option<(i32, i32, i32, *mut c_void)> {
    refresh_depth_view(os);
    let has_stencil = os.stencil_bits > 0;
    let OsContext { gl, depth_view, .. } = os;
    let fb = gl.as_mut()?.framebuffer_mut();
    let (w, h) = (fb.width() as i32, fb.height() as i32);
    let (bytes, ptr) = if has_stencil {
        (4, depth_view.as_mut_ptr().cast::<c_void>())
    } else {
        match fb.depth_buffer_mut()? {
            DepthBuffer::D24(v) | DepthBuffer::D32(v) => (4, v.as_mut_ptr().cast()),
            DepthBuffer::D16(v) => (2, v.as_mut_ptr().cast()),
        }
    };
    Some((w, h, bytes, ptr))
}

/// Rebuilds the Z24S8 copy of depth and stencil, for contexts with both.
pub(crate) fn refresh_depth_view(os: &mut OsContext) {
    let OsContext { gl, depth_view, .. } = os;
    let Some(fb) = gl.as_deref().map(Context::framebuffer) else {
        return;
    };
    let (Some(depth), Some(stencil)) = (fb.depth_buffer(), fb.stencil_buffer()) else {
        depth_view.clear();
        return;
    };
    let DepthBuffer::D24(d) = depth else {
        return;
    };
    depth_view.clear();
    depth_view.extend(d.iter().zip(stencil).map(|(&z, &s)| z | u32::from(s) << 24));
}

/// `OSMesaGetColorBuffer`: the caller's buffer bound to `ctx`, its size and
/// OSMesa format; `GL_FALSE` and zeros before the first `OSMesaMakeCurrent`.
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
        let shared = lookup(handle(ctx))?;
        let os = lock(&shared);
        os.binding
            .map(|b| (b.width, b.height, os.format as i32, b.ptr.cast::<c_void>()))
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

/// `OSMesaColorClamp`: recorded only. softgl's colour buffers hold unorm
/// values, so colours are always clamped (Mesa leaves float buffers unclamped).
#[no_mangle]
pub extern "C" fn OSMesaColorClamp(enable: u8) {
    with_current(|os| os.clamp = enable != 0)
}

/// `OSMesaPostprocess`: Mesa's gallium post-processing filters do not exist
/// in softgl; the call is accepted and has no effect.
///
/// # Safety
/// `filter` is unused.
#[no_mangle]
pub unsafe extern "C" fn OSMesaPostprocess(_ctx: OSMesaContext, _filter: *const c_char, _enable_value: u32) {}
