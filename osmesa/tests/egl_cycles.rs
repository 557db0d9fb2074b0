//! 1,000 EGL create / make-current / draw / destroy cycles leave the
//! process no bigger (its own test binary: other tests' threads would move
//! the resident size).

use std::ptr::null_mut;
use OSMesa::egl::*;
use OSMesa::*;

const GL_COLOR_BUFFER_BIT: u32 = 0x4000;
const GL_TRIANGLES: u32 = 4;

/// Resident set size in KiB (`/proc/self/statm`, pages of 4 KiB).
fn rss_kib() -> usize {
    let statm = std::fs::read_to_string("/proc/self/statm").expect("/proc/self/statm");
    let pages: usize = statm.split_whitespace().nth(1).unwrap().parse().unwrap();
    pages * 4
}

/// One cycle: a 64 × 64 pbuffer and a context, a clear and a triangle, read back.
fn cycle(d: EGLDisplay, config: EGLConfig) {
    let size = [EGL_WIDTH, 64, EGL_HEIGHT, 64, EGL_NONE];
    // SAFETY: both lists end with EGL_NONE.
    let (s, ctx) = unsafe {
        (
            eglCreatePbufferSurface(d, config, size.as_ptr()),
            eglCreateContext(d, config, null_mut(), [EGL_NONE].as_ptr()),
        )
    };
    assert!(!s.is_null() && !ctx.is_null());
    assert_eq!(eglMakeCurrent(d, s, s, ctx), EGL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 0.5, 0.0);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1.0, -1.0);
    glVertex2f(1.0, -1.0);
    glVertex2f(0.0, 1.0);
    glEnd();
    let mut px = [0u8; 4];
    // SAFETY: room for one RGBA pixel.
    unsafe { glReadPixels(32, 10, 1, 1, 0x1908, 0x1401, px.as_mut_ptr().cast()) };
    assert_eq!(px, [255, 128, 0, 255]);
    assert_eq!(eglMakeCurrent(d, null_mut(), null_mut(), null_mut()), EGL_TRUE);
    assert_eq!(eglDestroyContext(d, ctx), EGL_TRUE);
    assert_eq!(eglDestroySurface(d, s), EGL_TRUE);
}

#[test]
fn a_thousand_cycles_do_not_grow_the_process() {
    let d = eglGetDisplay(null_mut());
    // SAFETY: null outputs are allowed.
    assert_eq!(unsafe { eglInitialize(d, null_mut(), null_mut()) }, EGL_TRUE);
    assert_eq!(eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
    let want = [
        EGL_SURFACE_TYPE,
        EGL_PBUFFER_BIT,
        EGL_RENDERABLE_TYPE,
        EGL_OPENGL_BIT,
        EGL_DEPTH_SIZE,
        24,
        EGL_STENCIL_SIZE,
        8,
        EGL_NONE,
    ];
    let (mut config, mut n) = (null_mut(), 0);
    // SAFETY: the list ends with EGL_NONE; room for one handle.
    assert_eq!(
        unsafe { eglChooseConfig(d, want.as_ptr(), &mut config, 1, &mut n) },
        EGL_TRUE
    );
    assert_eq!(n, 1);
    // Warm up: the specialist cache, the allocator's arenas.
    for _ in 0..100 {
        cycle(d, config);
    }
    let before = rss_kib();
    for _ in 0..1000 {
        cycle(d, config);
    }
    let after = rss_kib();
    println!("RSS before {before} KiB, after 1,000 cycles {after} KiB");
    // Tolerance: 1 MiB for allocator fragmentation; one leaked 64 × 64 D24S8
    // pbuffer a cycle would be 1,000 × 32 KiB = 31 MiB.
    assert!(after <= before + 1024, "RSS grew from {before} to {after} KiB");
    assert_eq!(eglTerminate(d), EGL_TRUE);
}
