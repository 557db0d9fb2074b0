//! The accumulation buffer through the Rust API: allocated only when asked
//! for, GL's errors, Mesa's RGBA16 snorm arithmetic on known values (the
//! same operations are compared with llvmpipe byte for byte by
//! `osmesa/tests/c/accum.c`).

use softgl::{AccumOp, ClearMask, Context, Framebuffer, FramebufferDesc, GlError};

fn context(accum: bool) -> Context {
    let fb = Framebuffer::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap();
    let fb = if accum { fb.with_accum_buffer().unwrap() } else { fb };
    Context::with_framebuffer(fb)
}

#[test]
fn without_an_accumulation_buffer_accum_is_invalid_operation() {
    let mut gl = context(false);
    assert!(!gl.framebuffer().has_accum());
    assert_eq!(gl.accum(AccumOp::Load, 1.0), Err(GlError::InvalidOperation));
    assert_eq!(gl.get_error(), Some(GlError::InvalidOperation));
    // Clearing an absent buffer is no error.
    assert_eq!(gl.clear(ClearMask::ACCUM), Ok(()));
    assert_eq!(gl.get_error(), None);
    assert_eq!(AccumOp::from_gl(0x0105), Err(GlError::InvalidEnum));
    for op in [
        AccumOp::Accum,
        AccumOp::Load,
        AccumOp::Return,
        AccumOp::Mult,
        AccumOp::Add,
    ] {
        assert_eq!(AccumOp::from_gl(op.to_gl()), Ok(op));
    }
}

#[test]
fn clear_load_mult_add_and_return_give_mesas_values() {
    let mut gl = context(true);
    gl.clear_accum(0.5, -2.0, 1.0, 0.25).unwrap();
    assert_eq!(gl.state().clear_accum, [0.5, -1.0, 1.0, 0.25]);
    gl.clear(ClearMask::ACCUM).unwrap();
    // FLOAT_TO_SHORT: ((int)(65535 c) - 1) / 2.
    assert_eq!(
        gl.framebuffer().accum_buffer().unwrap().get(3, 3),
        Some([16383, -32768, 32767, 8191])
    );
    gl.accum(AccumOp::Mult, 0.5).unwrap();
    gl.accum(AccumOp::Add, 0.1).unwrap(); // + (short)(3276.7)
    assert_eq!(
        gl.framebuffer().accum_buffer().unwrap().get(0, 0),
        Some([8191 + 3276, -16384 + 3276, 16383 + 3276, 4095 + 3276])
    );
    // The colour buffer: cleared to (0.2, 0.4, 0.6, 0.8) = 51, 102, 153, 204.
    gl.clear_color(0.2, 0.4, 0.6, 0.8).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.accum(AccumOp::Load, 2.0).unwrap();
    // (short)(c/255 * 65534): 13107, 26214, 39321 (wraps), 52428 (wraps).
    let v = gl.framebuffer().accum_buffer().unwrap().get(5, 2).unwrap();
    assert_eq!(v, [13106, 26213, 39320u16 as i16, 52427u16 as i16]);
    // Return a scissored half: the rest keeps the cleared colour.
    gl.enable(softgl::Capability::ScissorTest).unwrap();
    gl.scissor(0, 0, 4, 8).unwrap();
    gl.accum(AccumOp::Load, 1.0).unwrap();
    gl.accum(AccumOp::Return, 0.5).unwrap();
    let fb = gl.framebuffer();
    // (short)(51/255 * 32767) = 6553; 6553 * 0.5/32767 * 255 = 25.498: 25.
    assert_eq!(fb.pixel(1, 1), Some([25, 51, 76, 102]));
    assert_eq!(fb.pixel(6, 1), Some([51, 102, 153, 204]));
}
