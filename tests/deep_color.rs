//! Deep colour framebuffers through the Rust API (`ColorFormat::Rgba16`,
//! `ColorFormat::Rgba32F`): clears, draws and reads at their precision. The
//! same formats are compared with llvmpipe by `osmesa/tests/c/deep.c`.

mod common;

use softgl::{BlendFactor, Capability, ClearMask, ColorFormat, ColorMask, Context, FramebufferDesc};

fn context(color: ColorFormat) -> Context {
    Context::new(FramebufferDesc {
        width: 8,
        height: 8,
        color,
        depth_bits: 24,
        stencil_bits: 8,
    })
    .unwrap()
}

#[test]
fn rgba16_clears_and_draws_at_16_bits() {
    let mut gl = context(ColorFormat::Rgba16);
    // A whole-buffer clear: (int)(c * 65535 + 0.5), as llvmpipe's pipe->clear.
    gl.clear_color(0.3, 0.5, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    let px = gl.framebuffer().pixel_f32(2, 2).unwrap();
    assert_eq!(px.map(|c| (c * 65535.0).round() as u32), [19661, 32768, 0, 65535]);
    // A drawn colour: llvmpipe's rounding to even (0.3 · 65535 = 19660.5 → 19660).
    common::quad(&mut gl, [0.3, 0.1, 1.0, 0.5]);
    let px = gl.framebuffer().pixel_f32(3, 3).unwrap();
    assert_eq!(px.map(|c| (c * 65535.0).round() as u32), [19660, 6554, 65535, 32768]);
    // The 8-bit view of it.
    // The 8-bit view of it: 19660 / 65535 · 255 = 76.498.
    assert_eq!(gl.framebuffer().pixel(3, 3), Some([76, 26, 255, 128]));
    // A masked clear leaves the masked channels.
    gl.color_mask(false, true, false, false).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    let px = gl.framebuffer().pixel_f32(3, 3).unwrap();
    assert_eq!(px.map(|c| (c * 65535.0).round() as u32), [19660, 32768, 65535, 32768]);
    assert_eq!(
        gl.state().color_mask,
        ColorMask {
            r: false,
            g: true,
            b: false,
            a: false
        }
    );
}

#[test]
fn rgba32f_blends_unclamped_unless_asked() {
    let mut gl = context(ColorFormat::Rgba32F);
    gl.clear_color(0.5, 0.25, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.enable(Capability::Blend).unwrap();
    gl.blend_func(BlendFactor::One, BlendFactor::One).unwrap();
    common::quad(&mut gl, [0.75, 0.5, 0.25, 1.0]);
    common::quad(&mut gl, [0.75, 0.5, 0.25, 1.0]);
    let px = gl.read_pixels_f32(4, 4, 1, 1).unwrap()[0];
    assert_eq!(px, [2.0, 1.25, 0.5, 3.0]);
    // GL_CLAMP_FRAGMENT_COLOR TRUE clamps the fragment, not the blend.
    gl.set_clamp_fragment_color(true).unwrap();
    gl.blend_func(BlendFactor::One, BlendFactor::Zero).unwrap();
    gl.enable(Capability::ColorSum).unwrap();
    gl.secondary_color3(0.5, 0.75, 0.0);
    common::quad(&mut gl, [0.75, 0.5, 0.25, 1.0]);
    assert_eq!(gl.read_pixels_f32(4, 4, 1, 1).unwrap()[0], [1.0, 1.0, 0.25, 1.0]);
    gl.set_clamp_fragment_color(false).unwrap();
    common::quad(&mut gl, [0.75, 0.5, 0.25, 1.0]);
    assert_eq!(gl.read_pixels_f32(4, 4, 1, 1).unwrap()[0], [1.25, 1.25, 0.25, 1.0]);
}
