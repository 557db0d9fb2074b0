//! The EGL face called from Rust, in-process: EGL's error code for every bad
//! argument, config choice and order, pbuffers with exact pixels, surfaceless
//! contexts, contexts on several threads, `eglTerminate`, proc addresses.
//!
//! Each test runs on its own thread (its own EGL error, API and current
//! context); the display is shared, so the one test that terminates it takes
//! `DISPLAY` for writing and the others for reading.

use std::ffi::{c_void, CStr};
use std::ptr::{null, null_mut};
use std::sync::{Arc, Barrier, RwLock, RwLockReadGuard};
use OSMesa::consts::OSMESA_RGBA;
use OSMesa::egl::*;
use OSMesa::*;

const GL_COLOR_BUFFER_BIT: u32 = 0x4000;
const GL_SCISSOR_TEST: u32 = 0x0C11;
const GL_VIEWPORT: u32 = 0x0BA2;
const GL_SCISSOR_BOX: u32 = 0x0C10;
const GL_RGBA: u32 = 0x1908;
const GL_UNSIGNED_BYTE: u32 = 0x1401;
const GL_VERSION: u32 = 0x1F02;
const GL_DEPTH_BITS: u32 = 0x0D56;
const GL_STENCIL_BITS: u32 = 0x0D57;
const GL_TRIANGLES: u32 = 4;

static DISPLAY: RwLock<()> = RwLock::new(());

/// The initialized display, held for reading, and this thread bound to OpenGL.
fn display() -> (EGLDisplay, RwLockReadGuard<'static, ()>) {
    let guard = DISPLAY.read().unwrap_or_else(|e| e.into_inner());
    let d = eglGetDisplay(null_mut());
    assert!(!d.is_null());
    // SAFETY: null outputs are allowed.
    assert_eq!(unsafe { eglInitialize(d, null_mut(), null_mut()) }, EGL_TRUE);
    assert_eq!(eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
    (d, guard)
}

/// Attribute list with its `EGL_NONE`.
fn attribs(pairs: &[(EGLint, EGLint)]) -> Vec<EGLint> {
    pairs.iter().flat_map(|&(n, v)| [n, v]).chain([EGL_NONE]).collect()
}

/// The configs `pairs` choose, as config ids.
fn choose(d: EGLDisplay, pairs: &[(EGLint, EGLint)]) -> Vec<EGLint> {
    let list = attribs(pairs);
    let mut configs = [null_mut(); 32];
    let mut n = -1;
    // SAFETY: the list ends with EGL_NONE; room for 16 handles.
    let ok = unsafe { eglChooseConfig(d, list.as_ptr(), configs.as_mut_ptr(), 32, &mut n) };
    assert_eq!(ok, EGL_TRUE, "error {:#x}", eglGetError());
    configs[..n as usize]
        .iter()
        .map(|&c| config_attr(d, c, EGL_CONFIG_ID))
        .collect()
}

fn config_attr(d: EGLDisplay, c: EGLConfig, name: EGLint) -> EGLint {
    let mut v = -7;
    // SAFETY: `v` is writable.
    assert_eq!(unsafe { eglGetConfigAttrib(d, c, name, &mut v) }, EGL_TRUE);
    v
}

/// The config with `depth` and `stencil` bits.
fn config(d: EGLDisplay, depth: EGLint, stencil: EGLint) -> EGLConfig {
    let list = attribs(&[
        (EGL_SURFACE_TYPE, EGL_PBUFFER_BIT),
        (EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT),
        (EGL_ALPHA_SIZE, 8),
        (EGL_DEPTH_SIZE, depth),
        (EGL_STENCIL_SIZE, stencil),
    ]);
    let mut c = null_mut();
    let mut n = 0;
    // SAFETY: the list ends with EGL_NONE; room for 1 handle.
    assert_eq!(
        unsafe { eglChooseConfig(d, list.as_ptr(), &mut c, 1, &mut n) },
        EGL_TRUE
    );
    assert_eq!(n, 1);
    assert_eq!(config_attr(d, c, EGL_DEPTH_SIZE), depth);
    c
}

fn pbuffer(d: EGLDisplay, c: EGLConfig, w: EGLint, h: EGLint) -> EGLSurface {
    let list = attribs(&[(EGL_WIDTH, w), (EGL_HEIGHT, h)]);
    // SAFETY: the list ends with EGL_NONE.
    let s = unsafe { eglCreatePbufferSurface(d, c, list.as_ptr()) };
    assert!(!s.is_null(), "error {:#x}", eglGetError());
    s
}

fn context(d: EGLDisplay, c: EGLConfig, pairs: &[(EGLint, EGLint)]) -> EGLContext {
    let list = attribs(pairs);
    // SAFETY: the list ends with EGL_NONE.
    unsafe { eglCreateContext(d, c, null_mut(), list.as_ptr()) }
}

/// Asserts `r` is the failure value and the thread's error is `code`.
#[track_caller]
fn fails<T: PartialEq + std::fmt::Debug>(r: T, fail: T, code: EGLint) {
    assert_eq!(r, fail);
    assert_eq!(eglGetError(), code, "expected {code:#x}");
}

fn read_rgba(w: i32, h: i32) -> Vec<u8> {
    let mut px = vec![0u8; (w * h * 4) as usize];
    // SAFETY: room for w × h RGBA bytes (pack alignment 4 divides a row).
    unsafe { glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px.as_mut_ptr().cast()) };
    px
}

fn ints(pname: u32) -> [i32; 4] {
    let mut v = [0; 4];
    // SAFETY: room for 4 values.
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v
}

fn version_string() -> String {
    let p = glGetString(GL_VERSION);
    assert!(!p.is_null());
    // SAFETY: glGetString returns a NUL-terminated static string.
    unsafe { CStr::from_ptr(p.cast()) }.to_string_lossy().into_owned()
}

#[test]
fn displays_and_strings() {
    let (d, _g) = display();
    // SAFETY: a null attribute list is allowed.
    let p = unsafe { eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, null_mut(), null()) };
    assert_eq!(p, d, "one display for both ways in");
    let s = |dpy, name| {
        let p = eglQueryString(dpy, name);
        assert!(!p.is_null(), "string {name:#x}");
        // SAFETY: a NUL-terminated static string.
        unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_string()
    };
    assert!(s(null_mut(), EGL_EXTENSIONS)
        .split(' ')
        .any(|e| e == "EGL_MESA_platform_surfaceless"));
    assert_eq!(s(d, EGL_CLIENT_APIS), "OpenGL");
    assert!(s(d, EGL_VERSION).starts_with("1.5"));
    let ext = s(d, EGL_EXTENSIONS);
    for e in ["EGL_KHR_create_context", "EGL_KHR_surfaceless_context"] {
        assert!(ext.split(' ').any(|x| x == e), "{e} in {ext}");
    }
    let (mut major, mut minor) = (0, 0);
    // SAFETY: writable outputs.
    assert_eq!(unsafe { eglInitialize(d, &mut major, &mut minor) }, EGL_TRUE);
    assert_eq!((major, minor), (1, 5));
    assert_eq!(eglQueryAPI(), EGL_OPENGL_API);
}

#[test]
fn every_bad_argument_has_its_egl_error() {
    let (d, _g) = display();
    let bogus = 0x1230 as *mut c_void;
    let none = attribs(&[]);
    let c = config(d, 24, 8);
    let (mut v, mut n) = (0, 0);
    let mut cfg = null_mut();

    // Displays.
    fails(eglGetDisplay(bogus), null_mut(), EGL_BAD_PARAMETER);
    // SAFETY (this block and the calls below): every list ends with EGL_NONE,
    // every output pointer is writable or deliberately null.
    unsafe {
        fails(
            eglGetPlatformDisplay(0x31D5, null_mut(), null()),
            null_mut(),
            EGL_BAD_PARAMETER,
        );
        fails(
            eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, bogus, null()),
            null_mut(),
            EGL_BAD_PARAMETER,
        );
        let a: [EGLAttrib; 3] = [0x3131, 1, EGL_NONE as EGLAttrib];
        fails(
            eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, null_mut(), a.as_ptr()),
            null_mut(),
            EGL_BAD_ATTRIBUTE,
        );
        fails(eglInitialize(bogus, null_mut(), null_mut()), EGL_FALSE, EGL_BAD_DISPLAY);
        fails(eglTerminate(bogus), EGL_FALSE, EGL_BAD_DISPLAY);
        fails(eglQueryString(null_mut(), EGL_VENDOR), null(), EGL_BAD_DISPLAY);
        fails(eglQueryString(bogus, EGL_VENDOR), null(), EGL_BAD_DISPLAY);
        fails(eglQueryString(d, 0x1234), null(), EGL_BAD_PARAMETER);
        fails(eglBindAPI(EGL_OPENGL_ES_API), EGL_FALSE, EGL_BAD_PARAMETER);
        fails(eglBindAPI(EGL_OPENVG_API), EGL_FALSE, EGL_BAD_PARAMETER);
        assert_eq!(eglQueryAPI(), EGL_OPENGL_API, "a refused API changes nothing");

        // Configs.
        fails(eglGetConfigs(bogus, null_mut(), 0, &mut n), EGL_FALSE, EGL_BAD_DISPLAY);
        fails(
            eglGetConfigs(d, null_mut(), 0, null_mut()),
            EGL_FALSE,
            EGL_BAD_PARAMETER,
        );
        let mut choose_fails = |pairs: &[(EGLint, EGLint)], code| {
            let l = attribs(pairs);
            fails(eglChooseConfig(d, l.as_ptr(), &mut cfg, 1, &mut n), EGL_FALSE, code);
        };
        choose_fails(&[(0x1234, 1)], EGL_BAD_ATTRIBUTE);
        choose_fails(&[(EGL_COLOR_BUFFER_TYPE, 5)], EGL_BAD_ATTRIBUTE);
        choose_fails(&[(EGL_DEPTH_SIZE, -5)], EGL_BAD_ATTRIBUTE);
        choose_fails(&[(EGL_NATIVE_RENDERABLE, 2)], EGL_BAD_ATTRIBUTE);
        choose_fails(&[(EGL_MATCH_NATIVE_PIXMAP, 77)], EGL_BAD_NATIVE_PIXMAP);
        fails(
            eglChooseConfig(d, none.as_ptr(), &mut cfg, 1, null_mut()),
            EGL_FALSE,
            EGL_BAD_PARAMETER,
        );
        fails(
            eglGetConfigAttrib(d, bogus, EGL_DEPTH_SIZE, &mut v),
            EGL_FALSE,
            EGL_BAD_CONFIG,
        );
        fails(
            eglGetConfigAttrib(d, null_mut(), EGL_DEPTH_SIZE, &mut v),
            EGL_FALSE,
            EGL_BAD_CONFIG,
        );
        fails(eglGetConfigAttrib(d, c, 0x1234, &mut v), EGL_FALSE, EGL_BAD_ATTRIBUTE);
        fails(
            eglGetConfigAttrib(d, c, EGL_DEPTH_SIZE, null_mut()),
            EGL_FALSE,
            EGL_BAD_PARAMETER,
        );

        // Surfaces.
        let pbuffer_fails = |config, pairs: &[(EGLint, EGLint)], code| {
            let l = attribs(pairs);
            fails(eglCreatePbufferSurface(d, config, l.as_ptr()), null_mut(), code);
        };
        pbuffer_fails(bogus, &[], EGL_BAD_CONFIG);
        pbuffer_fails(c, &[(EGL_WIDTH, -1)], EGL_BAD_PARAMETER);
        pbuffer_fails(c, &[(0x1234, 1)], EGL_BAD_ATTRIBUTE);
        pbuffer_fails(c, &[(EGL_TEXTURE_FORMAT, 0x305E)], EGL_BAD_MATCH);
        pbuffer_fails(c, &[(EGL_WIDTH, 16385)], EGL_BAD_ALLOC);
        fails(
            eglCreatePbufferSurface(bogus, c, none.as_ptr()),
            null_mut(),
            EGL_BAD_DISPLAY,
        );
        fails(
            eglCreateWindowSurface(d, c, 5, none.as_ptr()),
            null_mut(),
            EGL_BAD_NATIVE_WINDOW,
        );
        fails(
            eglCreatePlatformWindowSurface(d, c, bogus, null()),
            null_mut(),
            EGL_BAD_NATIVE_WINDOW,
        );
        fails(
            eglCreateWindowSurface(d, bogus, 5, none.as_ptr()),
            null_mut(),
            EGL_BAD_CONFIG,
        );
        fails(
            eglCreatePixmapSurface(d, c, 5, none.as_ptr()),
            null_mut(),
            EGL_BAD_NATIVE_PIXMAP,
        );
        fails(
            eglCreatePbufferFromClientBuffer(d, 0x3096, bogus, c, none.as_ptr()),
            null_mut(),
            EGL_BAD_PARAMETER,
        );
        let s = pbuffer(d, c, 4, 4);
        fails(eglQuerySurface(d, bogus, EGL_WIDTH, &mut v), EGL_FALSE, EGL_BAD_SURFACE);
        fails(eglQuerySurface(d, s, 0x1234, &mut v), EGL_FALSE, EGL_BAD_ATTRIBUTE);
        fails(
            eglQuerySurface(d, s, EGL_WIDTH, null_mut()),
            EGL_FALSE,
            EGL_BAD_PARAMETER,
        );
        fails(eglSurfaceAttrib(d, s, 0x1234, 0), EGL_FALSE, EGL_BAD_ATTRIBUTE);
        fails(eglSwapBuffers(d, s), EGL_FALSE, EGL_BAD_SURFACE);
        fails(eglBindTexImage(d, s, EGL_BACK_BUFFER), EGL_FALSE, EGL_BAD_MATCH);
        fails(eglSwapInterval(d, 1), EGL_FALSE, EGL_BAD_CONTEXT);
        fails(eglGetCurrentSurface(0x1234), null_mut(), EGL_BAD_PARAMETER);

        // Contexts.
        fails(context(d, bogus, &[]), null_mut(), EGL_BAD_CONFIG);
        fails(
            context(d, c, &[(EGL_CONTEXT_MAJOR_VERSION, 2), (EGL_CONTEXT_MINOR_VERSION, 0)]),
            null_mut(),
            EGL_BAD_MATCH,
        );
        fails(
            context(d, c, &[(EGL_CONTEXT_MAJOR_VERSION, 3), (EGL_CONTEXT_MINOR_VERSION, 3)]),
            null_mut(),
            EGL_BAD_MATCH,
        );
        fails(
            context(d, c, &[(EGL_CONTEXT_MINOR_VERSION, 7)]),
            null_mut(),
            EGL_BAD_MATCH,
        );
        fails(context(d, c, &[(EGL_CONTEXT_FLAGS_KHR, 2)]), null_mut(), EGL_BAD_MATCH);
        fails(
            context(d, c, &[(EGL_CONTEXT_FLAGS_KHR, 0x40)]),
            null_mut(),
            EGL_BAD_ATTRIBUTE,
        );
        fails(
            context(d, c, &[(EGL_CONTEXT_OPENGL_PROFILE_MASK, 4)]),
            null_mut(),
            EGL_BAD_ATTRIBUTE,
        );
        fails(context(d, c, &[(0x1234, 1)]), null_mut(), EGL_BAD_ATTRIBUTE);
        fails(
            eglCreateContext(d, c, bogus, none.as_ptr()),
            null_mut(),
            EGL_BAD_CONTEXT,
        );
        let ctx = context(d, c, &[(EGL_CONTEXT_MAJOR_VERSION, 1), (EGL_CONTEXT_MINOR_VERSION, 1)]);
        assert!(!ctx.is_null());
        fails(
            eglQueryContext(d, bogus, EGL_CONFIG_ID, &mut v),
            EGL_FALSE,
            EGL_BAD_CONTEXT,
        );
        fails(eglQueryContext(d, ctx, 0x1234, &mut v), EGL_FALSE, EGL_BAD_ATTRIBUTE);
        fails(eglMakeCurrent(bogus, s, s, ctx), EGL_FALSE, EGL_BAD_DISPLAY);
        fails(eglMakeCurrent(d, s, s, bogus), EGL_FALSE, EGL_BAD_CONTEXT);
        fails(eglMakeCurrent(d, bogus, bogus, ctx), EGL_FALSE, EGL_BAD_SURFACE);
        fails(eglMakeCurrent(d, s, null_mut(), ctx), EGL_FALSE, EGL_BAD_MATCH);
        fails(eglMakeCurrent(d, s, s, null_mut()), EGL_FALSE, EGL_BAD_MATCH);
        let s2 = pbuffer(d, c, 4, 4);
        fails(eglMakeCurrent(d, s, s2, ctx), EGL_FALSE, EGL_BAD_MATCH);
        assert!(eglGetCurrentContext().is_null(), "failed calls leave nothing current");
        // Syncs and images do not exist.
        fails(eglCreateSync(d, 0x30F9, null()), null_mut(), EGL_BAD_PARAMETER);
        fails(
            eglCreateImage(d, ctx, 0x30B1, null_mut(), null()),
            null_mut(),
            EGL_BAD_PARAMETER,
        );

        // Destroying twice.
        assert_eq!(eglDestroySurface(d, s2), EGL_TRUE);
        fails(eglDestroySurface(d, s2), EGL_FALSE, EGL_BAD_SURFACE);
        assert_eq!(eglDestroyContext(d, ctx), EGL_TRUE);
        fails(eglDestroyContext(d, ctx), EGL_FALSE, EGL_BAD_CONTEXT);
        fails(eglMakeCurrent(d, s, s, ctx), EGL_FALSE, EGL_BAD_CONTEXT);
        assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
    }
    assert_eq!(eglGetError(), EGL_SUCCESS, "eglGetError resets");
}

#[test]
fn configs_are_chosen_and_sorted_as_egl_says() {
    let (d, _g) = display();
    let mut n = 0;
    // SAFETY: counting only.
    assert_eq!(unsafe { eglGetConfigs(d, null_mut(), 0, &mut n) }, EGL_TRUE);
    assert_eq!(n, 24);
    let mut two = [null_mut(); 2];
    // SAFETY: room for 2 handles.
    assert_eq!(unsafe { eglGetConfigs(d, two.as_mut_ptr(), 2, &mut n) }, EGL_TRUE);
    assert_eq!(n, 2);
    let pb = [
        (EGL_SURFACE_TYPE, EGL_PBUFFER_BIT),
        (EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT),
    ];
    let ids = |r: std::ops::RangeInclusive<EGLint>| r.collect::<Vec<_>>();
    // Not asking for alpha: the smaller RGB8 buffers (ids 13..24) first, as
    // on Mesa; then single-sampled before 4 samples, smaller depth, then
    // smaller stencil.
    assert_eq!(choose(d, &pb), [ids(13..=24), ids(1..=12)].concat());
    let pb = [&pb[..], &[(EGL_ALPHA_SIZE, 8)]].concat();
    let with = |extra: &[(EGLint, EGLint)]| [&pb[..], extra].concat();
    // RGBA8: ids 1..6 single-sampled, 7..12 with 4 samples.
    assert_eq!(choose(d, &pb), ids(1..=12));
    assert_eq!(choose(d, &with(&[(EGL_DEPTH_SIZE, 1)])), [3, 4, 5, 6, 9, 10, 11, 12]);
    assert_eq!(choose(d, &with(&[(EGL_DEPTH_SIZE, 17)])), [5, 6, 11, 12]);
    assert_eq!(choose(d, &with(&[(EGL_STENCIL_SIZE, 1)])), [2, 4, 6, 8, 10, 12]);
    assert_eq!(
        choose(d, &with(&[(EGL_DEPTH_SIZE, 24), (EGL_STENCIL_SIZE, 8)])),
        [6, 12]
    );
    // What piglit (through waffle) asks for.
    let piglit = with(&[
        (EGL_BUFFER_SIZE, 0),
        (EGL_RED_SIZE, 1),
        (EGL_GREEN_SIZE, 1),
        (EGL_BLUE_SIZE, 1),
        (EGL_ALPHA_SIZE, 1),
        (EGL_DEPTH_SIZE, 1),
        (EGL_STENCIL_SIZE, 1),
        (EGL_SAMPLE_BUFFERS, 0),
        (EGL_SAMPLES, 0),
    ]);
    assert_eq!(choose(d, &piglit), [4, 6, 10, 12]);
    // piglit's -samples=2: 4 samples (llvmpipe has no 2).
    let piglit_ms = [&piglit[..], &[(EGL_SAMPLE_BUFFERS, 1), (EGL_SAMPLES, 2)]].concat();
    assert_eq!(choose(d, &piglit_ms), [10, 12]);
    // Defaults: EGL_SURFACE_TYPE = EGL_WINDOW_BIT and EGL_RENDERABLE_TYPE =
    // EGL_OPENGL_ES_BIT, which no config has.
    assert_eq!(choose(d, &[]), Vec::<EGLint>::new());
    assert_eq!(choose(d, &with(&[(EGL_RED_SIZE, 9)])), Vec::<EGLint>::new());
    assert_eq!(choose(d, &with(&[(EGL_SAMPLES, 1)])), ids(7..=12));
    assert_eq!(choose(d, &with(&[(EGL_SAMPLES, 5)])), Vec::<EGLint>::new());
    assert_eq!(choose(d, &with(&[(EGL_DEPTH_SIZE, EGL_DONT_CARE)])), ids(1..=12));
    assert_eq!(
        choose(d, &with(&[(EGL_DEPTH_SIZE, 8), (EGL_DEPTH_SIZE, 0)])),
        ids(1..=12),
        "the last value wins"
    );
    // EGL_CONFIG_ID: every other attribute is ignored.
    assert_eq!(choose(d, &[(EGL_CONFIG_ID, 3), (EGL_DEPTH_SIZE, 24)]), [3]);
    let c = config(d, 16, 8);
    for (name, want) in [
        (EGL_BUFFER_SIZE, 32),
        (EGL_RED_SIZE, 8),
        (EGL_ALPHA_SIZE, 8),
        (EGL_DEPTH_SIZE, 16),
        (EGL_STENCIL_SIZE, 8),
        (EGL_CONFIG_ID, 4),
        (EGL_SURFACE_TYPE, EGL_PBUFFER_BIT),
        (EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT),
        (EGL_CONFORMANT, EGL_OPENGL_BIT),
        (EGL_COLOR_BUFFER_TYPE, EGL_RGB_BUFFER),
        (EGL_CONFIG_CAVEAT, EGL_NONE),
        (EGL_NATIVE_VISUAL_ID, 0),
        (EGL_SAMPLES, 0),
        (EGL_MAX_PBUFFER_WIDTH, 16384),
    ] {
        assert_eq!(config_attr(d, c, name), want, "attribute {name:#x}");
    }
    let by_id = |id: EGLint| {
        let (mut c, mut n) = (null_mut(), 0);
        let list = attribs(&[(EGL_CONFIG_ID, id)]);
        // SAFETY: the list ends with EGL_NONE; room for 1 handle.
        assert_eq!(
            unsafe { eglChooseConfig(d, list.as_ptr(), &mut c, 1, &mut n) },
            EGL_TRUE
        );
        c
    };
    for (id, name, want) in [
        (12, EGL_SAMPLES, 4),
        (12, EGL_SAMPLE_BUFFERS, 1),
        (12, EGL_ALPHA_SIZE, 8),
        (18, EGL_BUFFER_SIZE, 24),
        (18, EGL_ALPHA_SIZE, 0),
        (18, EGL_SAMPLES, 0),
        (24, EGL_SAMPLES, 4),
        (24, EGL_DEPTH_SIZE, 24),
    ] {
        assert_eq!(
            config_attr(d, by_id(id), name),
            want,
            "config {id}, attribute {name:#x}"
        );
    }
}

#[test]
fn a_pbuffer_holds_exact_pixels_across_contexts() {
    let (d, _g) = display();
    let c = config(d, 24, 8);
    let s = pbuffer(d, c, 5, 4);
    let ctx = context(d, c, &[(EGL_CONTEXT_MAJOR_VERSION, 1), (EGL_CONTEXT_MINOR_VERSION, 1)]);
    assert!(!ctx.is_null());
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    assert_eq!(eglGetCurrentContext(), ctx);
    assert_eq!(eglGetCurrentSurface(EGL_DRAW), s);
    assert_eq!(eglGetCurrentSurface(EGL_READ), s);
    assert_eq!(eglGetCurrentDisplay(), d);
    assert_eq!(ints(GL_VIEWPORT), [0, 0, 5, 4], "viewport set to the first surface");
    assert_eq!(ints(GL_SCISSOR_BOX), [0, 0, 5, 4]);
    assert_eq!(ints(GL_DEPTH_BITS)[0], 24);
    assert_eq!(ints(GL_STENCIL_BITS)[0], 8);
    glClearColor(0.0, 0.0, 1.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 1, 2, 1);
    glClearColor(1.0, 0.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    let px = read_rgba(5, 4);
    let at = |px: &[u8], x: usize, y: usize| px[(y * 5 + x) * 4..][..4].to_vec();
    assert_eq!(at(&px, 0, 0), [0, 0, 255, 255]);
    assert_eq!(at(&px, 1, 1), [255, 0, 0, 255]);
    assert_eq!(at(&px, 2, 1), [255, 0, 0, 255]);
    assert_eq!(at(&px, 3, 1), [0, 0, 255, 255]);
    assert_eq!(px.chunks(4).filter(|p| p == &[255, 0, 0, 255]).count(), 2);
    let mut v = 0;
    // SAFETY (queries below): `v` is writable.
    unsafe {
        assert_eq!(eglQueryContext(d, ctx, EGL_RENDER_BUFFER, &mut v), EGL_TRUE);
        assert_eq!(v, EGL_BACK_BUFFER);
        assert_eq!(eglQueryContext(d, ctx, EGL_CONFIG_ID, &mut v), EGL_TRUE);
        assert_eq!(v, 6);
        assert_eq!(eglQueryContext(d, ctx, EGL_CONTEXT_CLIENT_TYPE, &mut v), EGL_TRUE);
        assert_eq!(v, EGL_OPENGL_API as EGLint);
        assert_eq!(eglQuerySurface(d, s, EGL_WIDTH, &mut v), EGL_TRUE);
        assert_eq!(v, 5);
        assert_eq!(eglQuerySurface(d, s, EGL_HEIGHT, &mut v), EGL_TRUE);
        assert_eq!(v, 4);
        assert_eq!(eglQuerySurface(d, s, EGL_CONFIG_ID, &mut v), EGL_TRUE);
        assert_eq!(v, 6);
    }
    assert_eq!(eglSwapBuffers(d, s), EGL_TRUE);
    assert_eq!(read_rgba(5, 4), px, "a pbuffer keeps its pixels at eglSwapBuffers");
    // Release, then a second context reads the same pixels from the surface.
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    assert!(eglGetCurrentContext().is_null());
    assert!(glGetString(GL_VERSION).is_null(), "no context: GL calls do nothing");
    // SAFETY: `v` is writable.
    assert_eq!(unsafe { eglQueryContext(d, ctx, EGL_RENDER_BUFFER, &mut v) }, EGL_TRUE);
    assert_eq!(v, EGL_NONE);
    let other = context(d, c, &[]);
    assert_eq!(eglMakeCurrent(d, s, s, other), EGL_TRUE);
    assert_eq!(read_rgba(5, 4), px);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    for x in [ctx, other] {
        assert_eq!(eglDestroyContext(d, x), EGL_TRUE);
    }
    assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
}

#[test]
fn a_surfaceless_context_answers_and_takes_its_first_surfaces_size() {
    let (d, _g) = display();
    let c = config(d, 0, 0);
    let ctx = context(d, c, &[]);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), ctx), EGL_TRUE);
    assert_eq!(eglGetCurrentContext(), ctx);
    assert!(eglGetCurrentSurface(EGL_DRAW).is_null());
    let (major, minor) = (
        version_string().as_bytes()[0] - b'0',
        version_string().as_bytes()[2] - b'0',
    );
    assert_eq!(version_string()[..3], *"1.5", "GL_VERSION");
    glClear(GL_COLOR_BUFFER_BIT);
    assert_eq!(glGetError(), 0);
    // The highest version GL_VERSION reports is what EGL grants, and no more.
    let v = |ma: u8, mi: u8| {
        context(
            d,
            c,
            &[
                (EGL_CONTEXT_MAJOR_VERSION, ma.into()),
                (EGL_CONTEXT_MINOR_VERSION, mi.into()),
            ],
        )
    };
    let top = v(major, minor);
    assert!(!top.is_null());
    fails(v(major, minor + 1), null_mut(), EGL_BAD_MATCH);
    let s = pbuffer(d, c, 7, 3);
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    assert_eq!(ints(GL_VIEWPORT), [0, 0, 7, 3]);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    for x in [ctx, top] {
        assert_eq!(eglDestroyContext(d, x), EGL_TRUE);
    }
    assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
}

#[test]
fn contexts_on_several_threads_draw_their_own_pixels() {
    let (d, _g) = display();
    let c = config(d, 24, 8);
    const N: usize = 4;
    let barrier = Arc::new(Barrier::new(N));
    let workers: Vec<_> = (0..N)
        .map(|i| {
            let barrier = barrier.clone();
            let d = d as usize;
            let c = c as usize;
            std::thread::spawn(move || {
                let (d, c) = (d as EGLDisplay, c as EGLConfig);
                assert_eq!(eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
                let (w, h) = (8 + i as i32, 6 + i as i32);
                let s = pbuffer(d, c, w, h);
                let ctx = context(d, c, &[]);
                assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
                barrier.wait();
                let shade = 40 * i as u8 + 10;
                for _ in 0..20 {
                    glClearColor(f32::from(shade) / 255.0, 0.0, 0.0, 1.0);
                    glClear(GL_COLOR_BUFFER_BIT);
                    glColor3ub(0, shade, 0);
                    glBegin(GL_TRIANGLES);
                    glVertex2f(-1.0, -1.0);
                    glVertex2f(3.0, -1.0);
                    glVertex2f(-1.0, 3.0);
                    glEnd();
                }
                let px = read_rgba(w, h);
                assert!(px.chunks(4).all(|p| p == [0, shade, 0, 255]), "thread {i}");
                assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
                assert_eq!(eglDestroyContext(d, ctx), EGL_TRUE);
                assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
            })
        })
        .collect();
    for w in workers {
        w.join().expect("worker");
    }
}

#[test]
fn a_context_current_elsewhere_is_refused_until_its_thread_lets_go() {
    let (d, _g) = display();
    let c = config(d, 0, 0);
    let s = pbuffer(d, c, 2, 2);
    let ctx = context(d, c, &[]);
    let (dd, ss, cc) = (d as usize, s as usize, ctx as usize);
    let (tx, rx) = std::sync::mpsc::channel();
    let (done_tx, done_rx) = std::sync::mpsc::channel::<()>();
    let t = std::thread::spawn(move || {
        assert_eq!(
            eglMakeCurrent(dd as EGLDisplay, ss as EGLSurface, ss as EGLSurface, cc as EGLContext),
            EGL_TRUE
        );
        tx.send(()).unwrap();
        // Ends without releasing: the thread's end releases the context.
        done_rx.recv().unwrap();
    });
    rx.recv().unwrap();
    fails(
        eglMakeCurrent(d, null_mut(), null_mut(), ctx),
        EGL_FALSE,
        EGL_BAD_ACCESS,
    );
    let other = context(d, c, &[]);
    fails(eglMakeCurrent(d, s, s, other), EGL_FALSE, EGL_BAD_ACCESS);
    done_tx.send(()).unwrap();
    t.join().unwrap();
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    assert_eq!(eglReleaseThread(), EGL_TRUE);
    assert!(eglGetCurrentContext().is_null());
    assert_eq!(eglQueryAPI(), EGL_NONE as EGLenum, "eglReleaseThread resets the API");
    assert_eq!(eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
    assert_eq!(eglMakeCurrent(d, s, s, other), EGL_TRUE);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    for x in [ctx, other] {
        assert_eq!(eglDestroyContext(d, x), EGL_TRUE);
    }
    assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
}

#[test]
fn proc_addresses_are_the_exports() {
    let addr = |p: EGLProc| p.map(|f| f as *const c_void);
    // SAFETY (each call): NUL-terminated names.
    unsafe {
        assert_eq!(
            addr(eglGetProcAddress(c"glClear".as_ptr())),
            Some(glClear as *const c_void)
        );
        assert_eq!(
            addr(eglGetProcAddress(c"eglMakeCurrent".as_ptr())),
            Some(eglMakeCurrent as *const c_void)
        );
        assert_eq!(
            addr(glXGetProcAddressARB(c"glBegin".as_ptr().cast())),
            Some(glBegin as *const c_void)
        );
        assert_eq!(
            addr(glXGetProcAddress(c"glEnd".as_ptr().cast())),
            Some(glEnd as *const c_void)
        );
        assert!(eglGetProcAddress(c"glNoSuchFunction".as_ptr()).is_none());
        assert!(eglGetProcAddress(null()).is_none());
    }
}

#[test]
fn terminate_invalidates_handles_but_not_current_contexts() {
    let _w = DISPLAY.write().unwrap_or_else(|e| e.into_inner());
    let d = eglGetDisplay(null_mut());
    // SAFETY: null outputs are allowed.
    assert_eq!(unsafe { eglInitialize(d, null_mut(), null_mut()) }, EGL_TRUE);
    assert_eq!(eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
    let c = config(d, 0, 0);
    let s = pbuffer(d, c, 3, 3);
    let ctx = context(d, c, &[]);
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    assert_eq!(eglTerminate(d), EGL_TRUE);
    assert_eq!(eglTerminate(d), EGL_TRUE, "terminating twice is allowed");
    assert_eq!(version_string()[..3], *"1.5", "still current after eglTerminate");
    assert_eq!(eglGetCurrentContext(), ctx);
    let mut v = 0;
    // SAFETY: writable outputs; the list is null.
    unsafe {
        fails(
            eglQueryContext(d, ctx, EGL_CONFIG_ID, &mut v),
            EGL_FALSE,
            EGL_NOT_INITIALIZED,
        );
        fails(eglCreatePbufferSurface(d, c, null()), null_mut(), EGL_NOT_INITIALIZED);
        fails(eglGetConfigs(d, null_mut(), 0, &mut v), EGL_FALSE, EGL_NOT_INITIALIZED);
    }
    fails(eglQueryString(d, EGL_VENDOR), null(), EGL_NOT_INITIALIZED);
    fails(eglMakeCurrent(d, s, s, ctx), EGL_FALSE, EGL_NOT_INITIALIZED);
    assert_eq!(
        eglMakeCurrent(d, null_mut(), null_mut(), null_mut()),
        EGL_TRUE,
        "releasing needs no display"
    );
    assert!(eglGetCurrentContext().is_null());
    // SAFETY: null outputs are allowed.
    assert_eq!(unsafe { eglInitialize(d, null_mut(), null_mut()) }, EGL_TRUE);
    fails(eglMakeCurrent(d, s, s, ctx), EGL_FALSE, EGL_BAD_CONTEXT);
    fails(eglDestroySurface(d, s), EGL_FALSE, EGL_BAD_SURFACE);
}

#[test]
fn osmesa_and_egl_contexts_share_the_thread_slot() {
    let (d, _g) = display();
    let c = config(d, 0, 0);
    let s = pbuffer(d, c, 2, 2);
    let ctx = context(d, c, &[]);
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    let os = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, null_mut());
    let mut buf = [0u8; 16];
    // SAFETY: `buf` holds 2 × 2 RGBA pixels and outlives its use here.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(os, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 2, 2) },
        1
    );
    assert!(eglGetCurrentContext().is_null(), "OSMesa's context replaced EGL's");
    glClearColor(1.0, 1.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    assert_eq!(buf[..4], [255, 255, 0, 255]);
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    assert_eq!(read_rgba(2, 2), [0u8; 16], "the pbuffer did not see OSMesa's clear");
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    OSMesaDestroyContext(os);
    assert_eq!(eglDestroyContext(d, ctx), EGL_TRUE);
    assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
}

#[test]
fn the_one_device_leads_to_the_one_display() {
    // MuJoCo's `MUJOCO_GL=egl` way in: devices, then the device's display.
    let (d, _g) = display();
    let ext = eglQueryString(null_mut(), EGL_EXTENSIONS);
    // SAFETY: a NUL-terminated static string.
    let ext = unsafe { CStr::from_ptr(ext) }.to_str().unwrap().to_string();
    for e in [
        "EGL_EXT_device_base",
        "EGL_EXT_device_enumeration",
        "EGL_EXT_device_query",
        "EGL_EXT_platform_device",
    ] {
        assert!(ext.split(' ').any(|x| x == e), "{e} in {ext}");
    }
    let mut n = -1;
    // SAFETY (each call): outputs NULL or writable with room for what is asked.
    unsafe {
        assert_eq!(eglQueryDevicesEXT(0, null_mut(), &mut n), EGL_TRUE);
        assert_eq!(n, 1);
        let mut devices = [null_mut(); 4];
        n = -1;
        assert_eq!(eglQueryDevicesEXT(4, devices.as_mut_ptr(), &mut n), EGL_TRUE);
        assert_eq!((n, devices[1]), (1, null_mut()));
        let device = devices[0];
        assert!(!device.is_null());
        fails(
            eglQueryDevicesEXT(4, devices.as_mut_ptr(), null_mut()),
            EGL_FALSE,
            EGL_BAD_PARAMETER,
        );
        fails(
            eglQueryDevicesEXT(0, devices.as_mut_ptr(), &mut n),
            EGL_FALSE,
            EGL_BAD_PARAMETER,
        );

        let s = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
        assert_eq!(CStr::from_ptr(s).to_str(), Ok("EGL_MESA_device_software"));
        fails(eglQueryDeviceStringEXT(device, EGL_VENDOR), null(), EGL_BAD_PARAMETER);
        fails(eglQueryDeviceStringEXT(d, EGL_EXTENSIONS), null(), EGL_BAD_DEVICE_EXT);
        let mut v: EGLAttrib = -7;
        fails(
            eglQueryDeviceAttribEXT(device, EGL_DEVICE_EXT, &mut v),
            EGL_FALSE,
            EGL_BAD_ATTRIBUTE,
        );
        fails(
            eglQueryDeviceAttribEXT(null_mut(), EGL_DEVICE_EXT, &mut v),
            EGL_FALSE,
            EGL_BAD_DEVICE_EXT,
        );

        let p = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, null());
        assert_eq!(p, d, "the device's display is the display");
        fails(
            eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, d, null()),
            null_mut(),
            EGL_BAD_PARAMETER,
        );
        fails(
            eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, null_mut(), null()),
            null_mut(),
            EGL_BAD_PARAMETER,
        );
        assert_eq!(eglQueryDisplayAttribEXT(d, EGL_DEVICE_EXT, &mut v), EGL_TRUE);
        assert_eq!(v, device as EGLAttrib);
        fails(
            eglQueryDisplayAttribEXT(d, EGL_VENDOR, &mut v),
            EGL_FALSE,
            EGL_BAD_ATTRIBUTE,
        );
        fails(
            eglQueryDisplayAttribEXT(device, EGL_DEVICE_EXT, &mut v),
            EGL_FALSE,
            EGL_BAD_DISPLAY,
        );
        assert!(eglGetProcAddress(c"eglQueryDevicesEXT".as_ptr()).is_some());
    }
    // A surfaceless context on it draws.
    let ctx = context(d, config(d, 24, 8), &[]);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), ctx), EGL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    assert_eq!(glGetError(), 0);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    assert_eq!(eglDestroyContext(d, ctx), EGL_TRUE);
}
