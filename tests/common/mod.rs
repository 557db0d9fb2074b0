//! Helpers shared by the integration tests.

use softgl::Context;

/// Number of pixels of `gl`'s RGBA8 color buffer equal to `rgba`.
#[allow(dead_code)] // Not every test that shares this module counts pixels.
pub fn count(gl: &mut Context, rgba: [u8; 4]) -> usize {
    gl.framebuffer()
        .color_bytes()
        .chunks_exact(4)
        .filter(|p| *p == rgba)
        .count()
}

/// Scenes recorded from llvmpipe as lines `name hex` (the RGBA bytes of the
/// colour buffer, bottom row first), by name.
#[allow(dead_code)] // Not every test that shares this module reads recordings.
pub fn hex_scenes(text: &str) -> std::collections::HashMap<String, Vec<u8>> {
    text.lines()
        .filter_map(|l| l.split_once(' '))
        .map(|(name, hex)| {
            let byte = |pair: &[u8]| u8::from_str_radix(std::str::from_utf8(pair).expect("ascii"), 16).expect("hex");
            (name.to_string(), hex.as_bytes().chunks(2).map(byte).collect())
        })
        .collect()
}

/// A framebuffer object (bound to both targets) whose depth is level 0 of
/// the new `size`² `GL_DEPTH_COMPONENT24` texture `texture` (left bound).
#[allow(dead_code)] // Only the render-to-depth-texture tests use it.
pub fn depth_texture_object(gl: &mut Context, texture: u32, size: i32) -> u32 {
    use softgl::fbo::{AttachmentPoint, FramebufferTarget};
    use softgl::texture::{InternalFormat, TexImageTarget, TextureTarget};
    gl.bind_texture(TextureTarget::D2, texture).unwrap();
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::DepthComponent24,
        [size, size, 1],
        0,
        None,
    )
    .unwrap();
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(FramebufferTarget::Both, fb).unwrap();
    gl.framebuffer_texture(
        FramebufferTarget::Both,
        AttachmentPoint::Depth,
        Some(TexImageTarget::D2),
        texture,
        0,
        0,
    )
    .unwrap();
    fb
}

/// Level 0 of the bound 2D texture as `n` depth floats (`glGetTexImage`).
#[allow(dead_code)] // Only the render-to-depth-texture tests use it.
pub fn depth_texels(gl: &mut Context, n: usize) -> Vec<f32> {
    use softgl::texture::{PixelFormat, PixelStore, PixelType, TexImageTarget};
    let mut out = vec![0u8; 4 * n];
    gl.get_tex_image(
        TexImageTarget::D2,
        0,
        PixelFormat::DepthComponent,
        PixelType::Float,
        &PixelStore::DEFAULT,
        &mut out,
    )
    .unwrap();
    out.chunks(4)
        .map(|c| f32::from_ne_bytes(c.try_into().unwrap()))
        .collect()
}

/// A quad of colour `rgba` over the whole viewport (identity matrices).
#[allow(dead_code)] // Only the colour-format tests use it.
pub fn quad(gl: &mut Context, rgba: [f32; 4]) {
    gl.begin(softgl::PrimitiveMode::Quads).unwrap();
    gl.color4(rgba[0], rgba[1], rgba[2], rgba[3]);
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
}
