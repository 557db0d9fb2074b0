//! Framebuffers drawing into lent colour memory (what the OSMesa C ABI does
//! with the caller's buffer): row strides with padding, top-down rows, and
//! memory too small for the size refused.

use softgl::{
    Clear, ClearMask, ColorFormat, ColorMemory, Context, Framebuffer, FramebufferDesc, GlError, PrimitiveMode,
};
use std::sync::{Arc, Mutex};

/// Memory shared with the test, so that it can look at what was drawn.
#[derive(Clone)]
struct Shared(Arc<Mutex<Vec<u8>>>);

/// A `ColorMemory` over a vector (the test keeps the other handle).
struct Lent(Vec<u8>, Shared);

impl ColorMemory for Lent {
    fn bytes(&self) -> &[u8] {
        &self.0
    }

    fn bytes_mut(&mut self) -> &mut [u8] {
        &mut self.0
    }
}

impl Drop for Lent {
    fn drop(&mut self) {
        *self.1 .0.lock().unwrap() = std::mem::take(&mut self.0);
    }
}

const W: usize = 4;
const H: usize = 3;
const STRIDE: usize = 6 * 4; // 2 pixels of padding per row

/// Draws a red bottom row over a blue clear into lent memory and returns the bytes.
fn draw(top_down: bool) -> Vec<u8> {
    let shared = Shared(Arc::new(Mutex::new(Vec::new())));
    let desc = FramebufferDesc {
        color: ColorFormat::Rgba8,
        ..FramebufferDesc::rgba8_d24s8(W as u32, H as u32)
    };
    let mem = Lent(vec![0xA5; STRIDE * H], shared.clone());
    let fb = Framebuffer::with_color_memory(desc, Box::new(mem), STRIDE, top_down).unwrap();
    assert_eq!((fb.color_stride(), fb.color_top_down()), (STRIDE, top_down));
    let mut gl = Context::new(desc).unwrap();
    gl.replace_framebuffer(fb);
    gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.ortho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0).unwrap();
    gl.begin(PrimitiveMode::Quads).unwrap();
    gl.color3(1.0, 0.0, 0.0);
    gl.vertex2(0.0, 0.0);
    gl.vertex2(W as f32, 0.0);
    gl.vertex2(W as f32, 1.0);
    gl.vertex2(0.0, 1.0);
    gl.end().unwrap();
    // Window (0, 0) reads red whatever the layout.
    assert_eq!(gl.framebuffer().pixel(0, 0), Some([255, 0, 0, 255]));
    assert_eq!(gl.framebuffer().pixel(3, 2), Some([0, 0, 255, 255]));
    drop(gl);
    let bytes = shared.0.lock().unwrap().clone();
    bytes
}

#[test]
fn bottom_up_rows_with_padding() {
    let b = draw(false);
    assert_eq!(&b[..4], &[255, 0, 0, 255], "row 0 is the bottom");
    assert_eq!(&b[STRIDE..STRIDE + 4], &[0, 0, 255, 255]);
    for row in b.chunks_exact(STRIDE) {
        assert!(row[W * 4..].iter().all(|&v| v == 0xA5), "padding written");
    }
}

#[test]
fn top_down_rows_with_padding() {
    let b = draw(true);
    assert_eq!(
        &b[2 * STRIDE..2 * STRIDE + 4],
        &[255, 0, 0, 255],
        "the last row is the bottom"
    );
    assert_eq!(&b[..4], &[0, 0, 255, 255]);
    for row in b.chunks_exact(STRIDE) {
        assert!(row[W * 4..].iter().all(|&v| v == 0xA5), "padding written");
    }
}

#[test]
fn memory_too_small_is_refused() {
    let shared = Shared(Arc::new(Mutex::new(Vec::new())));
    let desc = FramebufferDesc::rgba8_d24s8(W as u32, H as u32);
    let short = Lent(vec![0; STRIDE * (H - 1) + W * 4 - 1], shared.clone());
    let r = Framebuffer::with_color_memory(desc, Box::new(short), STRIDE, false);
    assert_eq!(r.err(), Some(GlError::InvalidValue));
    let exact = Lent(vec![0; STRIDE * (H - 1) + W * 4], shared.clone());
    let mut fb = Framebuffer::with_color_memory(desc, Box::new(exact), STRIDE, false).unwrap();
    // A stride below a row is refused and the framebuffer keeps its memory.
    let other = Lent(vec![0; 1000], shared);
    assert_eq!(
        fb.set_color_memory(Box::new(other), W * 4 - 1, false),
        Err(GlError::InvalidValue)
    );
    assert_eq!(fb.color_stride(), STRIDE);
}

#[test]
fn a_clone_owns_a_snapshot_of_lent_memory() {
    let shared = Shared(Arc::new(Mutex::new(Vec::new())));
    let desc = FramebufferDesc::rgba8_d24s8(W as u32, H as u32);
    let mem = Lent(vec![0; STRIDE * H], shared);
    let mut fb = Framebuffer::with_color_memory(desc, Box::new(mem), STRIDE, true).unwrap();
    let bounds = fb.bounds();
    let red = Clear::new(bounds).color(&fb, [1.0, 0.0, 0.0, 1.0], softgl::ColorMask::ALL);
    fb.apply_clear(&red);
    let snapshot = fb.clone();
    let green = Clear::new(bounds).color(&fb, [0.0, 1.0, 0.0, 1.0], softgl::ColorMask::ALL);
    fb.apply_clear(&green);
    assert_eq!(snapshot.pixel(1, 2), Some([255, 0, 0, 255]));
    assert_eq!(fb.pixel(1, 2), Some([0, 255, 0, 255]));
}
