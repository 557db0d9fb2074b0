//! The OSMesa context behind a handle, the registry of live handles, the
//! current context of each thread, and the guard every export runs under.

use crate::consts::*;
use crate::convert::UserFormat;
use softgl::{ColorMemory, Context, Framebuffer, FramebufferDesc, GlError};
use std::cell::RefCell;
use std::collections::HashMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};

/// Largest buffer side `OSMesaMakeCurrent` takes (Mesa's `OSMESA_MAX_WIDTH`).
pub const MAX_SIZE: i32 = 16384;

/// The caller's colour buffer, as `OSMesaMakeCurrent` gave it.
#[derive(Clone, Copy, Debug)]
pub struct Binding {
    pub ptr: *mut u8,
    pub ty: GLenum,
    pub width: i32,
    pub height: i32,
    pub format: UserFormat,
}

// SAFETY: the pointer is only dereferenced through the context's mutex, by the
// thread on which the context is current, under OSMesa's contract that the
// buffer stays valid while it is bound.
unsafe impl Send for Binding {}

impl Binding {
    /// Bytes from one row of the caller's buffer to the next.
    pub fn stride(&self, row_length: i32) -> usize {
        let pixels = if row_length > 0 { row_length } else { self.width };
        pixels as usize * self.format.bytes_per_pixel()
    }

    /// Bytes of the caller's buffer the image occupies.
    pub fn len(&self, row_length: i32) -> usize {
        self.stride(row_length) * (self.height as usize - 1) + self.width as usize * self.format.bytes_per_pixel()
    }
}

/// The caller's buffer lent to a softgl framebuffer.
pub struct UserMemory {
    ptr: *mut u8,
    len: usize,
}

impl UserMemory {
    /// # Safety
    /// `ptr` must be valid for reads and writes of `len` bytes for as long as
    /// the memory is lent (OSMesa's contract for the buffer of `OSMesaMakeCurrent`).
    pub unsafe fn new(ptr: *mut u8, len: usize) -> UserMemory {
        UserMemory { ptr, len }
    }
}

// SAFETY: see `Binding`; the memory is the caller's, used by one thread at a time.
unsafe impl Send for UserMemory {}

impl ColorMemory for UserMemory {
    fn bytes(&self) -> &[u8] {
        // SAFETY: `new`'s contract: valid for `len` bytes while lent.
        unsafe { std::slice::from_raw_parts(self.ptr, self.len) }
    }

    fn bytes_mut(&mut self) -> &mut [u8] {
        // SAFETY: `new`'s contract; `&mut self` makes this the only view.
        unsafe { std::slice::from_raw_parts_mut(self.ptr, self.len) }
    }
}

/// A client vertex array (`glVertexPointer` and friends).
#[derive(Clone, Copy, Debug)]
pub struct ClientArray {
    pub enabled: bool,
    pub size: i32,
    pub ty: GLenum,
    pub stride: i32,
    pub ptr: *const u8,
}

impl ClientArray {
    pub const fn new(size: i32) -> ClientArray {
        ClientArray {
            enabled: false,
            size,
            ty: GL_FLOAT,
            stride: 0,
            ptr: std::ptr::null(),
        }
    }
}

// SAFETY: the pointer is the caller's, read only while drawing on the thread
// where the context is current, under GL's contract for client arrays.
unsafe impl Send for ClientArray {}

/// `glPixelStore` state for one direction (pack or unpack).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelStore {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    pub row_length: i32,
    pub skip_rows: i32,
    pub skip_pixels: i32,
    pub alignment: i32,
    pub image_height: i32,
    pub skip_images: i32,
}

impl PixelStore {
    pub const DEFAULT: PixelStore = PixelStore {
        swap_bytes: false,
        lsb_first: false,
        row_length: 0,
        skip_rows: 0,
        skip_pixels: 0,
        alignment: 4,
        image_height: 0,
        skip_images: 0,
    };
}

/// Everything an OSMesa handle stands for.
pub struct OsContext {
    /// `OSMESA_RGBA`, …, as created.
    pub format: GLenum,
    pub depth_bits: i32,
    pub stencil_bits: i32,
    /// Made at the first `OSMesaMakeCurrent` (GL sets the viewport then).
    /// Boxed: `with_gl` moves it out for each call, and a pointer moves in
    /// one store where the 464-byte context took memcpy calls (measured:
    /// 60% of a `glColor3f` call before, under callgrind).
    pub gl: Option<Box<Context>>,
    pub binding: Option<Binding>,
    pub row_length: i32,
    pub y_up: bool,
    pub clamp: bool,
    pub vertex: ClientArray,
    pub color: ClientArray,
    pub normal: ClientArray,
    pub tex_coord: ClientArray,
    pub pack: PixelStore,
    pub unpack: PixelStore,
    /// `glHint` targets, in the order of `HINTS`.
    pub hints: [GLenum; 5],
    /// Capabilities accepted but without effect until lighting lands
    /// (`GL_NORMALIZE`, `GL_RESCALE_NORMAL`, `GL_COLOR_MATERIAL`, `GL_AUTO_NORMAL`).
    pub inert_caps: Vec<GLenum>,
    /// Depth and stencil interleaved as Mesa's Z24S8 buffer, handed out by
    /// `OSMesaGetDepthBuffer` when the context has a stencil buffer.
    pub depth_view: Vec<u32>,
    /// `glPushAttrib` and `glPushClientAttrib` stacks.
    pub attrib_stack: Vec<crate::gl::attrib::Saved>,
    pub client_attrib_stack: Vec<crate::gl::attrib::SavedClient>,
    /// Display lists by name, the one being compiled, `glListBase`, and how
    /// deep `glCallList` is nested.
    pub lists: HashMap<u32, Arc<Vec<crate::gl::Cmd>>>,
    pub compiling: Option<crate::gl::lists::Compiling>,
    pub list_base: u32,
    pub call_depth: u32,
}

pub const HINTS: [GLenum; 5] = [
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
];

impl OsContext {
    pub fn new(format: GLenum, depth_bits: i32, stencil_bits: i32) -> OsContext {
        OsContext {
            format,
            depth_bits,
            stencil_bits,
            gl: None,
            binding: None,
            row_length: 0,
            y_up: true,
            clamp: true,
            vertex: ClientArray::new(4),
            color: ClientArray::new(4),
            normal: ClientArray::new(3),
            tex_coord: ClientArray::new(4),
            pack: PixelStore::DEFAULT,
            unpack: PixelStore::DEFAULT,
            hints: [GL_DONT_CARE; 5],
            inert_caps: Vec::new(),
            depth_view: Vec::new(),
            attrib_stack: Vec::new(),
            client_attrib_stack: Vec::new(),
            lists: HashMap::new(),
            compiling: None,
            list_base: 0,
            call_depth: 0,
        }
    }

    /// A context drawing into `fb`, a buffer softgl owns (EGL's pbuffers),
    /// created as an RGBA one with these depth and stencil sizes.
    pub fn with_framebuffer(fb: Framebuffer, depth_bits: i32, stencil_bits: i32) -> OsContext {
        let mut os = OsContext::new(OSMESA_RGBA, depth_bits, stencil_bits);
        os.gl = Some(Box::new(Context::with_framebuffer(fb)));
        os
    }

    /// Draws into `fb` from now on (state kept); the previous framebuffer.
    pub fn swap_framebuffer(&mut self, fb: Framebuffer) -> Option<Framebuffer> {
        match &mut self.gl {
            Some(gl) => Some(gl.replace_framebuffer(fb)),
            None => {
                self.gl = Some(Box::new(Context::with_framebuffer(fb)));
                None
            }
        }
    }

    /// Depth bits of the buffer Mesa's llvmpipe OSMesa makes: Z16 (2 bytes a
    /// value) for 1 to 16 bits without stencil, else Z24 in 32 bits (Z24S8
    /// with stencil), also for 32 (measured: `GL_DEPTH_BITS` says 16 or 24).
    pub fn reported_depth_bits(&self) -> i32 {
        match (self.depth_bits, self.stencil_bits) {
            (0, _) => 0,
            (d, 0) if d <= 16 => 16,
            _ => 24,
        }
    }

    /// The framebuffer this context needs for `binding`.
    pub fn desc_for(&self, binding: &Binding) -> FramebufferDesc {
        FramebufferDesc {
            width: binding.width as u32,
            height: binding.height as u32,
            color: binding.format.render_format(),
            depth_bits: self.reported_depth_bits() as u32,
            stencil_bits: if self.stencil_bits > 0 { 8 } else { 0 },
        }
    }

    /// Records `e` in the GL context, if it has one.
    pub fn error(&mut self, e: GlError) {
        if let Some(gl) = &mut self.gl {
            gl.record_error(e);
        }
    }

    /// Points the framebuffer at the caller's buffer again after a change of
    /// `OSMESA_ROW_LENGTH` or `OSMESA_Y_UP`. `InvalidValue` (and no change)
    /// when the new layout does not fit.
    pub fn relayout(&mut self) -> Result<(), GlError> {
        let (Some(b), Some(gl)) = (self.binding, self.gl.as_mut()) else {
            return Ok(());
        };
        if b.format.is_direct() {
            // SAFETY: the buffer was lent by OSMesaMakeCurrent for this size;
            // `len` covers the rows the layout addresses.
            let mem = unsafe { UserMemory::new(b.ptr, b.len(self.row_length)) };
            gl.framebuffer_mut()
                .set_color_memory(Box::new(mem), b.stride(self.row_length), !self.y_up)?;
        }
        Ok(())
    }

    /// Copies softgl's buffer into the caller's for the converted formats.
    pub fn flush(&mut self) {
        let (Some(b), Some(gl)) = (self.binding, self.gl.as_ref()) else {
            return;
        };
        if b.format.is_direct() {
            return;
        }
        let len = b.len(self.row_length);
        // SAFETY: the buffer bound by OSMesaMakeCurrent holds `len` bytes for
        // this size and row length (OSMesa's contract).
        let dst = unsafe { std::slice::from_raw_parts_mut(b.ptr, len) };
        crate::convert::store(gl.framebuffer(), b.format, dst, b.stride(self.row_length), !self.y_up);
    }
}

/// A live handle's context.
pub type Shared = Arc<Mutex<OsContext>>;

/// Handles C holds, to their contexts. Handles are small integers shifted
/// to look like aligned pointers; they are never dereferenced.
fn registry() -> &'static Mutex<HashMap<usize, Shared>> {
    static REGISTRY: OnceLock<Mutex<HashMap<usize, Shared>>> = OnceLock::new();
    REGISTRY.get_or_init(|| Mutex::new(HashMap::new()))
}

/// A mutex's data even after a panic poisoned it (the state stays usable:
/// every mutation is a plain store).
pub fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// Registers `ctx` and returns its handle.
pub fn register(ctx: OsContext) -> usize {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(1);
    let id = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed) << 4;
    lock(registry()).insert(id, Arc::new(Mutex::new(ctx)));
    id
}

pub fn lookup(handle: usize) -> Option<Shared> {
    lock(registry()).get(&handle).cloned()
}

pub fn unregister(handle: usize) -> Option<Shared> {
    lock(registry()).remove(&handle)
}

thread_local! {
    /// This thread's current context: its handle and the context.
    pub static CURRENT: RefCell<Option<(usize, Shared)>> = const { RefCell::new(None) };
}

/// Runs `f`, returning `default` if it panics: no panic crosses into C.
pub fn guard<R: Copy>(default: R, f: impl FnOnce() -> R) -> R {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(default)
}

/// Runs `f` on this thread's current context (with its GL context made),
/// or returns `default` when there is none, as Mesa ignores such calls.
pub fn with_gl<R: Copy>(default: R, f: impl FnOnce(&mut OsContext, &mut Context) -> R) -> R {
    guard(default, || {
        CURRENT.with(|cur| {
            let cur = cur.borrow();
            let Some((_, shared)) = cur.as_ref() else {
                return default;
            };
            let mut os = lock(shared);
            let Some(mut gl) = os.gl.take() else {
                return default;
            };
            // The GL context is moved out for the call so that `f` can borrow both.
            let r = catch_unwind(AssertUnwindSafe(|| f(&mut os, &mut gl)));
            os.gl = Some(gl);
            r.unwrap_or(default)
        })
    })
}

/// Runs `f` on this thread's current OSMesa context (GL context in place),
/// or returns `default` when there is none.
pub fn with_os<R: Copy>(default: R, f: impl FnOnce(&mut OsContext) -> R) -> R {
    guard(default, || {
        CURRENT.with(|cur| match cur.borrow().as_ref() {
            Some((_, shared)) => f(&mut lock(shared)),
            None => default,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guard_turns_a_panic_into_the_default() {
        assert_eq!(guard(7, || panic!("inside an export")), 7);
        assert_eq!(guard(7, || 3), 3);
    }

    #[test]
    fn with_gl_keeps_the_context_usable_after_a_panic() {
        let h = register(OsContext::new(crate::consts::OSMESA_RGBA, 0, 0));
        let shared = lookup(h).unwrap();
        lock(&shared).gl = Some(Box::new(Context::new(FramebufferDesc::rgba8_d24s8(2, 2)).unwrap()));
        CURRENT.with(|c| *c.borrow_mut() = Some((h, shared.clone())));
        assert_eq!(with_gl(1, |_, _| panic!("in a GL call")), 1);
        assert!(lock(&shared).gl.is_some(), "the GL context is put back");
        assert_eq!(with_gl(0, |_, gl| gl.framebuffer().width()), 2);
        CURRENT.with(|c| *c.borrow_mut() = None);
        unregister(h);
    }
}
