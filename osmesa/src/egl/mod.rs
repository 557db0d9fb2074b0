//! The EGL 1.5 face of the same library: a surfaceless display whose
//! pbuffers and contexts are softgl's, for programs that left OSMesa for EGL
//! (piglit through waffle, PyOpenGL with `PYOPENGL_PLATFORM=egl`).
//!
//! - One display (`eglGetDisplay(EGL_DEFAULT_DISPLAY)`,
//!   `eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY)`
//!   and `eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device)` of the one
//!   device `eglQueryDevicesEXT` lists are the same handle), 24 configs (RGBA8 or RGB8 × 1 or 4 samples × depth 0/16/24 × stencil 0/8,
//!   pbuffers and desktop OpenGL only), pbuffer surfaces whose buffers softgl
//!   owns, desktop GL contexts up to the version `glGetString(GL_VERSION)` reports.
//! - An EGL context *is* an OSMesa context ([`crate::state::OsContext`]):
//!   `eglMakeCurrent` puts it in the same per-thread slot `OSMesaMakeCurrent`
//!   fills, so every `gl*` export of this library draws through it. A pbuffer's
//!   framebuffer moves into the context while bound and back when released.
//! - Handles are numbers tagged by kind (never dereferenced); a destroyed or
//!   foreign handle is an EGL error. Each thread has its own error, bound API
//!   and current context; a thread that exits releases its context.
//! - No panic crosses into C: every export runs under [`crate::state::guard`].
//!
//! Window and pixmap surfaces, syncs and images do not exist on this display:
//! those exports fail with EGL's error for the argument (see `stubs.rs`).
//! `glx.rs` holds the few GLX exports a program linked to `libGL.so.1` binds
//! (`glXGetProcAddressARB` answers; the rest are inert).

mod config;
mod consts;
mod context;
mod device;
mod display;
mod glx;
mod stubs;
mod surface;

pub use config::*;
pub use consts::*;
pub use context::*;
pub use device::*;
pub use display::*;
pub use glx::*;
pub use stubs::*;
pub use surface::*;

use crate::state::{guard, lock, with_context, Shared};
use softgl::Framebuffer;
use std::cell::RefCell;
use std::collections::HashMap;
use std::ffi::c_void;
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};

pub type EGLDisplay = *mut c_void;
pub type EGLConfig = *mut c_void;
pub type EGLSurface = *mut c_void;
pub type EGLContext = *mut c_void;
pub type EGLNativeDisplayType = *mut c_void;
pub type EGLNativeWindowType = usize;
pub type EGLNativePixmapType = usize;
pub type EGLClientBuffer = *mut c_void;
pub type EGLSync = *mut c_void;
pub type EGLImage = *mut c_void;
pub type EGLTime = u64;
/// `__eglMustCastToProperFunctionPointerType`.
pub type EGLProc = Option<unsafe extern "C" fn()>;

/// Handle tags (low 4 bits): a handle of one kind passed as another is refused.
/// OSMesa's context handles have 0 there.
const TAG_DISPLAY: usize = 0x1;
const TAG_CONFIG: usize = 0x2;
const TAG_SURFACE: usize = 0x4;
const TAG_CONTEXT: usize = 0x8;

/// The one display.
const DISPLAY: usize = 1 << 4 | TAG_DISPLAY;

/// A new handle of kind `tag`.
fn new_handle(tag: usize) -> usize {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(1);
    NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed) << 4 | tag
}

/// An EGL error code, as `eglGetError` reports it.
type EglResult<T> = Result<T, EGLint>;

/// A pbuffer surface.
pub(crate) struct Surface {
    /// Index into [`CONFIGS`].
    config: usize,
    width: i32,
    height: i32,
    largest: bool,
    mipmap_level: i32,
    /// The buffer while no context draws into it (it lives in the context then).
    fb: Option<Framebuffer>,
    /// The context this surface is bound to.
    bound_to: Option<usize>,
}

/// A context: the OSMesa context it is, and EGL's facts about it.
pub(crate) struct ContextEntry {
    shared: Shared,
    config: usize,
    version: (i32, i32),
    current_on: Option<std::thread::ThreadId>,
    /// Viewport and scissor are set to the first surface the context draws into.
    viewport_set: bool,
    surface: Option<usize>,
}

/// Everything behind the display.
#[derive(Default)]
pub(crate) struct Egl {
    initialized: bool,
    contexts: HashMap<usize, ContextEntry>,
    surfaces: HashMap<usize, Arc<Mutex<Surface>>>,
}

fn egl_state() -> MutexGuard<'static, Egl> {
    static EGL: OnceLock<Mutex<Egl>> = OnceLock::new();
    lock(EGL.get_or_init(|| Mutex::new(Egl::default())))
}

impl Egl {
    /// Checks `dpy` is the display and is initialized.
    fn check(&self, dpy: EGLDisplay) -> EglResult<()> {
        if dpy as usize != DISPLAY {
            Err(EGL_BAD_DISPLAY)
        } else if !self.initialized {
            Err(EGL_NOT_INITIALIZED)
        } else {
            Ok(())
        }
    }
}

/// A context current on a thread, and the surface it draws into.
pub(crate) struct Current {
    ctx: usize,
    shared: Shared,
    surface: Option<(usize, Arc<Mutex<Surface>>)>,
}

/// A thread's EGL state.
pub(crate) struct Thread {
    error: EGLint,
    api: EGLenum,
    current: Option<Current>,
}

impl Drop for Thread {
    /// A thread that ends releases its context (EGL leaves it current to a
    /// dead thread, where no one could make it current again).
    fn drop(&mut self) {
        if let Some(cur) = self.current.take() {
            guard((), || release(&mut egl_state(), cur));
        }
    }
}

thread_local! {
    static THREAD: RefCell<Thread> = const {
        RefCell::new(Thread { error: EGL_SUCCESS, api: EGL_NONE as EGLenum, current: None })
    };
}

/// Runs `f` on this thread's EGL state (nothing during thread teardown).
fn with_thread<R>(default: R, f: impl FnOnce(&mut Thread) -> R) -> R {
    THREAD.try_with(|t| f(&mut t.borrow_mut())).unwrap_or(default)
}

/// Runs an export's body: its error (or `EGL_SUCCESS`) becomes the thread's
/// error, an error or a panic returns `fail`.
fn call<R: Copy>(fail: R, f: impl FnOnce() -> EglResult<R>) -> R {
    let r = guard(Err(EGL_BAD_ALLOC), f);
    let code = match r {
        Ok(_) => EGL_SUCCESS,
        Err(e) => e,
    };
    with_thread((), |t| t.error = code);
    r.unwrap_or(fail)
}

/// [`call`] with the display checked and its state locked.
fn on_display<R: Copy>(dpy: EGLDisplay, fail: R, f: impl FnOnce(&mut Egl) -> EglResult<R>) -> R {
    call(fail, || {
        let mut egl = egl_state();
        egl.check(dpy)?;
        f(&mut egl)
    })
}

/// Most pairs an attribute list may hold (a longer one lacks its `EGL_NONE`).
const MAX_ATTRIBS: usize = 256;

/// The pairs of an `EGL_NONE`-terminated list (`NULL` is empty).
///
/// # Safety
/// `list` is `NULL` or points to pairs ending with an `EGL_NONE` attribute.
unsafe fn attrib_list<T: Copy>(list: *const T, wide: fn(T) -> i64) -> EglResult<Vec<(EGLint, i64)>> {
    let mut pairs = Vec::new();
    if list.is_null() {
        return Ok(pairs);
    }
    for i in 0..MAX_ATTRIBS {
        // SAFETY: the caller's list holds pairs up to EGL_NONE, which ends the loop.
        let name = wide(unsafe { *list.add(2 * i) });
        if name == i64::from(EGL_NONE) {
            return Ok(pairs);
        }
        // SAFETY: as above: a name other than EGL_NONE is followed by its value.
        let value = wide(unsafe { *list.add(2 * i + 1) });
        pairs.push((name as EGLint, value));
    }
    Err(EGL_BAD_ATTRIBUTE)
}

/// `attrib_list` for `EGLint` lists, values as `EGLint`.
///
/// # Safety
/// As [`attrib_list`].
unsafe fn int_attribs(list: *const EGLint) -> EglResult<Vec<(EGLint, EGLint)>> {
    // SAFETY: the caller's contract.
    let pairs = unsafe { attrib_list(list, i64::from) }?;
    Ok(pairs.into_iter().map(|(n, v)| (n, v as EGLint)).collect())
}

/// A 1×1 buffer for a context with no surface: GL calls work, draw nowhere visible.
/// Writes an attribute query's answer to the caller's `value`:
/// `EGL_BAD_PARAMETER` when it is NULL.
fn answer(value: *mut EGLint, v: EGLint) -> EglResult<EGLBoolean> {
    if value.is_null() {
        return Err(EGL_BAD_PARAMETER);
    }
    // SAFETY: checked non-null; writable by the caller's contract.
    unsafe { *value = v };
    Ok(EGL_TRUE)
}

fn placeholder() -> Framebuffer {
    let desc = softgl::FramebufferDesc {
        width: 1,
        height: 1,
        color: softgl::ColorFormat::Rgba8,
        depth_bits: 0,
        stencil_bits: 0,
    };
    Framebuffer::new(desc).expect("a 1x1 RGBA8 framebuffer is valid")
}

/// Releases `cur` (this thread's current context): its surface gets its
/// buffer back, and the thread's GL slot empties if it still holds it.
fn release(egl: &mut Egl, cur: Current) {
    if let Some(entry) = egl.contexts.get_mut(&cur.ctx) {
        entry.current_on = None;
        entry.surface = None;
    }
    if let Some((_, surface)) = &cur.surface {
        let mut s = lock(surface);
        s.fb = with_context(&cur.shared, |os| os.swap_framebuffer(placeholder())).flatten();
        s.bound_to = None;
    }
    crate::state::clear_current_if(cur.ctx);
}
