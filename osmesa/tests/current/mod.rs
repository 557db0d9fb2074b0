//! The set-up of the in-process C ABI tests (`abi.rs`, `lighting.rs`,
//! `fog.rs`, `beginend.rs`): a
//! context current on the test's thread (each test runs on its own thread,
//! so has its own current context) and the GL error codes they check.
#![allow(dead_code)]

use std::ptr::null_mut;
use OSMesa::consts::*;
use OSMesa::*;

pub const GL_INVALID_ENUM: u32 = 0x500;
pub const GL_INVALID_VALUE: u32 = 0x501;
pub const GL_INVALID_OPERATION: u32 = 0x502;
const GL_PROJECTION: u32 = 0x1701;
const GL_MODELVIEW: u32 = 0x1700;

/// An RGBA context with 24 depth and 8 stencil bits, current on this thread,
/// drawing into `buf` (`w` x `h` RGBA bytes); GL's initial matrices.
pub fn current(buf: &mut [u8], w: i32, h: i32) -> OSMesaContext {
    assert!(buf.len() >= (w * h * 4) as usize);
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, null_mut());
    assert!(!ctx.is_null());
    // SAFETY: `buf` holds w * h RGBA pixels (checked above) and outlives the
    // test's drawing.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, w, h) },
        GL_TRUE
    );
    ctx
}

/// [`current`] with an orthographic projection of the window in pixels.
pub fn current_in_pixels(buf: &mut [u8], w: i32, h: i32) -> OSMesaContext {
    let ctx = current(buf, w, h);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    ctx
}

/// The check step of the random-call tests: after `glFinish`, the error is
/// none or one of GL's codes (never anything else); counts it in `seen`
/// (`[without error, with error]`).
pub fn finish_and_count_error(step: usize, seen: &mut [usize; 2]) {
    glFinish();
    let e = glGetError();
    assert!(
        e == GL_NO_ERROR || (0x500..=0x505).contains(&e),
        "step {step}: error {e:#x}"
    );
    seen[usize::from(e != GL_NO_ERROR)] += 1;
}
