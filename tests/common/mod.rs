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
