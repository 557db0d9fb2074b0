//! GL's colour renderbuffer formats through the Rust API (`src/fbo.rs`
//! `RenderbufferFormat::kind`): the storage each takes, the sizes it
//! reports, half floats truncated, RGB formats' alpha 1, clears past 1 in
//! float objects. Compared with llvmpipe by `osmesa/tests/c/fbo_formats.c`.

mod common;

use softgl::fbo::{AttachmentPoint as P, FramebufferStatus as S, FramebufferTarget as T, RenderbufferFormat as F};
use softgl::{BlendFactor, Capability, ClearMask, ColorFormat, Context, FramebufferDesc};

/// An object of a `format` renderbuffer, 8×8, bound; its status.
fn object(gl: &mut Context, format: F) -> S {
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    let rb = gl.gen_renderbuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.bind_renderbuffer(rb).unwrap();
    gl.renderbuffer_storage(0, format, 8, 8).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Color(0), rb).unwrap();
    gl.viewport(0, 0, 8, 8).unwrap();
    gl.check_framebuffer_status(T::Both).unwrap()
}

fn context() -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap()
}

#[test]
fn every_colour_format_renders_on_a_storage_of_at_least_its_bits() {
    let cases = [
        (F::Rgba2, ColorFormat::Rgba8),
        (F::Rgba4, ColorFormat::Rgba8),
        (F::Rgb5A1, ColorFormat::Rgba8),
        (F::R3G3B2, ColorFormat::Rgb565),
        (F::Rgb4, ColorFormat::Rgb565),
        (F::Rgb5, ColorFormat::Rgb565),
        (F::Rgb10, ColorFormat::Rgbx16),
        (F::Rgb10A2, ColorFormat::Rgba16),
        (F::Rgb12, ColorFormat::Rgbx16),
        (F::Rgba12, ColorFormat::Rgba16),
        (F::Rgb16, ColorFormat::Rgbx16),
        (F::Rgba16F, ColorFormat::Rgba16F),
        (F::Rgb16F, ColorFormat::Rgbx16F),
        (F::Rgb32F, ColorFormat::Rgbx32F),
    ];
    for (format, storage) in cases {
        let mut gl = context();
        assert_eq!(object(&mut gl, format), S::Complete, "{format:?}");
        let bits: Vec<u32> = (0..4).map(|c| storage.channel_bits(c)).collect();
        assert_eq!(format.bits()[..4], bits[..], "{format:?}");
        let (desc, _) = gl.draw_framebuffer_desc().unwrap();
        assert_eq!(desc.color, storage, "{format:?}");
        // No alpha stored: alpha reads 1, cleared or drawn.
        gl.clear_color(0.5, 0.25, 0.75, 0.0).unwrap();
        gl.clear(ClearMask::COLOR).unwrap();
        common::quad(&mut gl, [0.5, 0.25, 0.75, 0.0]);
        let a = gl.read_pixels_f32(2, 2, 1, 1).unwrap()[0][3];
        assert_eq!(a, if storage.has_alpha() { 0.0 } else { 1.0 }, "{format:?}");
    }
}

#[test]
fn half_floats_are_truncated_at_every_store() {
    let mut gl = context();
    assert_eq!(object(&mut gl, F::Rgba16F), S::Complete);
    // Clears: toward zero (0.3 → 1228/4096), past 65504 to 65504, unclamped.
    gl.clear_color(0.3, -2.5, 70000.0, 3.0e-6).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    let px = gl.read_pixels_f32(1, 1, 1, 1).unwrap()[0];
    assert_eq!(px, [1228.0 / 4096.0, -2.5, 65504.0, 50.0 / 16_777_216.0]);
    // GL_COLOR_CLEAR_VALUE unclamped while a float object is drawn, clamped otherwise.
    assert_eq!(gl.clear_color_value(), [0.3, -2.5, 70000.0, 3.0e-6]);
    // Blended in f32, stored truncated: 1000 + 0.3 is 1000 (a half's step is 0.5 there).
    gl.clear_color(1000.0, 0.5, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.enable(Capability::Blend).unwrap();
    gl.blend_func(BlendFactor::One, BlendFactor::One).unwrap();
    common::quad(&mut gl, [0.3, 0.3, 0.6, 0.5]);
    let px = gl.read_pixels_f32(1, 1, 1, 1).unwrap()[0];
    assert_eq!(px, [1000.0, 3276.0 / 4096.0, 2456.0 / 4096.0, 1.5]);
    gl.bind_framebuffer(T::Both, 0).unwrap();
    assert_eq!(gl.clear_color_value(), [1.0, 0.5, 0.0, 1.0]);
}
