//! Framebuffer objects through the Rust API (`src/fbo.rs`): renderbuffer
//! and texture attachments, completeness, reads, blits, render to texture.

mod common;

use softgl::fbo::{
    AttachmentPoint as P, BlitFilter, BlitMask, FramebufferStatus as S, FramebufferTarget as T, RenderbufferFormat as F,
};
use softgl::texture::{
    Filter, InternalFormat, MipFilter, PixelFormat, PixelStore, PixelType, TexImageTarget, TexParam, TextureTarget,
};
use softgl::{Capability, ClearMask, CompareFunc, Context, FramebufferDesc, GlError, PrimitiveMode, ReadFormat};

fn context(w: u32, h: u32) -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(w, h)).unwrap()
}

/// A quad over the whole viewport at depth `z` (NDC) in `rgb`.
fn quad(gl: &mut Context, rgb: [f32; 3], z: f32) {
    gl.color3(rgb[0], rgb[1], rgb[2]);
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        gl.tex_coord2((x + 1.0) / 2.0, (y + 1.0) / 2.0);
        gl.vertex3(x, y, z);
    }
    gl.end().unwrap();
}

/// An FBO of an RGBA8 and a DEPTH24_STENCIL8 renderbuffer (`w`×`h`), bound.
fn rb_fbo(gl: &mut Context, w: i32, h: i32) -> u32 {
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    let rb = gl.gen_renderbuffers(2).unwrap();
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.bind_renderbuffer(rb[0]).unwrap();
    gl.renderbuffer_storage(0, F::Rgba8, w, h).unwrap();
    gl.bind_renderbuffer(rb[1]).unwrap();
    gl.renderbuffer_storage(0, F::Depth24Stencil8, w, h).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Color(0), rb[0]).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::DepthStencil, rb[1]).unwrap();
    fb
}

#[test]
fn a_renderbuffer_fbo_is_drawn_read_and_leaves_the_window_alone() {
    let mut gl = context(16, 16);
    gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    let fb = rb_fbo(&mut gl, 8, 4);
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    gl.viewport(0, 0, 8, 4).unwrap();
    gl.clear_color(1.0, 0.0, 0.0, 1.0).unwrap();
    gl.clear_depth(0.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::Gequal).unwrap();
    gl.viewport(0, 0, 4, 4).unwrap();
    quad(&mut gl, [0.0, 1.0, 0.0], 0.0);
    let px = gl.read_pixels(0, 0, 8, 4, ReadFormat::Rgba8).unwrap();
    assert_eq!(&px[..4], &[0, 255, 0, 255], "drawn into the object");
    assert_eq!(&px[4 * 7..4 * 8], &[255, 0, 0, 255], "cleared outside the quad");
    // Back to the window: its pixels are its own.
    gl.bind_framebuffer(T::Both, 0).unwrap();
    assert_eq!(gl.framebuffer().pixel(0, 0), Some([0, 0, 255, 255]));
    // Read from the object while the window is drawn.
    gl.bind_framebuffer(T::Read, fb).unwrap();
    let px = gl.read_pixels(0, 0, 1, 1, ReadFormat::Rgba8).unwrap();
    assert_eq!(px, [0, 255, 0, 255]);
    assert_eq!(gl.get_error(), None);
}

#[test]
fn completeness_and_its_errors() {
    let mut gl = context(8, 8);
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, fb).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::MissingAttachment));
    assert_eq!(gl.clear(ClearMask::COLOR), Err(GlError::InvalidFramebufferOperation));
    assert_eq!(gl.get_error(), Some(GlError::InvalidFramebufferOperation));
    let rb = gl.gen_renderbuffers(2).unwrap();
    gl.bind_renderbuffer(rb[0]).unwrap();
    gl.renderbuffer_storage(0, F::Rgba8, 4, 4).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Depth, rb[0]).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::IncompleteAttachment));
    gl.framebuffer_renderbuffer(T::Both, P::Depth, 0).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Color(0), rb[0]).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    // Separate depth and stencil renderbuffers: gallium's UNSUPPORTED.
    gl.bind_renderbuffer(rb[1]).unwrap();
    gl.renderbuffer_storage(0, F::DepthComponent24, 4, 4).unwrap();
    let s8 = gl.gen_renderbuffers(1).unwrap()[0];
    gl.framebuffer_renderbuffer(T::Both, P::Depth, rb[1]).unwrap();
    gl.bind_renderbuffer(s8).unwrap();
    gl.renderbuffer_storage(0, F::StencilIndex8, 4, 4).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Stencil, s8).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Unsupported));
    gl.framebuffer_renderbuffer(T::Both, P::Stencil, 0).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    // A draw buffer without an attachment: complete, as on llvmpipe (no
    // GL 3.0 draw-buffer rule with ARB_ES2_compatibility); it draws nothing.
    gl.draw_buffer(Some(1)).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    gl.draw_buffer(None).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    // Sizes and samples.
    assert_eq!(
        gl.renderbuffer_storage(0, F::Rgba8, 16385, 1),
        Err(GlError::InvalidValue)
    );
    // More samples than GL_MAX_SAMPLES: Mesa's GL_INVALID_OPERATION (as the C ABI).
    assert_eq!(
        gl.renderbuffer_storage(5, F::Rgba8, 1, 1),
        Err(GlError::InvalidOperation)
    );
    assert_eq!(gl.renderbuffer_storage(-1, F::Rgba8, 1, 1), Err(GlError::InvalidValue));
    gl.bind_renderbuffer(0).unwrap();
    assert_eq!(
        gl.renderbuffer_storage(0, F::Rgba8, 1, 1),
        Err(GlError::InvalidOperation)
    );
    gl.bind_framebuffer(T::Both, 0).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    assert_eq!(
        gl.framebuffer_renderbuffer(T::Both, P::Color(0), rb[0]),
        Err(GlError::InvalidOperation)
    );
}

fn rgba_texture(gl: &mut Context, name: u32, w: i32, h: i32) {
    gl.bind_texture(TextureTarget::D2, name).unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MagFilter(Filter::Nearest))
        .unwrap();
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [w, h, 1], 0, None)
        .unwrap();
}

#[test]
fn render_to_texture_then_sample_it() {
    let mut gl = context(8, 8);
    rgba_texture(&mut gl, 7, 4, 4);
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::D2), 7, 0, 0)
        .unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    gl.viewport(0, 0, 4, 4).unwrap();
    gl.clear_color(0.0, 1.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.viewport(0, 0, 2, 4).unwrap();
    quad(&mut gl, [1.0, 0.0, 0.0], 0.0);
    // glGetTexImage while still bound sees the pixels.
    let mut out = vec![0u8; 64];
    gl.get_tex_image(
        TexImageTarget::D2,
        0,
        PixelFormat::Rgba,
        PixelType::UnsignedByte,
        &PixelStore::DEFAULT,
        &mut out,
    )
    .unwrap();
    assert_eq!(&out[..4], &[255, 0, 0, 255]);
    assert_eq!(&out[12..16], &[0, 255, 0, 255]);
    // Sampled into the window.
    gl.bind_framebuffer(T::Both, 0).unwrap();
    gl.viewport(0, 0, 8, 8).unwrap();
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    quad(&mut gl, [1.0, 1.0, 1.0], 0.0);
    let f = gl.framebuffer();
    assert_eq!(f.pixel(0, 0), Some([255, 0, 0, 255]));
    assert_eq!(f.pixel(7, 7), Some([0, 255, 0, 255]));
    assert_eq!(gl.get_error(), None);
}

#[test]
fn a_depth_texture_is_rendered_and_read_back() {
    let mut gl = context(8, 8);
    gl.bind_texture(TextureTarget::D2, 3).unwrap();
    gl.tex_parameter(TextureTarget::D2, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
        .unwrap();
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::DepthComponent24,
        [4, 4, 1],
        0,
        None,
    )
    .unwrap();
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.framebuffer_texture(T::Both, P::Depth, Some(TexImageTarget::D2), 3, 0, 0)
        .unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    gl.draw_buffer(None).unwrap();
    gl.read_buffer(None, false).unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    gl.viewport(0, 0, 4, 4).unwrap();
    gl.clear_depth(1.0).unwrap();
    gl.clear(ClearMask::DEPTH).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.viewport(0, 0, 2, 4).unwrap();
    quad(&mut gl, [1.0, 1.0, 1.0], 0.0);
    gl.bind_framebuffer(T::Both, 0).unwrap();
    let texels = common::depth_texels(&mut gl, 16);
    let z = |i: usize| texels[i];
    // Window depth 0.5 is rint(0.5 · 0xffffff) = 0x800000 in the depth
    // test, sampled as llvmpipe reads Z24: z · f32(1/0xffffff).
    assert_eq!(z(0), 0x80_0000 as f32 * (1.0 / 16_777_215.0f64) as f32);
    assert_eq!(z(1), z(0));
    assert_eq!((z(2), z(3)), (1.0, 1.0), "cleared, not drawn");
}

#[test]
fn blits_scale_flip_and_check_their_arguments() {
    let mut gl = context(8, 8);
    let a = rb_fbo(&mut gl, 4, 4);
    gl.viewport(0, 0, 4, 4).unwrap();
    gl.clear_color(0.0, 0.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.viewport(0, 0, 2, 2).unwrap();
    quad(&mut gl, [1.0, 0.0, 0.0], 0.0);
    gl.bind_framebuffer(T::Read, a).unwrap();
    gl.bind_framebuffer(T::Draw, 0).unwrap();
    let all = BlitMask {
        color: true,
        depth: false,
        stencil: false,
    };
    // 4×4 → 8×8 flipped vertically.
    gl.blit_framebuffer([0, 0, 4, 4], [0, 8, 8, 0], all, BlitFilter::Nearest)
        .unwrap();
    let f = gl.framebuffer();
    assert_eq!(f.pixel(0, 7), Some([255, 0, 0, 255]));
    assert_eq!(f.pixel(3, 4), Some([255, 0, 0, 255]));
    assert_eq!(f.pixel(0, 0), Some([0, 0, 0, 255]));
    // Depth with LINEAR: INVALID_OPERATION; depth formats differ: INVALID_OPERATION.
    let depth = BlitMask {
        depth: true,
        ..Default::default()
    };
    assert_eq!(
        gl.blit_framebuffer([0, 0, 4, 4], [0, 0, 4, 4], depth, BlitFilter::Linear),
        Err(GlError::InvalidOperation)
    );
    let b = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Draw, b).unwrap();
    let rb = gl.gen_renderbuffers(1).unwrap()[0];
    gl.bind_renderbuffer(rb).unwrap();
    gl.renderbuffer_storage(0, F::DepthComponent16, 4, 4).unwrap();
    gl.framebuffer_renderbuffer(T::Draw, P::Depth, rb).unwrap();
    gl.draw_buffer(None).unwrap();
    assert_eq!(
        gl.blit_framebuffer([0, 0, 4, 4], [0, 0, 4, 4], depth, BlitFilter::Nearest),
        Err(GlError::InvalidOperation)
    );
    // Incomplete draw framebuffer.
    gl.framebuffer_renderbuffer(T::Draw, P::Color(0), rb).unwrap();
    assert_eq!(
        gl.blit_framebuffer([0, 0, 4, 4], [0, 0, 4, 4], all, BlitFilter::Nearest),
        Err(GlError::InvalidFramebufferOperation)
    );
}

#[test]
fn large_and_tiny_framebuffers() {
    let mut gl = context(4, 4);
    let _ = rb_fbo(&mut gl, 1, 1);
    gl.viewport(0, 0, 1, 1).unwrap();
    quad(&mut gl, [0.0, 0.0, 1.0], 0.0);
    assert_eq!(gl.read_pixels(0, 0, 1, 1, ReadFormat::Rgba8).unwrap(), [0, 0, 255, 255]);
    let _ = rb_fbo(&mut gl, 8192, 8192);
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    gl.viewport(0, 0, 8192, 8192).unwrap();
    gl.clear_color(0.0, 1.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.viewport(4096, 4096, 4096, 4096).unwrap();
    quad(&mut gl, [1.0, 0.0, 0.0], 0.0);
    let px = gl.read_pixels(4095, 8191, 2, 1, ReadFormat::Rgba8).unwrap();
    assert_eq!(px, [0, 255, 0, 255, 255, 0, 0, 255]);
}

/// The bound texture's level 0 of `target` as RGBA bytes.
fn texels(gl: &mut Context, target: TexImageTarget, len: usize) -> Vec<u8> {
    let mut out = vec![0u8; len];
    gl.get_tex_image(
        target,
        0,
        PixelFormat::Rgba,
        PixelType::UnsignedByte,
        &PixelStore::DEFAULT,
        &mut out,
    )
    .unwrap();
    out
}

#[test]
fn cube_faces_and_3d_layers_are_rendered_into() {
    let mut gl = context(4, 4);
    gl.bind_texture(TextureTarget::Cube, 5).unwrap();
    for f in 0..6 {
        gl.tex_image(
            TexImageTarget::CubeFace(f),
            0,
            InternalFormat::Rgba8,
            [2, 2, 1],
            0,
            None,
        )
        .unwrap();
    }
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.viewport(0, 0, 2, 2).unwrap();
    for f in 0..6u8 {
        gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::CubeFace(f)), 5, 0, 0)
            .unwrap();
        assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
        gl.clear_color(f32::from(f) / 5.0, 0.0, 0.0, 1.0).unwrap();
        gl.clear(ClearMask::COLOR).unwrap();
    }
    // A cube face given to a 2D target: INVALID_OPERATION.
    assert_eq!(
        gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::D2), 5, 0, 0),
        Err(GlError::InvalidOperation)
    );
    assert_eq!(gl.get_error(), Some(GlError::InvalidOperation));
    gl.bind_framebuffer(T::Both, 0).unwrap();
    for f in 0..6u8 {
        let t = texels(&mut gl, TexImageTarget::CubeFace(f), 16);
        let red = (f32::from(f) / 5.0 * 255.0).round_ties_even() as u8;
        assert!(t.chunks(4).all(|p| p == [red, 0, 0, 255]), "face {f}: {t:?}");
    }
    // Slice 2 of a 3D texture.
    gl.bind_texture(TextureTarget::D3, 6).unwrap();
    gl.tex_image(TexImageTarget::D3, 0, InternalFormat::Rgba8, [2, 2, 3], 0, None)
        .unwrap();
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::D3), 6, 0, 2)
        .unwrap();
    gl.clear_color(0.0, 1.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    assert_eq!(
        gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::D3), 6, 0, 3),
        Ok(())
    );
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::IncompleteAttachment));
    gl.bind_framebuffer(T::Both, 0).unwrap();
    let t = texels(&mut gl, TexImageTarget::D3, 48);
    assert!(t[..32].iter().all(|&b| b == 0), "slices 0 and 1 untouched");
    assert!(t[32..].chunks(4).all(|p| p == [0, 255, 0, 255]), "slice 2: {t:?}");
    assert_eq!(gl.get_error(), None);
}

#[test]
fn a_texture_redefined_while_attached_is_checked_again() {
    let mut gl = context(4, 4);
    rgba_texture(&mut gl, 2, 4, 4);
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::D2), 2, 0, 0)
        .unwrap();
    gl.clear_color(1.0, 1.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    // Redefined as a luminance image: not colour-renderable here.
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Luminance8, [4, 4, 1], 0, None)
        .unwrap();
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Unsupported));
    assert_eq!(gl.clear(ClearMask::COLOR), Err(GlError::InvalidFramebufferOperation));
    gl.tex_image(TexImageTarget::D2, 0, InternalFormat::Rgba8, [2, 2, 1], 0, None)
        .unwrap();
    gl.viewport(0, 0, 2, 2).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    assert_eq!(
        gl.read_pixels(1, 1, 1, 1, ReadFormat::Rgba8).unwrap(),
        [255, 255, 0, 255]
    );
    // Deleting the texture detaches it.
    gl.get_error();
    gl.delete_textures(&[2]);
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::MissingAttachment));
}

#[test]
fn a_4096_shadow_map_bound_again_is_not_converted_again() {
    // Figures (not assertions): the time of binding a 4096² depth texture
    // for drawing and back, the first time (f32 texels converted to depth
    // units) and again (the cached depth buffer reused).
    let mut gl = context(4, 4);
    let fb = common::depth_texture_object(&mut gl, 9, 4096);
    gl.bind_framebuffer(T::Both, 0).unwrap();
    for pass in 0..3 {
        let t = std::time::Instant::now();
        gl.bind_framebuffer(T::Both, fb).unwrap();
        let acquire = t.elapsed();
        gl.viewport(0, 0, 4096, 4096).unwrap();
        gl.clear_depth(0.25).unwrap();
        gl.clear(ClearMask::DEPTH).unwrap();
        gl.flush().unwrap();
        let t = std::time::Instant::now();
        gl.bind_framebuffer(T::Both, 0).unwrap();
        println!("pass {pass}: bind {acquire:?}, unbind (write back) {:?}", t.elapsed());
    }
    let z = 0x40_0000 as f32 * (1.0 / 16_777_215.0f64) as f32;
    assert!(common::depth_texels(&mut gl, 4096 * 4096).into_iter().all(|v| v == z));
}

#[test]
fn the_window_is_read_and_blitted_while_an_object_is_drawn() {
    let mut gl = context(4, 4);
    gl.clear_color(0.0, 0.0, 1.0, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    let fb = rb_fbo(&mut gl, 4, 4);
    gl.bind_framebuffer(T::Read, 0).unwrap();
    assert_eq!(gl.read_pixels(3, 3, 1, 1, ReadFormat::Rgba8).unwrap(), [0, 0, 255, 255]);
    let color = BlitMask {
        color: true,
        ..Default::default()
    };
    gl.blit_framebuffer([0, 0, 4, 4], [0, 0, 4, 4], color, BlitFilter::Nearest)
        .unwrap();
    gl.bind_framebuffer(T::Read, fb).unwrap();
    assert_eq!(gl.read_pixels(0, 0, 1, 1, ReadFormat::Rgba8).unwrap(), [0, 0, 255, 255]);
    // Sampling the texture drawn into (a feedback loop, undefined in GL):
    // the draw samples what was rendered before it, and nothing panics.
    rgba_texture(&mut gl, 4, 4, 4);
    gl.framebuffer_texture(T::Both, P::Color(0), Some(TexImageTarget::D2), 4, 0, 0)
        .unwrap();
    gl.viewport(0, 0, 4, 4).unwrap();
    gl.clear_color(0.0, 1.0, 0.0, 1.0).unwrap();
    gl.clear(ClearMask::COLOR).unwrap();
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.disable(Capability::DepthTest).unwrap();
    // White modulated by the texels: green where it was cleared green.
    quad(&mut gl, [1.0, 1.0, 1.0], 0.0);
    assert_eq!(gl.read_pixels(1, 1, 1, 1, ReadFormat::Rgba8).unwrap(), [0, 255, 0, 255]);
    assert_eq!(gl.get_error(), None);
}

/// An FBO of 4-sample RGBA8 and DEPTH24_STENCIL8 renderbuffers, bound.
fn ms_fbo(gl: &mut Context, w: i32, h: i32) -> u32 {
    let fb = gl.gen_framebuffers(1).unwrap()[0];
    let rb = gl.gen_renderbuffers(2).unwrap();
    gl.bind_framebuffer(T::Both, fb).unwrap();
    gl.bind_renderbuffer(rb[0]).unwrap();
    gl.renderbuffer_storage(4, F::Rgba8, w, h).unwrap();
    gl.bind_renderbuffer(rb[1]).unwrap();
    gl.renderbuffer_storage(2, F::Depth24Stencil8, w, h).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Color(0), rb[0]).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::DepthStencil, rb[1]).unwrap();
    fb
}

/// Two overlapping depth-tested triangles with edges across pixels.
fn ms_scene(gl: &mut Context) {
    gl.clear_color(0.1, 0.2, 0.3, 1.0).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.begin(PrimitiveMode::Triangles).unwrap();
    gl.color3(1.0, 0.5, 0.0);
    gl.vertex3(-0.9, -0.7, 0.2);
    gl.vertex3(0.8, -0.2, -0.3);
    gl.vertex3(0.1, 0.9, 0.4);
    gl.color3(0.0, 0.6, 1.0);
    gl.vertex3(-0.6, 0.5, -0.5);
    gl.vertex3(0.7, 0.7, 0.6);
    gl.vertex3(0.0, -0.9, 0.0);
    gl.end().unwrap();
}

#[test]
fn a_multisampled_fbo_renders_multisampled_and_resolves_by_blit() {
    let (w, h) = (24, 16);
    // The reference: a 4-sample context, read resolved.
    let mut reference = Context::new_multisample(FramebufferDesc::rgba8_d24s8(w, h), 4).unwrap();
    ms_scene(&mut reference);
    let want = reference
        .read_pixels(0, 0, w as i32, h as i32, ReadFormat::Rgba8)
        .unwrap();
    let mut gl = context(w, h);
    let single = rb_fbo(&mut gl, w as i32, h as i32);
    let ms = ms_fbo(&mut gl, w as i32, h as i32);
    assert_eq!(gl.check_framebuffer_status(T::Both), Ok(S::Complete));
    assert_eq!((gl.samples(), gl.draw_framebuffer_samples()), (4, 4));
    // Unbound and bound again before drawing: the samples follow.
    gl.bind_framebuffer(T::Both, 0).unwrap();
    assert_eq!(gl.samples(), 1);
    gl.bind_framebuffer(T::Both, ms).unwrap();
    ms_scene(&mut gl);
    // Reads from a multisampled object: GL_INVALID_OPERATION.
    assert_eq!(
        gl.read_pixels(0, 0, 1, 1, ReadFormat::Rgba8),
        Err(GlError::InvalidOperation)
    );
    assert_eq!(gl.get_error(), Some(GlError::InvalidOperation));
    gl.bind_framebuffer(T::Draw, single).unwrap();
    let all = [0, 0, w as i32, h as i32];
    let colour = BlitMask {
        color: true,
        depth: false,
        stencil: false,
    };
    // Scaled: GL_INVALID_OPERATION.
    assert_eq!(
        gl.blit_framebuffer(all, [0, 0, 12, 16], colour, BlitFilter::Nearest),
        Err(GlError::InvalidOperation)
    );
    assert_eq!(gl.get_error(), Some(GlError::InvalidOperation));
    gl.blit_framebuffer(all, all, colour, BlitFilter::Nearest).unwrap();
    let depth = BlitMask {
        color: false,
        depth: true,
        stencil: false,
    };
    gl.blit_framebuffer(all, all, depth, BlitFilter::Nearest).unwrap();
    gl.bind_framebuffer(T::Read, single).unwrap();
    let got = gl.read_pixels(0, 0, w as i32, h as i32, ReadFormat::Rgba8).unwrap();
    assert_eq!(got, want, "resolved as a 4-sample context resolves");
    // Antialiased: some pixels are neither the clear colour nor a triangle's.
    let mixed = got
        .chunks(4)
        .filter(|p| ![[26, 51, 77, 255], [255, 128, 0, 255], [0, 153, 255, 255]].contains(&[p[0], p[1], p[2], p[3]]))
        .count();
    assert!(mixed > 10, "{mixed} mixed pixels");
    // Depth: sample 0's, every pixel.
    let coords: Vec<(u32, u32)> = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).collect();
    let z = gl
        .with_read_framebuffer(false, |fb| {
            coords.iter().map(|&(x, y)| fb.depth_at(x, y)).collect::<Vec<_>>()
        })
        .unwrap();
    let z0: Vec<_> = coords
        .iter()
        .map(|&(x, y)| reference.framebuffer().depth_at(x, y))
        .collect();
    assert_eq!(z, z0);
    assert!(z.iter().any(|v| *v != Some(0xff_ffff)), "depth drawn");
    assert_eq!(gl.get_error(), None);
}

#[test]
fn the_window_buffers_bits_whatever_is_bound() {
    use softgl::fbo::WindowBuffer as W;
    let mut gl = context(8, 8);
    let both = |gl: &Context| [W::Color, W::Depth, W::Stencil].map(|b| gl.window_buffer_bits(b));
    // Depth and stencil together are one packed buffer (llvmpipe's Z24_UNORM_S8_UINT):
    // each reports both sizes.
    let expected = [
        Some([8, 8, 8, 8, 0, 0]),
        Some([0, 0, 0, 0, 24, 8]),
        Some([0, 0, 0, 0, 24, 8]),
    ];
    assert_eq!(both(&gl), expected);
    // An object bound: still the window's.
    rb_fbo(&mut gl, 4, 4);
    assert_eq!(both(&gl), expected);
    let desc = FramebufferDesc {
        width: 8,
        height: 8,
        color: softgl::ColorFormat::Rgb565,
        depth_bits: 16,
        stencil_bits: 0,
    };
    let gl = Context::new(desc).unwrap();
    assert_eq!(both(&gl), [Some([5, 6, 5, 0, 0, 0]), Some([0, 0, 0, 0, 16, 0]), None]);
}

/// An unscaled depth and stencil blit copies rows (`copy_test_rows`): the
/// pixels of the scissored destination box take the source's, and the
/// others keep their own, as the pixel-by-pixel path left them.
#[test]
fn an_unscaled_depth_and_stencil_blit_copies_the_scissored_box() {
    let mut gl = context(4, 4);
    let (w, h) = (9u32, 7u32);
    let src = rb_fbo(&mut gl, w as i32, h as i32);
    gl.viewport(0, 0, w as i32, h as i32).unwrap();
    gl.clear_depth(0.25).unwrap();
    gl.clear_stencil(7).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    // A step in the source's depth and stencil: its right half.
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(4, 0, 5, 7).unwrap();
    gl.clear_depth(0.75).unwrap();
    gl.clear_stencil(9).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.disable(Capability::ScissorTest).unwrap();
    let dst = rb_fbo(&mut gl, w as i32, h as i32);
    gl.clear_depth(1.0).unwrap();
    gl.clear_stencil(1).unwrap();
    gl.clear(ClearMask::ALL).unwrap();
    gl.bind_framebuffer(T::Read, src).unwrap();
    gl.bind_framebuffer(T::Draw, dst).unwrap();
    gl.enable(Capability::ScissorTest).unwrap();
    gl.scissor(2, 1, 5, 4).unwrap();
    let mask = BlitMask {
        color: false,
        depth: true,
        stencil: true,
    };
    let all = [0, 0, w as i32, h as i32];
    gl.blit_framebuffer(all, all, mask, BlitFilter::Nearest).unwrap();
    gl.disable(Capability::ScissorTest).unwrap();
    let read = |gl: &mut Context, fb: u32| {
        gl.bind_framebuffer(T::Read, fb).unwrap();
        gl.with_read_framebuffer(false, |f| {
            (0..h)
                .flat_map(|y| (0..w).map(move |x| (x, y)))
                .map(|(x, y)| (f.depth_at(x, y), f.stencil_at(x, y)))
                .collect::<Vec<_>>()
        })
        .unwrap()
    };
    let (from, to) = (read(&mut gl, src), read(&mut gl, dst));
    let far = to[0];
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            let inside = (2..7).contains(&x) && (1..5).contains(&y);
            assert_eq!(to[i], if inside { from[i] } else { far }, "({x}, {y})");
        }
    }
    assert_ne!(from[0], from[8], "the source has its step");
    assert_ne!(from[0], far);
}
