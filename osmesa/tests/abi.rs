//! The C ABI called from Rust, in-process: handles, current contexts, the
//! unimplemented entry points, client arrays, pixel store and the converted
//! formats. Each test runs on its own thread, so has its own current context.

use std::ffi::c_void;
use std::ptr::{null, null_mut};
use OSMesa::consts::*;
use OSMesa::*;

mod current;
use current::{current_in_pixels as current, GL_INVALID_ENUM, GL_INVALID_OPERATION, GL_INVALID_VALUE};

const GL_TRIANGLES: u32 = 4;
const GL_QUADS: u32 = 7;
const GL_AUTO_NORMAL: u32 = 0x0D80;

fn px(buf: &[u8], w: usize, x: usize, y: usize) -> [u8; 4] {
    let o = (y * w + x) * 4;
    buf[o..o + 4].try_into().unwrap()
}

#[test]
fn calls_without_a_current_context_do_nothing() {
    assert!(OSMesaGetCurrentContext().is_null());
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glVertex2f(0.0, 0.0);
    glEnd();
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert!(glGetString(GL_VENDOR).is_null());
    let mut v = [7i32; 4];
    // SAFETY: room for the 4 values of GL_VIEWPORT.
    unsafe { glGetIntegerv(0x0BA2, v.as_mut_ptr()) };
    assert_eq!(v, [7; 4]);
}

#[test]
fn unknown_and_destroyed_handles_are_refused() {
    let mut buf = vec![0u8; 16];
    let bogus = 0xdead_bee0usize as OSMesaContext;
    // SAFETY: the buffer holds 2x2 RGBA pixels; the handle is never dereferenced.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(bogus, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 2, 2) },
        GL_FALSE
    );
    OSMesaDestroyContext(bogus);
    OSMesaDestroyContext(null_mut());
    let ctx = OSMesaCreateContext(OSMESA_RGBA, null_mut());
    OSMesaDestroyContext(ctx);
    OSMesaDestroyContext(ctx); // twice: ignored
                               // SAFETY: as above.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 2, 2) },
        GL_FALSE
    );
    let (mut w, mut h, mut f, mut p) = (5, 5, 5, null_mut::<c_void>());
    // SAFETY: valid output pointers.
    assert_eq!(
        unsafe { OSMesaGetColorBuffer(ctx, &mut w, &mut h, &mut f, &mut p) },
        GL_FALSE
    );
    // A refused OSMesaMakeCurrent leaves the current context as it was.
    let mut px4 = vec![0u8; 16];
    let live = current(&mut px4, 2, 2);
    let other = OSMesaCreateContextExt(OSMESA_RGB_565, 0, 0, 0, null_mut());
    // SAFETY: 2x2 pixels of 2 bytes fit; the type is refused before any use.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(other, px4.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 2, 2) },
        GL_FALSE
    );
    assert_eq!(OSMesaGetCurrentContext(), live);
    OSMesaDestroyContext(other);
    OSMesaDestroyContext(live);
    // Unknown formats and negative sizes: no context.
    assert!(OSMesaCreateContextExt(OSMESA_COLOR_INDEX, 0, 0, 0, null_mut()).is_null());
    assert!(OSMesaCreateContextExt(OSMESA_RGBA, -1, 0, 0, null_mut()).is_null());
    let core = [OSMESA_PROFILE, OSMESA_CORE_PROFILE, 0];
    // SAFETY: zero-terminated attribute lists.
    unsafe {
        assert!(OSMesaCreateContextAttribs(core.as_ptr(), null_mut()).is_null());
        let gl3 = [OSMESA_CONTEXT_MAJOR_VERSION, 3, 0];
        assert!(OSMesaCreateContextAttribs(gl3.as_ptr(), null_mut()).is_null());
        let ok = [OSMESA_FORMAT, OSMESA_BGRA as i32, OSMESA_DEPTH_BITS, 16, 0];
        let c = OSMesaCreateContextAttribs(ok.as_ptr(), null_mut());
        assert!(!c.is_null());
        OSMesaDestroyContext(c);
    }
}

#[test]
fn unimplemented_capabilities_record_invalid_operation() {
    let mut buf = vec![0u8; 8 * 8 * 4];
    let ctx = current(&mut buf, 8, 8);
    // GL_POLYGON_SMOOTH: a capability softgl does not implement yet.
    const SMOOTH: u32 = 0x0B41;
    glEnable(SMOOTH);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    assert_eq!(glIsEnabled(SMOOTH), GL_FALSE);
    glDisable(SMOOTH); // disabling what is off is fine
    assert_eq!(glGetError(), GL_NO_ERROR);
    glEnable(SMOOTH);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    // Stored for the evaluators: accepted and reported.
    glEnable(GL_AUTO_NORMAL);
    assert_eq!((glGetError(), glIsEnabled(GL_AUTO_NORMAL)), (GL_NO_ERROR, GL_TRUE));
    // Drawing still works after all that.
    glColor3f(0.0, 1.0, 0.0);
    glRectf(0.0, 0.0, 8.0, 8.0);
    glFinish();
    assert_eq!(px(&buf, 8, 3, 3), [0, 255, 0, 255]);
    OSMesaDestroyContext(ctx);
    assert!(OSMesaGetCurrentContext().is_null());
}

#[test]
fn proc_addresses_are_the_exports() {
    // SAFETY: NUL-terminated names.
    unsafe {
        let clear = OSMesaGetProcAddress(c"glClear".as_ptr()).expect("glClear");
        assert_eq!(clear as usize, glClear as *const () as usize);
        let make = OSMesaGetProcAddress(c"OSMesaMakeCurrent".as_ptr()).expect("OSMesaMakeCurrent");
        assert_eq!(make as usize, OSMesaMakeCurrent as *const () as usize);
        assert!(OSMesaGetProcAddress(c"glBlendColorEXT".as_ptr()).is_some());
        assert!(OSMesaGetProcAddress(c"glNoSuchThing".as_ptr()).is_none());
        assert!(OSMesaGetProcAddress(null()).is_none());
    }
}

#[test]
fn client_arrays_of_every_type_draw_like_immediate_mode() {
    let (w, h) = (16usize, 16usize);
    let mut a = vec![0u8; w * h * 4];
    let ctx = current(&mut a, 16, 16);
    // Two triangles: short positions, unsigned byte colours, drawn by index.
    let pos: [i16; 8] = [1, 1, 15, 1, 15, 15, 1, 15];
    let col: [u8; 16] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255];
    let idx: [u16; 6] = [0, 1, 2, 0, 2, 3];
    // SAFETY: the arrays outlive the draws; 6 u16 indices.
    unsafe {
        glVertexPointer(2, GL_SHORT, 0, pos.as_ptr().cast());
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, col.as_ptr().cast());
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx.as_ptr().cast());
    }
    assert_eq!(glGetError(), GL_NO_ERROR);
    glFinish();
    let arrays = a.clone();
    // The same with glDrawArrays of a quad, and with glArrayElement.
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_QUADS, 0, 4);
    glFinish();
    assert_eq!(a, arrays, "glDrawArrays(GL_QUADS) differs from the indexed triangles");
    glClear(GL_COLOR_BUFFER_BIT);
    // SAFETY: 6 u16 indices.
    unsafe { glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_UNSIGNED_SHORT, idx.as_ptr().cast()) };
    glFinish();
    assert_eq!(a, arrays, "glDrawRangeElements differs");
    // SAFETY: refused before reading.
    unsafe { glDrawRangeElements(GL_TRIANGLES, 3, 0, 6, GL_UNSIGNED_SHORT, idx.as_ptr().cast()) };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    for i in 0..4 {
        glArrayElement(i);
    }
    glEnd();
    glFinish();
    assert_eq!(a, arrays, "glArrayElement differs");
    // And immediate mode with the same values.
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    for i in 0..4 {
        glColor4ub(col[i * 4], col[i * 4 + 1], col[i * 4 + 2], col[i * 4 + 3]);
        glVertex2s(pos[i * 2], pos[i * 2 + 1]);
    }
    glEnd();
    glFinish();
    assert_eq!(a, arrays, "immediate mode differs");
    // Smooth shading at the centre (1.5, 1.5), next to the red vertex at (1, 1).
    assert_eq!(px(&a, w, 1, 1), [246, 0, 9, 255]);
    assert_eq!(px(&a, w, 0, 0), [0, 0, 0, 0]);
    OSMesaDestroyContext(ctx);
}

#[test]
fn read_pixels_honours_the_pack_state() {
    let (w, h) = (8usize, 4usize);
    let mut buf = vec![0u8; w * h * 4];
    let ctx = current(&mut buf, 8, 4);
    glClearColor(0.0, 0.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(0); // points, one per pixel of row 1, red = x * 30
    for x in 0..8 {
        glColor3ub(x as u8 * 30, 7, 9);
        glVertex2f(x as f32 + 0.5, 1.5);
    }
    glEnd();
    // 3 pixels from (2, 1) as RGB, alignment 8, row length 5, skip 1 pixel and 1 row.
    let mut out = [0xEEu8; 64];
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 5);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    // SAFETY: 64 bytes hold 2 rows of stride 16 after a 16 + 3 byte skip.
    unsafe { glReadPixels(2, 1, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, out.as_mut_ptr().cast()) };
    assert_eq!(glGetError(), GL_NO_ERROR);
    // Row stride: 5 pixels * 3 bytes = 15, aligned to 16. Start: 16 + 3.
    assert_eq!(&out[19..28], &[60, 7, 9, 90, 7, 9, 120, 7, 9]);
    assert!(out[..19].iter().all(|&b| b == 0xEE), "skipped bytes were written");
    assert_eq!(&out[35..44], &[0, 0, 0, 0, 0, 0, 0, 0, 0], "row 2 is the cleared row");
    assert!(out[44..].iter().all(|&b| b == 0xEE));
    // A read from outside the framebuffer leaves those bytes alone.
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    let mut one = [0xEEu8; 8];
    // SAFETY: 2 RGBA pixels.
    unsafe { glReadPixels(7, 1, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, one.as_mut_ptr().cast()) };
    assert_eq!(one, [210, 7, 9, 255, 0xEE, 0xEE, 0xEE, 0xEE]);
    // Errors: a null destination, a bad type.
    // SAFETY: null is refused before any write.
    unsafe { glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, null_mut()) };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // SAFETY: the bad type is refused before any write.
    unsafe { glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, one.as_mut_ptr().cast()) };
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    OSMesaDestroyContext(ctx);
}

#[test]
fn y_up_and_row_length_change_the_layout_of_later_frames() {
    let (w, h) = (4usize, 3usize);
    let mut buf = vec![0xA5u8; 6 * h * 4];
    let ctx = current(&mut buf, 4, 3);
    let draw = || {
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1.0, 0.0, 0.0);
        glRectf(0.0, 0.0, 4.0, 1.0); // the bottom row
        glFinish();
    };
    draw();
    assert_eq!(px(&buf, w, 0, 0), [255, 0, 0, 255], "Y_UP: row 0 is the bottom");
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    draw();
    assert_eq!(
        px(&buf, w, 0, 2),
        [255, 0, 0, 255],
        "Y_UP 0: the last row is the bottom"
    );
    assert_eq!(px(&buf, w, 0, 0), [0, 0, 255, 255]);
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, 6);
    draw();
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(px(&buf, 6, 3, 0), [255, 0, 0, 255], "rows are 6 pixels apart");
    assert_eq!(px(&buf, 6, 0, 1), [0, 0, 255, 255]);
    // A row length shorter than the width is refused and changes nothing.
    OSMesaPixelStore(OSMESA_ROW_LENGTH, 2);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    let mut v = 0;
    // SAFETY: one writable GLint.
    unsafe { OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &mut v) };
    assert_eq!(v, 6);
    OSMesaDestroyContext(ctx);
}

#[test]
fn converted_formats_reach_the_buffer_at_finish_and_when_switching() {
    let mut floats = vec![-1.0f32; 2 * 2 * 4];
    let ctx = OSMesaCreateContextExt(OSMESA_ARGB, 0, 0, 0, null_mut());
    // SAFETY: 2x2 pixels of 4 floats.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, floats.as_mut_ptr().cast(), GL_FLOAT, 2, 2) },
        GL_TRUE
    );
    glClearColor(0.2, 0.4, 0.6, 0.8);
    glClear(GL_COLOR_BUFFER_BIT);
    assert_eq!(
        floats[0], -1.0,
        "converted formats are written at flush time, as in Mesa"
    );
    glFlush();
    // Rendered in floats (RGBA32F), as Mesa does: the clear colour as given.
    assert_eq!(&floats[..4], &[0.8, 0.2, 0.4, 0.6], "ARGB order");
    // Switching to another context flushes the previous one.
    glClearColor(1.0, 0.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    let mut other = vec![0u8; 4];
    let ctx2 = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, null_mut());
    // SAFETY: one RGBA pixel.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx2, other.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 1, 1) },
        GL_TRUE
    );
    assert_eq!(&floats[..4], &[1.0, 1.0, 0.0, 0.0]);
    OSMesaDestroyContext(ctx2);
    OSMesaDestroyContext(ctx);
}

#[test]
fn a_context_destroyed_while_current_elsewhere_stays_safe() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    let handle = ctx as usize;
    // Another thread destroys it; this thread keeps drawing into it safely.
    std::thread::spawn(move || OSMesaDestroyContext(handle as OSMesaContext))
        .join()
        .unwrap();
    glClearColor(0.0, 1.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    // The attribute calls too (they reach the context without the registry).
    glColor3f(0.0, 0.0, 1.0);
    glBegin(GL_QUADS);
    for (x, y) in [(0.0, 0.0), (2.0, 0.0), (2.0, 4.0), (0.0, 4.0)] {
        glVertex2f(x, y);
    }
    glEnd();
    glFinish();
    assert_eq!(px(&buf, 4, 0, 0), [0, 0, 255, 255]);
    assert_eq!(px(&buf, 4, 3, 0), [0, 255, 0, 255]);
    assert_eq!(OSMesaGetCurrentContext(), ctx);
    // The handle is gone for everyone else.
    let mut b2 = vec![0u8; 4];
    // SAFETY: one RGBA pixel.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, b2.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 1, 1) },
        GL_FALSE
    );
}

/// Fills the `w` x `w` pixel window with one quad of `rgb`, a colour per vertex.
fn fill_with_attribute_calls(w: f32, rgb: [u8; 3]) {
    glBegin(GL_QUADS);
    for (x, y) in [(0.0, 0.0), (w, 0.0), (w, w), (0.0, w)] {
        glColor3ub(rgb[0], rgb[1], rgb[2]);
        glVertex2f(x, y);
    }
    glEnd();
    glFinish();
}

#[test]
fn contexts_on_several_threads_draw_with_attribute_calls() {
    // Each thread's attribute calls reach its own context, at the same time.
    const W: usize = 8;
    let threads: Vec<_> = (0..4u8)
        .map(|t| {
            std::thread::spawn(move || {
                let mut buf = vec![0u8; W * W * 4];
                let ctx = current(&mut buf, W as i32, W as i32);
                for round in 0..100u8 {
                    // A unorm8 colour through glColor3ub comes back exact.
                    let rgb = [t * 60 + 15, round * 2, 255 - t * 60];
                    fill_with_attribute_calls(W as f32, rgb);
                    let want = [rgb[0], rgb[1], rgb[2], 255];
                    assert!(buf.chunks(4).all(|p| p == want), "thread {t} round {round}");
                }
                assert_eq!(glGetError(), GL_NO_ERROR);
                // SAFETY: null context and buffer: releases.
                assert_eq!(unsafe { OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0) }, GL_TRUE);
                OSMesaDestroyContext(ctx);
            })
        })
        .collect();
    for t in threads {
        t.join().unwrap();
    }
}

#[test]
fn a_context_current_on_one_thread_is_refused_on_another() {
    const GL_CURRENT_COLOR: u32 = 0x0B00;
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    let (handle, mine) = (ctx as usize, buf.as_ptr() as usize);
    // Another thread tries to make it current and to ask for its buffer,
    // then draws green with it if it could (and ends with it current).
    let elsewhere = move || {
        std::thread::spawn(move || {
            let ctx = handle as OSMesaContext;
            let (mut w, mut h, mut f, mut p) = (0, 0, 0, null_mut::<c_void>());
            // SAFETY: valid output pointers.
            let asked = unsafe { OSMesaGetColorBuffer(ctx, &mut w, &mut h, &mut f, &mut p) };
            let mut other = vec![0u8; 4 * 4 * 4];
            // SAFETY: 4x4 RGBA pixels, alive until the thread ends, which
            // releases the context.
            let made = unsafe { OSMesaMakeCurrent(ctx, other.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 4, 4) };
            fill_with_attribute_calls(4.0, [0, 255, 0]);
            (asked, p as usize, made, other[..4].to_vec())
        })
        .join()
        .unwrap()
    };
    assert_eq!(elsewhere(), (GL_FALSE, 0, GL_FALSE, vec![0; 4]), "current here");
    // Here it still draws.
    fill_with_attribute_calls(4.0, [255, 0, 0]);
    assert_eq!(px(&buf, 4, 3, 3), [255, 0, 0, 255]);
    // SAFETY: null context and buffer: releases.
    assert_eq!(unsafe { OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0) }, GL_TRUE);
    assert_eq!(
        elsewhere(),
        (GL_TRUE, mine, GL_TRUE, vec![0, 255, 0, 255]),
        "current nowhere"
    );
    // The other thread's end released it; its current colour is the context's.
    // SAFETY: `buf` holds 4x4 RGBA pixels and outlives the binding.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 4, 4) },
        GL_TRUE
    );
    let mut color = [0.0f32; 4];
    // SAFETY: room for the 4 values of GL_CURRENT_COLOR.
    unsafe { glGetFloatv(GL_CURRENT_COLOR, color.as_mut_ptr()) };
    assert_eq!(color, [0.0, 1.0, 0.0, 1.0]);
    OSMesaDestroyContext(ctx);
}

#[test]
fn a_new_type_for_the_same_context_leaves_the_old_buffer_alone() {
    let mut bytes = vec![0u8; 2 * 2 * 4];
    let ctx = current(&mut bytes, 2, 2);
    glClearColor(1.0, 0.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    // Deferred, as llvmpipe's: the clear reaches the buffer at the flush.
    glFinish();
    assert_eq!(px(&bytes, 2, 1, 1), [255, 0, 0, 255]);
    // The same context on a float buffer of the same size: softgl's own
    // RGBA8 buffer, converted at glFinish; the byte buffer is not drawn on.
    let mut floats = vec![0.0f32; 2 * 2 * 4];
    // SAFETY: 2x2 pixels of 4 floats.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, floats.as_mut_ptr().cast(), GL_FLOAT, 2, 2) },
        GL_TRUE
    );
    glClearColor(0.0, 1.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    assert_eq!(px(&bytes, 2, 1, 1), [255, 0, 0, 255]);
    assert_eq!(&floats[..4], &[0.0, 1.0, 0.0, 1.0]);
    // And back to bytes: drawn into directly again.
    // SAFETY: 2x2 RGBA pixels.
    assert_eq!(
        unsafe { OSMesaMakeCurrent(ctx, bytes.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 2, 2) },
        GL_TRUE
    );
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    assert_eq!(px(&bytes, 2, 1, 1), [0, 255, 0, 255]);
    OSMesaDestroyContext(ctx);
}

#[test]
fn interleaved_arrays_draw_like_separate_ones() {
    #[repr(C)]
    #[derive(Clone, Copy)]
    struct C4ubV3f {
        c: [u8; 4],
        v: [f32; 3],
    }
    let verts = [
        C4ubV3f {
            c: [255, 0, 0, 255],
            v: [1.0, 1.0, 0.0],
        },
        C4ubV3f {
            c: [0, 255, 0, 255],
            v: [15.0, 2.0, 0.0],
        },
        C4ubV3f {
            c: [0, 0, 255, 255],
            v: [8.0, 14.0, 0.0],
        },
    ];
    let mut a = vec![0u8; 16 * 16 * 4];
    let ctx = current(&mut a, 16, 16);
    // SAFETY: `verts` outlives the draw; GL_C4UB_V3F is 16 bytes a vertex.
    unsafe { glInterleavedArrays(0x2A23, 0, verts.as_ptr().cast()) };
    assert_eq!(glIsEnabled(GL_COLOR_ARRAY), GL_TRUE);
    assert_eq!(glIsEnabled(GL_NORMAL_ARRAY), GL_FALSE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    assert_eq!(glGetError(), GL_NO_ERROR);
    let interleaved = a.clone();
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    for v in &verts {
        glColor4ub(v.c[0], v.c[1], v.c[2], v.c[3]);
        glVertex3f(v.v[0], v.v[1], v.v[2]);
    }
    glEnd();
    glFinish();
    assert_eq!(a, interleaved);
    assert!(
        a.chunks_exact(4).filter(|p| p[3] == 255).count() > 60,
        "the triangle was drawn"
    );
    // SAFETY: refused before any use.
    unsafe { glInterleavedArrays(0x1234, 0, verts.as_ptr().cast()) };
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    OSMesaDestroyContext(ctx);
}

/// `OSMesaGetDepthBuffer` on a context made current on a `w`×`h` RGBA
/// buffer: the return value, width, height, bytes per value and the values
/// (read over the whole `w × h × bytes` it reports), outputs pre-set to junk.
fn depth_buffer(ctx: OSMesaContext) -> (u8, i32, i32, i32, Option<Vec<u32>>) {
    let (mut w, mut h, mut bpv, mut p) = (-1, -1, -1, std::ptr::dangling_mut::<c_void>());
    // SAFETY: valid output pointers.
    let r = unsafe { OSMesaGetDepthBuffer(ctx, &mut w, &mut h, &mut bpv, &mut p) };
    let values = (!p.is_null()).then(|| {
        let n = (w * h) as usize;
        // SAFETY: OSMesaGetDepthBuffer's promise: `w × h` values of `bpv` bytes at `p`.
        unsafe {
            match bpv {
                2 => std::slice::from_raw_parts(p.cast::<u16>(), n)
                    .iter()
                    .map(|&v| u32::from(v))
                    .collect(),
                _ => std::slice::from_raw_parts(p.cast::<u32>(), n).to_vec(),
            }
        }
    });
    (r, w, h, bpv, values)
}

fn get_int(pname: u32) -> i32 {
    let mut v = -1;
    // SAFETY: room for one value.
    unsafe { glGetIntegerv(pname, &mut v) };
    v
}

/// Mesa 22.3.6 (llvmpipe) answers, measured with a C probe on every depth
/// and stencil size (docs/osmesa-facts.md): `(depth bits asked, stencil bits
/// asked, GL_TRUE?, bytes per value, GL_DEPTH_BITS, GL_STENCIL_BITS, the
/// value after glClearDepth(0.5), glClearStencil(0x5a), glClear)`.
const MESA_DEPTH_TABLE: [(i32, i32, u8, i32, i32, i32, u32); 8] = [
    (0, 0, GL_FALSE, 0, 0, 0, 0),
    (0, 8, GL_FALSE, 0, 0, 8, 0),
    (16, 0, GL_TRUE, 2, 16, 0, 0x8000),
    (16, 8, GL_TRUE, 4, 24, 8, 0x5a80_0000),
    (24, 0, GL_TRUE, 4, 24, 0, 0x0080_0000),
    (24, 8, GL_TRUE, 4, 24, 8, 0x5a80_0000),
    (32, 0, GL_TRUE, 4, 24, 0, 0x0080_0000),
    (32, 8, GL_TRUE, 4, 24, 8, 0x5a80_0000),
];

#[test]
fn depth_buffer_answers_as_mesa_for_every_depth_and_stencil_size() {
    const GL_DEPTH_BITS: u32 = 0x0D56;
    const GL_STENCIL_BITS: u32 = 0x0D57;
    let (w, h) = (7, 5);
    for (depth, stencil, ret, bpv, depth_bits, stencil_bits, cleared) in MESA_DEPTH_TABLE {
        let what = format!("depth {depth} stencil {stencil}");
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth, stencil, 0, null_mut());
        let mut buf = vec![0u8; (w * h * 4) as usize];
        // SAFETY: `buf` holds w × h RGBA pixels and outlives the binding.
        assert_eq!(
            unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, w, h) },
            GL_TRUE
        );
        assert_eq!(
            (get_int(GL_DEPTH_BITS), get_int(GL_STENCIL_BITS)),
            (depth_bits, stencil_bits),
            "{what}"
        );
        glClearDepth(0.5);
        glClearStencil(0x5a);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glFinish();
        let (r, rw, rh, rbpv, values) = depth_buffer(ctx);
        if ret == GL_FALSE {
            assert_eq!(
                (r, rw, rh, rbpv, values),
                (GL_FALSE, 0, 0, 0, None),
                "{what}: zeros and NULL, as Mesa"
            );
        } else {
            assert_eq!((r, rw, rh, rbpv), (GL_TRUE, w, h, bpv), "{what}");
            assert_eq!(values, Some(vec![cleared; (w * h) as usize]), "{what}");
        }
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn depth_buffer_follows_a_new_size_and_survives_a_viewport() {
    for (depth, stencil) in [(16, 0), (24, 0), (24, 8)] {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth, stencil, 0, null_mut());
        let mut small = vec![0u8; 3 * 2 * 4];
        let mut large = vec![0u8; 9 * 6 * 4];
        // SAFETY: each buffer holds the pixels its call names and outlives its binding.
        unsafe {
            assert_eq!(
                OSMesaMakeCurrent(ctx, small.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 3, 2),
                GL_TRUE
            );
            let (_, w, h, _, v) = depth_buffer(ctx);
            assert_eq!((w, h, v.map(|v| v.len())), (3, 2, Some(6)));
            // A larger buffer: the depth buffer grows with it, and so does what is handed out.
            assert_eq!(
                OSMesaMakeCurrent(ctx, large.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 9, 6),
                GL_TRUE
            );
        }
        glViewport(0, 0, 100, 100);
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glFinish();
        let (r, w, h, _, v) = depth_buffer(ctx);
        let full = if depth == 16 { 0xffff } else { 0x00ff_ffff };
        assert_eq!(
            (r, w, h, v),
            (GL_TRUE, 9, 6, Some(vec![full; 54])),
            "depth {depth} stencil {stencil}"
        );
        // Back to the small one: the view shrinks too.
        // SAFETY: as above.
        assert_eq!(
            unsafe { OSMesaMakeCurrent(ctx, small.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 3, 2) },
            GL_TRUE
        );
        let (_, w, h, _, v) = depth_buffer(ctx);
        assert_eq!((w, h, v.map(|v| v.len())), (3, 2, Some(6)));
        OSMesaDestroyContext(ctx);
        // A destroyed handle: GL_FALSE and zeros, never a pointer.
        assert_eq!(depth_buffer(ctx), (GL_FALSE, 0, 0, 0, None));
    }
}

#[test]
fn make_current_with_null_context_and_buffer_releases_as_mesa() {
    // Mesa 22.3.6 (measured): (NULL, NULL, any type, 0, 0) → GL_TRUE and no
    // current context; (NULL, buffer, …) → GL_FALSE; (ctx, NULL, …) → GL_FALSE,
    // the current context unchanged in both.
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    // SAFETY: null arguments are never dereferenced; `buf` holds 4x4 RGBA pixels.
    unsafe {
        assert_eq!(
            OSMesaMakeCurrent(null_mut(), buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 4, 4),
            GL_FALSE
        );
        assert_eq!(OSMesaGetCurrentContext(), ctx);
        assert_eq!(OSMesaMakeCurrent(ctx, null_mut(), GL_UNSIGNED_BYTE, 4, 4), GL_FALSE);
        assert_eq!(OSMesaGetCurrentContext(), ctx);
        assert_eq!(
            OSMesaMakeCurrent(null_mut(), null_mut(), GL_UNSIGNED_BYTE, 0, 0),
            GL_TRUE
        );
    }
    assert!(OSMesaGetCurrentContext().is_null());
    // Nothing is current: GL calls do nothing, the buffer stays as it was.
    glClearColor(1.0, 1.0, 1.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    assert_eq!(px(&buf, 4, 0, 0), [0, 0, 0, 0]);
    // SAFETY: as above.
    unsafe {
        assert_eq!(
            OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0),
            GL_TRUE,
            "twice, any type"
        );
        assert_eq!(
            OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 4, 4),
            GL_TRUE
        );
    }
    assert_eq!(OSMesaGetCurrentContext(), ctx);
    OSMesaDestroyContext(ctx);
}

#[test]
fn releasing_a_converted_format_copies_its_last_frame() {
    let mut floats = vec![-1.0f32; 4];
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, null_mut());
    // SAFETY: one pixel of 4 floats, alive past the release below.
    unsafe {
        assert_eq!(
            OSMesaMakeCurrent(ctx, floats.as_mut_ptr().cast(), GL_FLOAT, 1, 1),
            GL_TRUE
        );
    }
    glClearColor(0.0, 0.0, 1.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    // SAFETY: null arguments are not dereferenced.
    assert_eq!(unsafe { OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0) }, GL_TRUE);
    assert_eq!(floats, [0.0, 0.0, 1.0, 1.0]);
    OSMesaDestroyContext(ctx);
}

#[test]
fn a_draw_without_arrays_between_begin_and_end_is_invalid_operation() {
    const GL_COMPILE: u32 = 0x1300;
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current(&mut buf, 4, 4);
    // No vertex array enabled: GL draws nothing, but inside glBegin/glEnd
    // the draw is still an error (piglit's gl-1.0-dlist-beginend).
    glBegin(GL_TRIANGLES);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    assert_eq!(glGetError(), GL_NO_ERROR);
    // Recorded in a list, the error comes when the list runs inside glBegin.
    let list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndList();
    assert_eq!(glGetError(), GL_NO_ERROR);
    glBegin(GL_TRIANGLES);
    glCallList(list);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    OSMesaDestroyContext(ctx);
}
