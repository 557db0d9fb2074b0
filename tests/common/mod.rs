//! Helpers shared by the integration tests.

use softgl::Context;

/// Number of pixels of `gl`'s RGBA8 color buffer equal to `rgba`.
pub fn count(gl: &Context, rgba: [u8; 4]) -> usize {
    gl.framebuffer()
        .color_bytes()
        .chunks_exact(4)
        .filter(|p| *p == rgba)
        .count()
}
