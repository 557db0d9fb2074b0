//! The attribute calls' current context while it passes between threads:
//! the sole thread with a context current reads it from a global, the
//! others from their thread-local (`state::fast`). One test in its own
//! binary, so that no other test's thread has a context current and every
//! step below is the transition it names.

use std::ptr::null_mut;
use std::sync::{Arc, Barrier};
use OSMesa::consts::*;
use OSMesa::*;

const GL_CURRENT_COLOR: u32 = 0x0B00;
const GL_QUADS: u32 = 7;
const GL_PROJECTION: u32 = 0x1701;
const GL_MODELVIEW: u32 = 0x1700;

/// A 4x4 RGBA context current on this thread, drawing into `buf`, with
/// window coordinates in pixels.
fn make_current(ctx: OSMesaContext, buf: &mut [u8; 64]) {
    // SAFETY: `buf` holds 4x4 RGBA pixels; each test releases or ends the
    // thread before the buffer goes.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 4, 4) },
        GL_TRUE
    );
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
}

fn release() {
    // SAFETY: null context and buffer: releases.
    assert_eq!(unsafe { OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0) }, GL_TRUE);
}

fn current_color() -> [f32; 4] {
    let mut c = [0.0f32; 4];
    // SAFETY: room for the 4 values of GL_CURRENT_COLOR.
    unsafe { glGetFloatv(GL_CURRENT_COLOR, c.as_mut_ptr()) };
    c
}

/// Fills the window with `rgb` through attribute calls and checks every
/// pixel and the current colour.
fn draw_and_check(buf: &[u8; 64], rgb: [u8; 3], what: &str) {
    glBegin(GL_QUADS);
    for (x, y) in [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)] {
        glColor3ub(rgb[0], rgb[1], rgb[2]);
        glVertex2f(x, y);
    }
    glEnd();
    glFinish();
    let want = [rgb[0], rgb[1], rgb[2], 255];
    assert!(buf.chunks(4).all(|p| p == want), "{what}: {buf:?}");
    let c = rgb.map(|v| f32::from(v) / 255.0);
    assert_eq!(current_color(), [c[0], c[1], c[2], 1.0], "{what}");
}

fn context() -> usize {
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, null_mut());
    assert!(!ctx.is_null());
    ctx as usize
}

#[test]
fn the_current_context_follows_threads_through_every_transition() {
    let (a, b, c) = (context(), context(), context());
    let mut buf = [0u8; 64];
    // The only thread with a context: the global path.
    make_current(a as OSMesaContext, &mut buf);
    draw_and_check(&buf, [10, 20, 30], "sole");
    // Another thread gets one too: both on their thread-locals, at once.
    let both = Arc::new(Barrier::new(2));
    let other = {
        let both = both.clone();
        std::thread::spawn(move || {
            let mut buf = [0u8; 64];
            make_current(b as OSMesaContext, &mut buf);
            both.wait();
            for i in 0..50 {
                draw_and_check(&buf, [200, i, 100], "second thread");
            }
            both.wait();
            // Ends with `b` current: the thread's end releases it.
        })
    };
    both.wait();
    for i in 0..50 {
        draw_and_check(&buf, [i, 40, 50], "first thread beside the second");
    }
    both.wait();
    other.join().unwrap();
    draw_and_check(&buf, [60, 70, 80], "alone again, not claimed since");
    // Released and made current again: the sole thread once more.
    release();
    make_current(a as OSMesaContext, &mut buf);
    assert_eq!(current_color(), [60.0 / 255.0, 70.0 / 255.0, 80.0 / 255.0, 1.0]);
    // A switch to another context and back, still the sole thread.
    let mut buf_c = [0u8; 64];
    make_current(c as OSMesaContext, &mut buf_c);
    draw_and_check(&buf_c, [1, 2, 3], "switched");
    make_current(a as OSMesaContext, &mut buf);
    assert_eq!(current_color(), [60.0 / 255.0, 70.0 / 255.0, 80.0 / 255.0, 1.0]);
    // Released here, then current on a thread that ends with it current.
    release();
    glColor3f(1.0, 0.0, 0.0); // no context: ignored
    std::thread::spawn(move || {
        let mut buf = [0u8; 64];
        make_current(a as OSMesaContext, &mut buf);
        draw_and_check(&buf, [90, 100, 110], "the only thread, then ends");
    })
    .join()
    .unwrap();
    // Its end left no context behind on any path.
    make_current(b as OSMesaContext, &mut buf);
    assert_eq!(
        current_color(),
        [200.0 / 255.0, 49.0 / 255.0, 100.0 / 255.0, 1.0],
        "b as left"
    );
    draw_and_check(&buf, [5, 6, 7], "b here");
    make_current(a as OSMesaContext, &mut buf);
    assert_eq!(
        current_color(),
        [90.0 / 255.0, 100.0 / 255.0, 110.0 / 255.0, 1.0],
        "a as left"
    );
    release();
    for h in [a, b, c] {
        OSMesaDestroyContext(h as OSMesaContext);
    }
}
