//! The OSMesa context behind a handle, the registry of live handles, the
//! current context of each thread, and the guard every export runs under.
//!
//! The API a face of this library (the OSMesa entry points in `api.rs`, or
//! another one over the same contexts) builds on:
//! - [`create_context`] registers a context and returns its handle;
//!   [`destroy_context`] unregisters it (and releases it on this thread);
//! - [`make_current`] binds a caller's colour buffer to a handle and makes it
//!   current on this thread; [`release_current`] leaves none current;
//!   [`current_handle`] names this thread's current context;
//! - [`with_current`] runs a closure on this thread's current [`OsContext`],
//!   [`with_gl`] on its GL state and [`softgl::Context`] (what `gl/*` uses).
//!
//! Every GL entry point reaches its context through [`with_gl`], which hands
//! it the [`GlState`] and the [`Context`], or, for the vertex attribute
//! calls, through [`attrib`]: `gl/*` imports from here and from `gl_state`,
//! never the other way.
//!
//! The threading contract, GL's: a context is current on one thread at a
//! time. A thread holds its current context's lock for as long as the
//! context is current there (taken by the make-current functions, released
//! when another context is made current, at release, and at thread exit),
//! so its GL calls lock nothing: they reach the context through a pointer in
//! a thread-local slot. Making a context current that another thread has
//! current fails ([`MakeCurrentError::InUse`]); other threads reach a
//! context only while it is current nowhere, under its lock, briefly
//! ([`with_context`]: `OSMesaGetColorBuffer`, `OSMesaGetDepthBuffer`,
//! EGL's surface swaps). A context destroyed on another thread while
//! current stays valid here until released: the slot holds its `Arc`.
//!
//! Cost, measured with `osmesa/bench/calls.c` (callgrind, instructions per
//! `glColor3f` call, the benchmark's loop's 11 included): 157 with a
//! thread-local `RefCell`, a `Mutex` lock and `catch_unwind` per call; 57
//! with the lock held while current and a `thread_local!` pointer (its
//! `__tls_get_addr` call and the spills around it took 20); 39 with the
//! pointer in a global while one thread has a context current (`fast`), as
//! [`attrib`] reads it now; Mesa 22's llvmpipe takes 30. In time (10 million
//! calls, median of 5 repetitions, 5 interleaved runs, 2 loaded cores):
//! 24-34 ns before, 4.1-9 ns (median 4.8) after, Mesa 4.6-8 (5.0).

use crate::consts::*;
use crate::convert::UserFormat;
use crate::gl_state::GlState;
use softgl::framebuffer::DepthBuffer;
use softgl::{ColorMemory, Context, Framebuffer, FramebufferDesc, GlError};
use std::cell::{RefCell, RefMut};
use std::collections::HashMap;
use std::mem::ManuallyDrop;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};

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

/// Everything an OSMesa handle stands for.
pub struct OsContext {
    /// `OSMESA_RGBA`, …, as created.
    format: GLenum,
    depth_bits: i32,
    stencil_bits: i32,
    /// Whether accumulation bits were asked for (Mesa then gives RGBA16 snorm).
    accum: bool,
    /// Made at the first `OSMesaMakeCurrent` (GL sets the viewport then).
    /// Boxed: a replaced framebuffer or a moved `OsContext` moves a pointer,
    /// not the 464-byte context (moving it took memcpy calls: 60% of a
    /// `glColor3f` call, under callgrind).
    gl: Option<Box<Context>>,
    /// The GL state softgl's context does not hold (client arrays, lists, …).
    gl_state: GlState,
    binding: Option<Binding>,
    row_length: i32,
    y_up: bool,
    clamp: bool,
    /// Depth and stencil interleaved as Mesa's Z24S8 buffer, handed out by
    /// `OSMesaGetDepthBuffer` when the context has both.
    depth_view: Vec<u32>,
}

/// What [`OsContext::depth_buffer`] hands out: width, height, bytes per value
/// and the first value, as `OSMesaGetDepthBuffer` returns them.
#[derive(Clone, Copy, Debug)]
pub struct DepthView {
    pub width: i32,
    pub height: i32,
    pub bytes_per_value: i32,
    pub ptr: *mut u8,
}

impl OsContext {
    pub fn new(format: GLenum, depth_bits: i32, stencil_bits: i32) -> OsContext {
        OsContext {
            format,
            depth_bits,
            stencil_bits,
            accum: false,
            gl: None,
            gl_state: GlState::default(),
            binding: None,
            row_length: 0,
            y_up: true,
            clamp: false,
            depth_view: Vec::new(),
        }
    }

    /// Gives the framebuffers this context makes an accumulation buffer
    /// (`accumBits` > 0 at creation).
    pub fn set_accum(&mut self, accum: bool) {
        self.accum = accum;
    }

    /// The OSMesa format it was created with.
    pub fn format(&self) -> GLenum {
        self.format
    }

    /// The caller's buffer last bound by [`make_current`], if any.
    pub fn binding(&self) -> Option<Binding> {
        self.binding
    }

    /// `OSMESA_ROW_LENGTH` (0: the buffer's width) and `OSMESA_Y_UP`.
    pub fn layout(&self) -> (i32, bool) {
        (self.row_length, self.y_up)
    }

    /// `OSMesaColorClamp`'s flag.
    /// Records `OSMesaColorClamp`'s flag. It changes nothing, as in Mesa
    /// 22.3.6: its OSMesa framebuffer never counts as a float one, so
    /// `GL_CLAMP_FRAGMENT_COLOR` is ignored there and fragment colours in a
    /// `GL_FLOAT` buffer stay unclamped either way (measured:
    /// `osmesa/tests/c/deep.c`, docs/llvmpipe-facts.md, "Deep colour buffers").
    /// The Rust API's `Context::set_clamp_fragment_color` is GL's clamp.
    pub fn set_clamp(&mut self, clamp: bool) {
        self.clamp = clamp;
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
    fn desc_for(&self, binding: &Binding) -> FramebufferDesc {
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

    /// Sets `OSMESA_ROW_LENGTH` and `OSMESA_Y_UP` and points the framebuffer
    /// at the caller's buffer again. `InvalidValue` (and no change) when the
    /// new layout does not fit: a row length shorter than the buffer's width.
    pub fn set_layout(&mut self, row_length: i32, y_up: bool) -> Result<(), GlError> {
        if row_length < 0 || self.binding.is_some_and(|b| row_length > 0 && row_length < b.width) {
            return Err(GlError::InvalidValue);
        }
        let (Some(b), Some(gl)) = (self.binding, self.gl.as_mut()) else {
            (self.row_length, self.y_up) = (row_length, y_up);
            return Ok(());
        };
        if b.format.is_direct() {
            // SAFETY: the buffer was lent by OSMesaMakeCurrent for this size;
            // `len` covers the rows the layout addresses.
            let mem = unsafe { UserMemory::new(b.ptr, b.len(row_length)) };
            gl.framebuffer_mut()
                .set_color_memory(Box::new(mem), b.stride(row_length), !y_up)?;
        }
        (self.row_length, self.y_up) = (row_length, y_up);
        Ok(())
    }

    /// Points this context at `binding`, making its GL context at the first call.
    fn bind(&mut self, binding: Binding) -> Result<(), GlError> {
        let desc = self.desc_for(&binding);
        let len = binding.len(self.row_length);
        let stride = binding.stride(self.row_length);
        let same = self.gl.as_ref().is_some_and(|gl| *gl.framebuffer_desc() == desc);
        let fb = if binding.format.is_direct() {
            // SAFETY: OSMesaMakeCurrent's contract: `buffer` holds the image
            // (`len` bytes for this size and row length) while bound.
            let mem = unsafe { UserMemory::new(binding.ptr, len) };
            if same {
                let gl = self.gl.as_mut().expect("checked above");
                gl.framebuffer_mut()
                    .set_color_memory(Box::new(mem), stride, !self.y_up)?;
                None
            } else {
                Some(Framebuffer::with_color_memory(desc, Box::new(mem), stride, !self.y_up)?)
            }
        } else if same && self.binding.is_some_and(|b| !b.format.is_direct()) {
            // softgl's own buffer already: keep it (and depth, stencil).
            None
        } else {
            // Not the previous caller's memory: a buffer of softgl's own.
            Some(Framebuffer::new(desc)?)
        };
        if let Some(mut fb) = fb {
            if self.accum {
                fb = fb.with_accum_buffer()?;
            }
            match &mut self.gl {
                Some(gl) => {
                    gl.replace_framebuffer(fb);
                }
                None => self.gl = Some(Box::new(Context::with_framebuffer(fb))),
            }
        }
        self.binding = Some(binding);
        Ok(())
    }

    /// Copies softgl's buffer into the caller's for the converted formats,
    /// and brings the Z24S8 copy of depth and stencil up to date once
    /// `OSMesaGetDepthBuffer` has handed it out (what `glFlush`, `glFinish`
    /// and a change of current context do). A client that never asks for
    /// the depth buffer pays nothing for it: rebuilding the copy was 4 MiB
    /// written at every `glFinish` of a 1024² context.
    pub fn flush(&mut self) {
        // What Mesa's flush ends of its immediate mode (a context switched
        // away from between glBegin and glEnd keeps its primitive open).
        if let Some(gl) = self.gl.as_mut().filter(|gl| !gl.inside_begin()) {
            // Outside glBegin/glEnd it cannot fail.
            let _ = gl.flush();
        }
        if !self.depth_view.is_empty() {
            self.refresh_depth_view();
        }
        let (Some(b), Some(gl)) = (self.binding, self.gl.as_mut()) else {
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

    /// Rebuilds the Z24S8 copy of depth and stencil, for contexts with both;
    /// empties it otherwise.
    fn refresh_depth_view(&mut self) {
        let fb = self.gl.as_deref_mut().map(Context::framebuffer);
        match fb.and_then(|fb| Some((fb.depth_buffer()?, fb.stencil_buffer()?))) {
            Some((DepthBuffer::D24(d), stencil)) => {
                self.depth_view.clear();
                self.depth_view
                    .extend(d.iter().zip(stencil).map(|(&z, &s)| z | u32::from(s) << 24));
            }
            _ => self.depth_view.clear(),
        }
    }

    /// The depth buffer as `OSMesaGetDepthBuffer` hands it out, laid out as
    /// Mesa 22's llvmpipe OSMesa does: for 1-16 bits without stencil 2 bytes a
    /// value (Z16); otherwise 4 bytes, Z24 in the low bits and, with a stencil
    /// buffer, the stencil in the high byte (Z24S8). `None` without a depth
    /// buffer (also with a stencil buffer alone, as Mesa) or before the first
    /// [`make_current`]. The pointer always addresses
    /// `width × height × bytes_per_value` bytes: softgl's live depth buffer
    /// without stencil, the copy made at this call (refreshed by
    /// [`OsContext::flush`]) with it; both stay put until the next
    /// `make_current` with another size or the context's destruction.
    pub fn depth_buffer(&mut self) -> Option<DepthView> {
        self.refresh_depth_view();
        let fb = self.gl.as_mut()?.framebuffer_mut();
        let (width, height) = (fb.width() as i32, fb.height() as i32);
        let n = width as usize * height as usize;
        let has_stencil = fb.has_stencil();
        let (bytes_per_value, ptr, len): (i32, *mut u8, usize) = match fb.depth_buffer_mut()? {
            _ if has_stencil => (4, self.depth_view.as_mut_ptr().cast(), self.depth_view.len()),
            DepthBuffer::D24(v) | DepthBuffer::D32(v) | DepthBuffer::D32F(v) => (4, v.as_mut_ptr().cast(), v.len()),
            DepthBuffer::D16(v) => (2, v.as_mut_ptr().cast(), v.len()),
        };
        // Never a pointer to fewer values than the size says.
        (len == n).then_some(DepthView {
            width,
            height,
            bytes_per_value,
            ptr,
        })
    }
}

/// A live handle's context and whether some thread has it current.
pub struct SharedContext {
    /// Set while a thread has the context current: that thread then holds
    /// `os`'s lock for as long (see [`Current`]), so the flag tells that long
    /// hold from the brief ones of [`with_context`].
    current: AtomicBool,
    os: Mutex<OsContext>,
}

/// A live handle's context, as the registry, EGL and the current slots hold it.
pub type Shared = Arc<SharedContext>;

/// `os` as a context a handle can stand for, current nowhere yet.
pub fn share(os: OsContext) -> Shared {
    Arc::new(SharedContext {
        current: AtomicBool::new(false),
        os: Mutex::new(os),
    })
}

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

/// Registers a new context (`format` one of the OSMesa formats; `depth_bits`
/// and `stencil_bits` as `OSMesaCreateContextExt` takes them) and returns its
/// handle, never 0. `accum_bits` > 0 asks for an accumulation buffer.
pub fn create_context(format: GLenum, depth_bits: i32, stencil_bits: i32, accum_bits: i32) -> usize {
    static NEXT: AtomicUsize = AtomicUsize::new(1);
    let id = NEXT.fetch_add(1, Ordering::Relaxed) << 4;
    let mut ctx = OsContext::new(format, depth_bits, stencil_bits);
    ctx.set_accum(accum_bits > 0);
    lock(registry()).insert(id, share(ctx));
    id
}

/// The context of a live handle.
pub fn lookup(handle: usize) -> Option<Shared> {
    lock(registry()).get(&handle).cloned()
}

/// Unregisters `handle`; a context current on this thread stops being
/// current, one current on another thread lives until that thread makes
/// another current. `false` for an unknown handle.
pub fn destroy_context(handle: usize) -> bool {
    if lock(registry()).remove(&handle).is_none() {
        return false;
    }
    clear_current_if(handle);
    true
}

/// Why [`make_current`] refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MakeCurrentError {
    UnknownContext,
    /// Null buffer, or a side outside `1..=MAX_SIZE`.
    BadBuffer,
    /// A type the context's format does not take (as Mesa refuses it).
    BadType,
    /// softgl could not make the framebuffer (too large, row length too short).
    Framebuffer(GlError),
    /// Current on another thread (GL allows one at a time: GLX's
    /// `BadAccess`, EGL's `EGL_BAD_ACCESS`; Mesa's OSMesa lets both race).
    InUse,
}

/// Binds `buffer` (`width` × `height` pixels of the context's format and
/// `ty`) to `handle` and makes it current on this thread; the previous
/// current context gets its last frame copied out (converted formats). On an
/// error the current context is unchanged.
///
/// # Safety
/// `buffer` holds `width` × `height` pixels (rows of `OSMESA_ROW_LENGTH`
/// pixels when set) and stays valid while it is bound to the context.
pub unsafe fn make_current(
    handle: usize,
    buffer: *mut u8,
    ty: GLenum,
    width: i32,
    height: i32,
) -> Result<(), MakeCurrentError> {
    let shared = lookup(handle).ok_or(MakeCurrentError::UnknownContext)?;
    let size_ok = |s: i32| (1..=MAX_SIZE).contains(&s);
    if buffer.is_null() || !size_ok(width) || !size_ok(height) {
        return Err(MakeCurrentError::BadBuffer);
    }
    let bind = |os: &mut OsContext| {
        let format = UserFormat::new(os.format, ty).ok_or(MakeCurrentError::BadType)?;
        let binding = Binding {
            ptr: buffer,
            ty,
            width,
            height,
            format,
        };
        os.bind(binding).map_err(MakeCurrentError::Framebuffer)
    };
    // Current here already: a new buffer for it, nothing to copy out.
    let again = with_slot(|slot| match slot {
        Some(cur) if Arc::ptr_eq(&cur.shared, &shared) => Some(bind(cur.os())),
        _ => None,
    });
    if let Some(Some(r)) = again {
        return r;
    }
    let mut new = Current::acquire(handle, shared).ok_or(MakeCurrentError::InUse)?;
    // (An error drops `new`, which releases the context again.)
    bind(new.os())?;
    let previous = with_slot(|slot| slot.replace(new)).ok_or(MakeCurrentError::InUse)?;
    // Stop the previous context: its caller's buffer gets its last frame.
    if let Some(mut prev) = previous {
        prev.os().flush();
    }
    Ok(())
}

/// Leaves no context current on this thread; the one that was gets its last
/// frame copied out, as at a switch.
pub fn release_current() {
    if let Some(Some(mut prev)) = with_slot(Option::take) {
        prev.os().flush();
    }
}

/// Makes `shared` (handle `h`) this thread's current context without binding
/// anything (EGL's make-current does its own bookkeeping); nothing changes
/// when it already is. The context it replaces is flushed when
/// `flush_previous(its handle)` says so. `false` (and no change) when
/// another thread has `shared` current.
pub fn replace_current(h: usize, shared: Shared, flush_previous: impl FnOnce(usize) -> bool) -> bool {
    let mine = |slot: &mut Option<Current>| slot.as_ref().is_some_and(|c| Arc::ptr_eq(&c.shared, &shared));
    if with_slot(mine) == Some(true) {
        return true;
    }
    let Some(new) = Current::acquire(h, shared) else {
        return false;
    };
    let Some(previous) = with_slot(|slot| slot.replace(new)) else {
        return false;
    };
    if let Some(mut prev) = previous {
        if flush_previous(prev.handle) {
            prev.os().flush();
        }
    }
    true
}

/// Empties this thread's slot if it holds handle `h` (safe during thread exit).
pub fn clear_current_if(h: usize) {
    let _ = with_slot(|slot| {
        if slot.as_ref().is_some_and(|c| c.handle == h) {
            *slot = None;
        }
    });
}

/// This thread's current context.
pub fn current_handle() -> Option<usize> {
    CURRENT
        .try_with(|slot| slot.try_borrow().ok()?.0.as_ref().map(|c| c.handle))
        .ok()
        .flatten()
}

/// This thread's current context, holding the context's lock for as long as
/// it is current here: GL lets one thread at a time use a context, so the
/// calls on it lock nothing (see the module docs).
struct Current {
    handle: usize,
    /// The locked context. While current it is reached only through this
    /// pointer, taken once from `guard`: by the attribute calls' fast path
    /// (a copy in `FAST`) and by everything else through [`Current::os`].
    os: *mut OsContext,
    /// `shared.os`'s lock. `'static` stands for "while `shared` lives":
    /// [`Drop`] drops it before `shared`.
    guard: ManuallyDrop<MutexGuard<'static, OsContext>>,
    shared: Shared,
}

impl Current {
    /// Takes `shared`'s context for this thread; `None` when another thread
    /// has it current.
    fn acquire(handle: usize, shared: Shared) -> Option<Current> {
        if shared.current.swap(true, Ordering::Acquire) {
            return None;
        }
        // SAFETY: the mutex lives in the `Arc`'s allocation, which never
        // moves and which `Current` keeps alive (`shared`) until after the
        // guard is dropped (first thing in `drop`).
        let mutex: &'static Mutex<OsContext> = unsafe { &*std::ptr::from_ref(&shared.os) };
        // Waits at most for a brief holder (`with_context`): a thread that
        // keeps the lock set `current` first.
        let mut guard = lock(mutex);
        let os: *mut OsContext = &mut *guard;
        Some(Current {
            handle,
            os,
            guard: ManuallyDrop::new(guard),
            shared,
        })
    }

    /// The context. Only in a [`with_slot`] closure (which nulls `FAST`)
    /// or on a `Current` taken out of the slot.
    fn os(&mut self) -> &mut OsContext {
        // SAFETY: `os` points into the data `guard` keeps locked for this
        // thread. The only other way to it is `FAST`, which is null while
        // the slot is borrowed (`with_slot`) and never holds a context taken
        // out of the slot; `&mut self` makes this the only reference now.
        unsafe { &mut *self.os }
    }
}

impl Drop for Current {
    /// Releases the context; also at thread exit, for a thread that ends
    /// with a context current.
    fn drop(&mut self) {
        // No stale fast pointer may outlive the lock.
        if fast::get() == self.os {
            fast::set(std::ptr::null_mut());
        }
        // SAFETY: dropped once, here, and not used after.
        unsafe { ManuallyDrop::drop(&mut self.guard) };
        self.shared.current.store(false, Ordering::Release);
    }
}

thread_local! {
    /// This thread's current context.
    static CURRENT: RefCell<Slot> = const { RefCell::new(Slot(None)) };
}

/// `FAST`, the current context for [`attrib`]: `CURRENT`'s `os`, or null
/// when there is none or `CURRENT` is borrowed (a call on the context is
/// running).
///
/// Each thread keeps it in a `thread_local!` `Cell` (no destructor: always
/// there while the thread runs), which in a shared library costs a
/// `__tls_get_addr` call and the spills around it: 20 of the 57 instructions
/// a `glColor3f` took. So while exactly one thread has a context current —
/// the usual program — that thread also keeps it in `SOLE`, a global, with
/// its thread pointer in `SOLE_TP`; [`get`] compares the running thread's
/// pointer (`fs:0` on x86-64, `tpidr_el0` on AArch64: one instruction) with
/// `SOLE_TP` first. Why a thread that reads its own pointer in `SOLE_TP`
/// finds its own `FAST` in `SOLE`:
/// - `SOLE_TP` is set (to its own pointer) only by a thread whose slot gets
///   a context while no other thread has one (`transition`, under `CLAIMS`),
///   and a thread's slot emptying, here or at its exit, clears its own claim;
/// - so while a thread has a context current no other thread claims; one
///   that gets a context too only clears `SOLE_TP` (never `SOLE`);
/// - `SOLE` is written only by the claimant: at its claim, at its unclaim,
///   and by [`set`] when it finds its pointer in `SOLE_TP` (its own earlier
///   write, or a stale read of it while `SOLE` is still its own).
///
/// Tried and rejected: `FAST` in the static TLS block (initial-exec, as
/// Mesa's current context; `global_asm!` and an `fs`-relative load). It
/// marks the whole library `STATIC_TLS`, and its 9 KB of thread-locals
/// (std's, the JIT's) do not fit the room glibc keeps for libraries loaded
/// later: `dlopen` (PyOpenGL, ctypes) failed with "cannot allocate memory in
/// static TLS block".
mod fast {
    use super::{lock, OsContext};
    use std::cell::Cell;
    use std::sync::atomic::{AtomicPtr, AtomicUsize, Ordering::Relaxed};
    use std::sync::Mutex;

    thread_local! {
        static FAST: Cell<*mut OsContext> = const { Cell::new(std::ptr::null_mut()) };
    }

    /// The sole thread with a current context: its `FAST` and thread pointer.
    static SOLE: AtomicPtr<OsContext> = AtomicPtr::new(std::ptr::null_mut());
    static SOLE_TP: AtomicUsize = AtomicUsize::new(0);
    /// How many threads have a context current; held while claiming.
    static CLAIMS: Mutex<usize> = Mutex::new(0);

    /// The running thread's thread pointer: unique among live threads,
    /// never 0. `None` where it is not read (no `SOLE` there).
    #[inline(always)]
    fn tp() -> Option<usize> {
        #[cfg(all(target_arch = "x86_64", target_os = "linux"))]
        {
            let tp: usize;
            // SAFETY: loads the TCB's self pointer, which the x86-64 TLS
            // ABI keeps at `fs:0` for every thread; touches nothing else.
            unsafe {
                std::arch::asm!("mov {}, qword ptr fs:[0]", out(reg) tp,
                    options(nostack, readonly, preserves_flags));
            }
            Some(tp)
        }
        #[cfg(all(target_arch = "aarch64", target_os = "linux"))]
        {
            let tp: usize;
            // SAFETY: reads the thread pointer register; no memory.
            unsafe {
                std::arch::asm!("mrs {}, tpidr_el0", out(reg) tp, options(nostack, nomem, preserves_flags));
            }
            Some(tp)
        }
        #[cfg(not(all(any(target_arch = "x86_64", target_arch = "aarch64"), target_os = "linux")))]
        {
            None
        }
    }

    /// This thread's `FAST`.
    #[inline(always)]
    pub fn get() -> *mut OsContext {
        if let Some(tp) = tp() {
            if SOLE_TP.load(Relaxed) == tp {
                return SOLE.load(Relaxed);
            }
        }
        FAST.with(Cell::get)
    }

    /// Sets this thread's `FAST` (and `SOLE` when this thread is the claimant).
    pub fn set(p: *mut OsContext) {
        FAST.with(|fast| fast.set(p));
        if tp().is_some_and(|tp| SOLE_TP.load(Relaxed) == tp) {
            SOLE.store(p, Relaxed);
        }
    }

    /// This thread's slot got a context (`current`, with `FAST` = `p`) or
    /// lost it: counts it, and claims `SOLE` when no other thread has one.
    pub fn transition(current: bool, p: *mut OsContext) {
        let Some(me) = tp() else {
            return;
        };
        let mut threads = lock(&CLAIMS);
        if current {
            *threads += 1;
            if *threads == 1 {
                SOLE.store(p, Relaxed);
                SOLE_TP.store(me, Relaxed);
            } else {
                SOLE_TP.store(0, Relaxed);
            }
        } else {
            *threads = threads.saturating_sub(1);
            if SOLE_TP.load(Relaxed) == me {
                SOLE_TP.store(0, Relaxed);
                SOLE.store(std::ptr::null_mut(), Relaxed);
            }
        }
    }
}

/// The borrowed slot (and whether it held a context): `FAST` is null
/// meanwhile and set from the slot again when this drops (after a panic
/// too).
struct SlotBorrow<'a>(RefMut<'a, Slot>, bool);

impl Drop for SlotBorrow<'_> {
    fn drop(&mut self) {
        let os = self.0 .0.as_ref().map_or(std::ptr::null_mut(), |c| c.os);
        fast::set(os);
        if self.0 .0.is_some() != self.1 {
            fast::transition(self.0 .0.is_some(), os);
        }
    }
}

/// A thread's slot: its current context, if any.
struct Slot(Option<Current>);

impl Drop for Slot {
    /// At thread exit: the thread has no context current any more.
    fn drop(&mut self) {
        if self.0.is_some() {
            fast::transition(false, std::ptr::null_mut());
        }
    }
}

/// Runs `f` on this thread's slot, exclusively: an attribute call made
/// meanwhile finds no context (is ignored) and a nested `with_slot` gets
/// `None`, so no two references to the current context ever coexist.
/// `None` also once the slot is gone (thread exit).
fn with_slot<R>(f: impl FnOnce(&mut Option<Current>) -> R) -> Option<R> {
    CURRENT
        .try_with(|slot| {
            let slot = slot.try_borrow_mut().ok()?;
            let had = slot.0.is_some();
            let mut slot = SlotBorrow(slot, had);
            fast::set(std::ptr::null_mut());
            Some(f(&mut slot.0 .0))
        })
        .ok()
        .flatten()
}

/// Runs `f` on `shared`'s context: in place when it is this thread's
/// current one, under its lock when it is current nowhere. `None` when
/// another thread has it current (GL lets one thread at a time use a
/// context) or this thread's is in use (a nested call).
pub fn with_context<R>(shared: &Shared, f: impl FnOnce(&mut OsContext) -> R) -> Option<R> {
    let mut f = Some(f);
    let mine = with_slot(|slot| match slot {
        Some(cur) if Arc::ptr_eq(&cur.shared, shared) => f.take().map(|f| f(cur.os())),
        _ => None,
    });
    if let Some(Some(r)) = mine {
        return Some(r);
    }
    let f = f?;
    if shared.current.load(Ordering::Acquire) {
        return None;
    }
    Some(f(&mut lock(&shared.os)))
}

/// Runs `f`, returning `default` if it panics: no panic crosses into C.
pub fn guard<R: Copy>(default: R, f: impl FnOnce() -> R) -> R {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(default)
}

/// Runs `f` on this thread's current context's GL state and GL context, or
/// returns `default` when there is none (or it was never bound to a buffer),
/// as Mesa ignores such calls. A panic in `f` returns `default` too.
pub fn with_gl<R: Copy>(default: R, f: impl FnOnce(&mut GlState, &mut Context) -> R) -> R {
    with_current(default, |os| match os.gl.as_deref_mut() {
        Some(gl) => f(&mut os.gl_state, gl),
        None => default,
    })
}

/// Runs `f` on this thread's current OSMesa context, or returns `default`
/// when there is none. A panic in `f` returns `default` too.
pub fn with_current<R: Copy>(default: R, f: impl FnOnce(&mut OsContext) -> R) -> R {
    guard(default, || {
        with_slot(|slot| match slot {
            Some(cur) => f(cur.os()),
            None => default,
        })
        .unwrap_or(default)
    })
}

/// The attribute calls' way in (`glColor`, `glVertex`, …): `f` on this
/// thread's current GL context at once, with no lock, no `RefCell` and no
/// unwinding guard. `Some(f)` back while a display list is compiled (the
/// caller records it through [`with_gl`]). Nothing happens without a
/// current context, as in Mesa, or inside another call on it.
///
/// `f` must not panic: a panic here would abort the process (an
/// `extern "C"` function does not unwind). The attribute calls are plain
/// stores into the current attributes and `Vec` pushes (whose only panic,
/// capacity overflow, needs more than the address space).
#[inline(always)]
pub fn attrib<F: FnOnce(&mut Context)>(f: F) -> Option<F> {
    let p = fast::get();
    if p.is_null() {
        return None;
    }
    // SAFETY: a non-null `fast::get()` is this thread's `FAST` (see `fast`
    // for its `SOLE` copy): its current context, whose lock
    // this thread holds (`Current`). It is null while any other reference
    // to that context is live (`with_slot`) and from before the lock is
    // released (`Current::drop`), and `f` cannot reach the slot (it only
    // sees the `Context`): this is the only reference until it returns.
    let os = unsafe { &mut *p };
    if os.gl_state.compiling.is_some() {
        return Some(f);
    }
    if let Some(gl) = os.gl.as_deref_mut() {
        f(gl);
    }
    None
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
        let h = create_context(OSMESA_RGBA, 0, 0, 0);
        let mut buf = vec![0u8; 2 * 2 * 4];
        // SAFETY: `buf` holds 2×2 RGBA pixels and outlives the binding (released below).
        unsafe { make_current(h, buf.as_mut_ptr(), GL_UNSIGNED_BYTE, 2, 2) }.unwrap();
        assert_eq!(with_gl(1, |_, _| panic!("in a GL call")), 1);
        assert_eq!(with_gl(0, |_, gl| gl.framebuffer().width()), 2);
        release_current();
        assert_eq!(current_handle(), None);
        assert!(destroy_context(h));
        assert!(!destroy_context(h), "a handle dies once");
    }

    /// A 2x2 RGBA context current on this thread, drawing into `buf`.
    fn current_2x2(buf: &mut [u8; 16]) -> usize {
        let h = create_context(OSMESA_RGBA, 0, 0, 0);
        // SAFETY: `buf` holds 2x2 RGBA pixels and outlives the binding (the
        // tests release or destroy the context before it goes).
        unsafe { make_current(h, buf.as_mut_ptr(), GL_UNSIGNED_BYTE, 2, 2) }.unwrap();
        h
    }

    fn current_color() -> [f32; 4] {
        with_gl([0.0; 4], |_, gl| gl.current().color.to_array())
    }

    #[test]
    fn an_attribute_call_reaches_only_a_free_current_context() {
        let mut ran = false;
        assert!(attrib(|_: &mut Context| ran = true).is_none());
        assert!(!ran, "no current context: nothing runs");
        let mut buf = [0u8; 16];
        let h = current_2x2(&mut buf);
        assert!(attrib(|gl: &mut Context| gl.color4(0.5, 0.25, 1.0, 1.0)).is_none());
        assert_eq!(current_color(), [0.5, 0.25, 1.0, 1.0]);
        // Inside another call on the context the fast path finds none (two
        // references to the context never coexist): ignored.
        with_gl((), |_, gl| {
            assert!(attrib(|g: &mut Context| g.color4(1.0, 0.0, 0.0, 1.0)).is_none());
            gl.normal3(0.0, 1.0, 0.0);
        });
        assert_eq!(current_color(), [0.5, 0.25, 1.0, 1.0]);
        // After that call (and after a panicking one) the fast path is back.
        assert_eq!(with_gl(1, |_, _| panic!("in a GL call")), 1);
        assert!(attrib(|gl: &mut Context| gl.color4(0.0, 1.0, 0.0, 1.0)).is_none());
        assert_eq!(current_color(), [0.0, 1.0, 0.0, 1.0]);
        // While a list is compiled the call comes back to be recorded.
        let list = crate::gl_state::Compiling {
            name: 1,
            execute: false,
            cmds: Vec::new(),
            run: None,
        };
        with_gl((), |os, _| os.compiling = Some(list));
        assert!(attrib(|gl: &mut Context| gl.color4(1.0, 1.0, 1.0, 1.0)).is_some());
        with_gl((), |os, _| os.compiling = None);
        assert_eq!(current_color(), [0.0, 1.0, 0.0, 1.0]);
        assert!(destroy_context(h));
        assert!(attrib(|_: &mut Context| ran = true).is_none());
        assert!(!ran, "destroyed while current here: released");
    }

    #[test]
    fn a_context_is_current_on_one_thread_at_a_time() {
        let mut buf = [0u8; 16];
        let h = current_2x2(&mut buf);
        attrib(|gl: &mut Context| gl.color4(0.0, 0.0, 1.0, 1.0));
        let shared = lookup(h).unwrap();
        let elsewhere = |shared: Shared| {
            std::thread::spawn(move || {
                let mut other = [0u8; 16];
                // SAFETY: `other` holds 2x2 RGBA pixels; the thread ends
                // (releasing the context) before it goes.
                let made = unsafe { make_current(h, other.as_mut_ptr(), GL_UNSIGNED_BYTE, 2, 2) };
                let seen = with_context(&shared, |os| os.format());
                // Changes the current colour, and ends with the context current.
                attrib(|gl: &mut Context| gl.color4(1.0, 0.0, 0.0, 1.0));
                (made, seen)
            })
            .join()
            .unwrap()
        };
        assert_eq!(elsewhere(shared.clone()), (Err(MakeCurrentError::InUse), None));
        assert_eq!(current_color(), [0.0, 0.0, 1.0, 1.0], "untouched by the other thread");
        assert_eq!(
            with_context(&shared, |os| os.format()),
            Some(OSMESA_RGBA),
            "here: in place"
        );
        release_current();
        assert_eq!(
            with_context(&shared, |os| os.format()),
            Some(OSMESA_RGBA),
            "current nowhere"
        );
        assert_eq!(elsewhere(shared.clone()), (Ok(()), Some(OSMESA_RGBA)));
        // The other thread ended with it current: its end released it.
        // SAFETY: as in `current_2x2`.
        unsafe { make_current(h, buf.as_mut_ptr(), GL_UNSIGNED_BYTE, 2, 2) }.unwrap();
        assert_eq!(current_color(), [1.0, 0.0, 0.0, 1.0], "the other thread's colour");
        release_current();
        assert!(destroy_context(h));
    }
}
