//! Deferred rendering through the Rust API: draws and clears wait in the
//! scene until something reads the framebuffer, a draw keeps the state and
//! texels it was made with, and a scene past its memory bound flushes, even
//! in the middle of one draw, without changing a pixel.

use softgl::texture::{
    Filter, InternalFormat, MipFilter, PixelData, PixelFormat, PixelStore, PixelType, TexImageTarget, TexParam,
    TextureTarget,
};
use softgl::{Capability, ClearMask, Context, FramebufferDesc, PrimitiveMode, VertexArrays};

fn context(w: u32, h: u32) -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(w, h)).unwrap()
}

fn quad(gl: &mut Context, rgb: [f32; 3]) {
    gl.color3(rgb[0], rgb[1], rgb[2]);
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.vertex2(x, y);
    }
    gl.end().unwrap();
}

#[test]
fn draws_wait_until_the_framebuffer_is_read() {
    let mut gl = context(100, 70);
    gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    quad(&mut gl, [1.0, 0.0, 0.0]);
    let s = gl.scene_stats();
    assert_eq!(s.pending_primitives, 2, "the quad's two triangles wait");
    assert_eq!(
        gl.framebuffer_pending().pixel(50, 35),
        Some([0, 0, 0, 0]),
        "nothing drawn yet"
    );
    // Reading pixels flushes: every pixel is the quad's.
    let bytes = gl.read_pixels(0, 0, 100, 70, softgl::ReadFormat::Rgba8).unwrap();
    assert!(bytes.chunks(4).all(|p| p == [255, 0, 0, 255]));
    assert_eq!(gl.scene_stats().pending_primitives, 0);
    assert_eq!(gl.scene_stats().flushes, 1);
}

#[test]
fn clears_and_draws_keep_their_order_in_every_tile() {
    let mut gl = context(150, 130);
    gl.clear_color(1.0, 0.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    quad(&mut gl, [0.0, 1.0, 0.0]);
    // A scissored clear over the left half, after the quad.
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(0, 0, 75, 130).unwrap();
    gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.disable(Capability::ScissorTest).unwrap();
    let fb = gl.framebuffer();
    for (x, y) in [(0, 0), (74, 129), (70, 64), (1, 127)] {
        assert_eq!(
            fb.pixel(x, y),
            Some([0, 0, 255, 255]),
            "({x}, {y}) cleared after the quad"
        );
    }
    for (x, y) in [(75, 0), (149, 129), (128, 64)] {
        assert_eq!(fb.pixel(x, y), Some([0, 255, 0, 255]), "({x}, {y}) the quad's");
    }
}

/// A 1×1 RGBA8 texture of `rgba` on the bound 2D texture.
fn texel(gl: &mut Context, rgba: [u8; 4]) {
    let pixels = PixelData {
        format: PixelFormat::Rgba,
        ty: PixelType::UnsignedByte,
        store: PixelStore::DEFAULT,
        bytes: &rgba,
    };
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [1, 1, 1], 0, Some(pixels))
        .unwrap();
}

#[test]
fn a_draw_samples_the_texels_it_was_made_with() {
    let mut gl = context(80, 80);
    gl.bind_texture(TextureTarget::D2, 1).unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    texel(&mut gl, [10, 20, 30, 255]);
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(0, 0, 40, 80).unwrap();
    quad(&mut gl, [1.0, 1.0, 1.0]);
    // Rewritten while the first draw holds its texels: the draw is
    // rasterized first (as llvmpipe flushes before writing a resource a
    // scene reads), so no copy is made and only the second draw sees it.
    texel(&mut gl, [200, 100, 50, 255]);
    assert_eq!(gl.scene_stats().flushes, 1);
    gl.scissor(40, 0, 40, 80).unwrap();
    quad(&mut gl, [1.0, 1.0, 1.0]);
    // And deleted before the flush: the draw keeps the texels.
    gl.delete_textures(&[1]);
    assert_eq!(gl.scene_stats().pending_primitives, 2);
    let fb = gl.framebuffer();
    assert_eq!(fb.pixel(10, 10), Some([10, 20, 30, 255]));
    assert_eq!(fb.pixel(70, 70), Some([200, 100, 50, 255]));
}

/// `n` small triangles in a grid over a `w`×`h` window, in pixel coordinates.
fn grid(n: usize, w: u32, h: u32) -> (Vec<f32>, Vec<f32>) {
    let (mut pos, mut col) = (Vec::new(), Vec::new());
    for i in 0..n {
        let (x, y) = ((i * 7 % w as usize) as f32, (i * 13 / w as usize % h as usize) as f32);
        pos.extend_from_slice(&[x, y, x + 5.5, y + 0.5, x + 1.0, y + 4.5]);
        let c = (i % 255) as f32 / 255.0;
        for _ in 0..3 {
            col.extend_from_slice(&[c, 1.0 - c, 0.5]);
        }
    }
    (pos, col)
}

#[test]
fn a_draw_past_the_memory_bound_flushes_midway_and_draws_the_same_pixels() {
    let (w, h) = (200, 150);
    let (pos, col) = grid(20_000, w, h);
    let render = |bound: usize| {
        let mut gl = context(w, h);
        gl.set_scene_bound(bound);
        gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0).unwrap();
        gl.enable(Capability::Blend).unwrap();
        gl.blend_func(softgl::BlendFactor::One, softgl::BlendFactor::One)
            .unwrap();
        let arrays = VertexArrays::with_colors(2, &pos, 3, &col);
        gl.draw_arrays(PrimitiveMode::Triangles, 0, 60_000, &arrays).unwrap();
        let stats = gl.scene_stats();
        let bytes = gl.framebuffer().color_bytes().to_vec();
        (stats, bytes)
    };
    let (whole, image) = render(0);
    // Triangles reaching past the window's edge are clipped into several.
    assert_eq!(whole.flushes, 0, "16 MiB hold it all: {whole:?}");
    assert!(whole.pending_primitives >= 20_000, "{whole:?}");
    let bound = 256 << 10;
    let (split, split_image) = render(bound);
    assert!(split.flushes >= 5, "{split:?}");
    // The last primitive (~200 bytes) and its bin entries may pass the bound.
    assert!(split.peak_bytes <= bound + 1024, "{split:?}");
    assert!(image == split_image, "flushing midway changed pixels");
}

/// A scene past its bound is flushed on the pool while the next one
/// records (`raster/background.rs`): the bytes are those of one flush at
/// the end, for 1, 2 and 8 threads, a clear recorded while a flush is in
/// flight lands after it, and reading the framebuffer waits for it.
#[test]
fn scenes_flushed_in_the_background_draw_what_one_flush_draws() {
    let (w, h) = (200, 150);
    let (pos, col) = grid(20_000, w, h);
    let render = |threads: usize, bound: usize| {
        let mut gl = context(w, h);
        gl.set_threads(threads);
        gl.set_scene_bound(bound);
        gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0).unwrap();
        gl.enable(Capability::Blend).unwrap();
        gl.blend_func(softgl::BlendFactor::One, softgl::BlendFactor::One)
            .unwrap();
        gl.enable(Capability::DepthTest).unwrap();
        gl.depth_func(softgl::CompareFunc::Always).unwrap();
        let arrays = VertexArrays::with_colors(2, &pos, 3, &col);
        gl.draw_arrays(PrimitiveMode::Triangles, 0, 60_000, &arrays).unwrap();
        let middle = gl.scene_stats();
        // Recorded while the last background flush may still run: the
        // clear of the left half comes after it in every tile.
        gl.enable(Capability::ScissorTest).unwrap();
        gl.scissor(0, 0, 100, 150).unwrap();
        gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
        gl.clear(ClearMask::COLOR).unwrap();
        gl.disable(Capability::ScissorTest).unwrap();
        gl.draw_arrays(PrimitiveMode::Triangles, 0, 300, &arrays).unwrap();
        let pixels = gl
            .read_pixels(0, 0, w as i32, h as i32, softgl::ReadFormat::Rgba8)
            .unwrap();
        let depth = gl.framebuffer().depth_buffer().map(|d| format!("{d:?}"));
        (middle, gl.scene_stats(), pixels, depth)
    };
    let at_once = render(1, 0);
    assert_eq!(at_once.1.flushes, 1, "{:?}", at_once.1);
    // Some of the left half is the clear's blue, some of the right half is not.
    let px = |x: usize, y: usize| &at_once.2[(y * w as usize + x) * 4..][..4];
    assert!((0..150).any(|y| px(10, y) == [0, 0, 255, 255]));
    assert!((0..150).all(|y| px(150, y) != [0, 0, 255, 255]));
    let mut flushes = None;
    for threads in [1, 2, 8] {
        let split = render(threads, 256 << 10);
        assert!(split.0.flushes >= 5, "{threads} threads: {:?}", split.0);
        // The same flushes for any number of threads.
        assert_eq!(*flushes.get_or_insert(split.1.flushes), split.1.flushes);
        assert!(split.1.peak_bytes <= (256 << 10) + 1024, "{:?}", split.1);
        assert!(split.2 == at_once.2, "{threads} threads changed the colours");
        assert!(split.3 == at_once.3, "{threads} threads changed the depths");
    }
}

#[test]
fn draws_holding_more_than_64_mib_of_textures_are_flushed() {
    // 24 textures of 4 MiB, each uploaded, drawn with and deleted, no flush
    // asked for: the scene holds at most 64 MiB of them (llvmpipe's bound).
    let mut gl = context(16, 16);
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    let texels = vec![200u8; 1024 * 1024 * 4];
    for name in 1..=24 {
        gl.bind_texture(TextureTarget::D2, name).unwrap();
        gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
            .unwrap();
        let pixels = PixelData {
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            store: PixelStore::DEFAULT,
            bytes: &texels,
        };
        gl.tex_image(
            TexImageTarget::D2,
            0,
            InternalFormat::Rgba8,
            [1024, 1024, 1],
            0,
            Some(pixels),
        )
        .unwrap();
        quad(&mut gl, [1.0, 1.0, 1.0]);
        gl.delete_textures(&[name]);
    }
    // The 17th texture passes 64 MiB: the scene is flushed after its quad's
    // first triangle; its second and the 7 later quads (14 triangles) wait.
    let s = gl.scene_stats();
    assert_eq!((s.flushes, s.pending_primitives), (1, 15), "{s:?}");
    assert_eq!(gl.framebuffer().pixel(8, 8), Some([200, 200, 200, 200]));
}

#[test]
fn draws_whose_own_textures_pass_64_mib_flush_only_for_a_new_one() {
    // Unit 0 a 4096² RGBA8 texture (64 MiB), unit 1 a texel: every draw
    // holds more than the bound. As llvmpipe, only an image new to a scene
    // that held draws flushes it (it flushed after every primitive: MuJoCo's
    // light passes, a 64 MiB depth texture and the floor's).
    let mut gl = context(16, 16);
    let big = vec![90u8; 4096 * 4096 * 4];
    for (unit, name, side, bytes) in [(0, 1, 4096, &big[..]), (1, 2, 1, &[255u8; 4][..])] {
        gl.active_texture(unit).unwrap();
        gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
        gl.bind_texture(TextureTarget::D2, name).unwrap();
        gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
            .unwrap();
        let pixels = PixelData {
            format: PixelFormat::Rgba,
            ty: PixelType::UnsignedByte,
            store: PixelStore::DEFAULT,
            bytes,
        };
        gl.tex_image(
            TexImageTarget::D2,
            0,
            InternalFormat::Rgba8,
            [side, side, 1],
            0,
            Some(pixels),
        )
        .unwrap();
    }
    drop(big);
    for _ in 0..10 {
        quad(&mut gl, [1.0, 1.0, 1.0]);
    }
    let s = gl.scene_stats();
    assert_eq!((s.flushes, s.pending_primitives), (0, 20), "{s:?}");
    // A new texture on unit 1: the scene is flushed after the first
    // triangle of the draw that brings it.
    gl.bind_texture(TextureTarget::D2, 3).unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    texel(&mut gl, [255, 255, 255, 255]);
    assert_eq!(gl.scene_stats().flushes, 0);
    quad(&mut gl, [1.0, 1.0, 1.0]);
    let s = gl.scene_stats();
    assert_eq!((s.flushes, s.pending_primitives), (1, 1), "{s:?}");
    assert_eq!(gl.framebuffer().pixel(8, 8), Some([90, 90, 90, 90]));
}

/// A draw reuses the last untextured draw's plan (key, layout, uniforms)
/// only while nothing it was made of changed: each change below, through the
/// state, the texture units or the texture objects, shows in the next draw.
#[test]
fn every_state_change_reaches_the_next_draw_of_the_same_kind() {
    let mut gl = context(40, 40);
    let read = |gl: &mut Context| gl.read_pixels(20, 20, 1, 1, softgl::ReadFormat::Rgba8).unwrap();
    quad(&mut gl, [1.0, 0.0, 0.0]);
    assert_eq!(read(&mut gl), [255, 0, 0, 255]);
    // The state: a colour mask.
    gl.color_mask(false, true, true, true).unwrap();
    quad(&mut gl, [0.0, 1.0, 0.0]);
    assert_eq!(read(&mut gl), [255, 255, 0, 255], "red kept, green written");
    gl.color_mask(true, true, true, true).unwrap();
    quad(&mut gl, [0.0, 0.0, 1.0]);
    assert_eq!(read(&mut gl), [0, 0, 255, 255]);
    // The texture units: a 2D target enabled with no texture complete is no
    // texturing; one made complete (the texture objects) then samples.
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    quad(&mut gl, [1.0, 1.0, 1.0]);
    assert_eq!(read(&mut gl), [255, 255, 255, 255]);
    gl.bind_texture(TextureTarget::D2, 3).unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    texel(&mut gl, [10, 20, 30, 255]);
    quad(&mut gl, [1.0, 1.0, 1.0]);
    assert_eq!(read(&mut gl), [10, 20, 30, 255]);
    gl.disable(Capability::Texture(TextureTarget::D2)).unwrap();
    quad(&mut gl, [0.0, 1.0, 0.0]);
    assert_eq!(read(&mut gl), [0, 255, 0, 255]);
}
