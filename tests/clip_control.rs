//! `glClipControl` and float depth through the Rust API: errors, the z
//! mapping into a 32-bit float depth buffer, the near plane, the y flip and
//! facing (docs/llvmpipe-facts.md §39).

use softgl::{
    Capability, ClearMask, ClipControl, ClipDepthMode, ClipOrigin, ColorFormat, CompareFunc, Context, DepthFormat,
    Face, FramebufferDesc, GlError, PrimitiveMode,
};

const LL: u32 = ClipControl::GL_LOWER_LEFT;
const UL: u32 = ClipControl::GL_UPPER_LEFT;
const NEG: u32 = ClipControl::GL_NEGATIVE_ONE_TO_ONE;
const ZERO: u32 = ClipControl::GL_ZERO_TO_ONE;

fn float_depth_context(w: u32, h: u32) -> Context {
    let mut gl = Context::new(FramebufferDesc {
        width: w,
        height: h,
        color: ColorFormat::Rgba8,
        depth_bits: FramebufferDesc::FLOAT_DEPTH,
        stencil_bits: 8,
    })
    .unwrap();
    assert_eq!(gl.framebuffer().depth_format(), Some(DepthFormat::D32F));
    assert_eq!(
        gl.framebuffer().depth_at(0, 0),
        Some(1.0f32.to_bits()),
        "cleared to 1.0"
    );
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::Always).unwrap();
    gl
}

/// A quad over the whole viewport at clip z `z` (w = 1), in colour `c`.
fn quad(gl: &mut Context, z: f32, c: [f32; 3]) {
    gl.begin(PrimitiveMode::Quads).unwrap();
    gl.color3(c[0], c[1], c[2]);
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.vertex3(x, y, z);
    }
    gl.end().unwrap();
}

#[test]
fn clip_control_errors_and_state() {
    let mut gl = float_depth_context(4, 4);
    assert_eq!(gl.clip_control_state(), ClipControl::default());
    assert_eq!(gl.clip_control(LL + 7, ZERO), Err(GlError::InvalidEnum));
    assert_eq!(gl.clip_control(LL, LL), Err(GlError::InvalidEnum));
    assert_eq!(gl.clip_control_state().to_gl(), (LL, NEG));
    gl.clip_control(UL, ZERO).unwrap();
    assert_eq!(
        gl.clip_control_state(),
        ClipControl {
            origin: ClipOrigin::UpperLeft,
            depth: ClipDepthMode::ZeroToOne
        }
    );
    gl.begin(PrimitiveMode::Triangles).unwrap();
    assert_eq!(gl.clip_control(LL, NEG), Err(GlError::InvalidOperation));
    gl.end().unwrap();
    assert_eq!(gl.clip_control_state().to_gl(), (UL, ZERO));
}

#[test]
fn zero_to_one_maps_clip_z_onto_the_depth_range_exactly() {
    let mut gl = float_depth_context(4, 4);
    // Plain GL: clip z 0.25 is window 0.625; ZERO_TO_ONE: 0.25 itself, and a
    // small z keeps its precision (reverse Z's reason).
    quad(&mut gl, 0.25, [1.0, 0.0, 0.0]);
    gl.flush().unwrap();
    assert_eq!(gl.framebuffer().depth_at(1, 1), Some(0.625f32.to_bits()));
    gl.clip_control(LL, ZERO).unwrap();
    for z in [0.25f32, 3.0e-7, 0.0] {
        quad(&mut gl, z, [1.0, 0.0, 0.0]);
        gl.flush().unwrap();
        assert_eq!(gl.framebuffer().depth_at(2, 1), Some(z.to_bits()), "z {z}");
    }
    // With a depth range: n + (f − n)·z.
    gl.depth_range(0.25, 0.75).unwrap();
    quad(&mut gl, 0.5, [1.0, 0.0, 0.0]);
    gl.flush().unwrap();
    assert_eq!(gl.framebuffer().depth_at(2, 2), Some(0.5f32.to_bits()));
}

#[test]
fn zero_to_one_clips_at_z_zero() {
    let mut gl = float_depth_context(4, 4);
    gl.clear_color(0.0, 0.0, 0.0, 0.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    // Behind z = 0 but in front of z = −w: drawn by plain GL only.
    quad(&mut gl, -0.5, [1.0, 0.0, 0.0]);
    gl.flush().unwrap();
    assert_eq!(gl.framebuffer().pixel(1, 1), Some([255, 0, 0, 255]));
    gl.clip_control(LL, ZERO).unwrap();
    quad(&mut gl, -0.5, [0.0, 1.0, 0.0]);
    gl.flush().unwrap();
    assert_eq!(gl.framebuffer().pixel(1, 1), Some([255, 0, 0, 255]), "clipped away");
}

#[test]
fn upper_left_flips_y_and_keeps_facing() {
    let mut gl = float_depth_context(8, 8);
    gl.enable(Capability::CullFace).unwrap();
    gl.cull_face(Face::Back).unwrap();
    for (origin, red_row) in [(LL, 1), (UL, 6)] {
        gl.clip_control(origin, NEG).unwrap();
        gl.clear_color(0.0, 0.0, 0.0, 0.0).unwrap();
        gl.clear(ClearMask::ALL).unwrap();
        // A counter-clockwise triangle in the bottom half of clip space.
        gl.begin(PrimitiveMode::Triangles).unwrap();
        gl.color3(1.0, 0.0, 0.0);
        gl.vertex3(-1.0, -1.0, 0.0);
        gl.vertex3(1.0, -1.0, 0.0);
        gl.vertex3(0.0, 0.0, 0.0);
        gl.end().unwrap();
        gl.flush().unwrap();
        let fb = gl.framebuffer();
        assert_eq!(
            fb.pixel(4, red_row),
            Some([255, 0, 0, 255]),
            "origin {origin:#x}: front, drawn"
        );
        assert_eq!(fb.pixel(4, 7 - red_row), Some([0, 0, 0, 0]), "origin {origin:#x}");
    }
}
