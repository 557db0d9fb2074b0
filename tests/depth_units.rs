//! A depth texture a framebuffer object rendered into is sampled in the
//! depth test's units, in place (`TexImage::units`), instead of units
//! written back as `Depth32F` texels: the samplers (the JIT's native
//! depth lookup and the interpreter) must read exactly what they read
//! from the written texels, and `glGetTexImage` must return the same.

mod common;

use softgl::fbo::{AttachmentPoint as P, FramebufferTarget as T, RenderbufferFormat as F};
use softgl::texture::{
    Filter, InternalFormat, MipFilter, PixelFormat, PixelStore, PixelType, TexImageTarget, TexParam, TextureTarget,
};
use softgl::{Backend, Capability, ClearMask, CompareFunc, Context, DepthMode, FramebufferDesc, PrimitiveMode, Wrap};

const N: i32 = 16;

/// Triangles at slanted depths (NDC x, y, z), drawn with the depth test.
fn triangles(gl: &mut Context, tris: &[[[f32; 3]; 3]]) {
    gl.begin(PrimitiveMode::Triangles).unwrap();
    for t in tris {
        for v in t {
            gl.vertex3(v[0], v[1], v[2]);
        }
    }
    gl.end().unwrap();
}

/// A quad over the viewport sampling unit 0, r across it for the compare.
fn sample(gl: &mut Context) {
    gl.enable(Capability::Texture(TextureTarget::D2)).unwrap();
    gl.color3(1.0, 1.0, 1.0);
    gl.begin(PrimitiveMode::Quads).unwrap();
    for (x, y, r) in [(-1.0, -1.0, 0.0), (1.0, -1.0, 1.0), (1.0, 1.0, 0.9), (-1.0, 1.0, 0.2)] {
        gl.tex_coord4((x + 1.0) / 2.0 * 1.1 - 0.05, (y + 1.0) / 2.0 * 0.97, r, 1.0);
        gl.vertex3(x, y, 0.0);
    }
    gl.end().unwrap();
    gl.disable(Capability::Texture(TextureTarget::D2)).unwrap();
}

struct Case {
    format: InternalFormat,
    filter: Filter,
    mode: DepthMode,
    compare: Option<CompareFunc>,
    backend: Backend,
}

/// Renders a depth texture in two passes (the second without a clear),
/// samples it over a float colour object and returns the samples and the
/// texture read back as floats.
fn run(c: &Case, units: bool) -> (Vec<[f32; 4]>, Vec<u8>) {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(N as u32, N as u32)).unwrap();
    gl.set_backend(c.backend);
    // Native sampling (NEAREST) from the first draw.
    gl.set_jit_tier(Some(softgl_jit::Tier::Optimized));
    gl.set_depth_units_sampled(units);
    gl.bind_texture(TextureTarget::D2, 5).unwrap();
    gl.tex_image(TexImageTarget::D2, 0, c.format, [N, N, 1], 0, None)
        .unwrap();
    for p in [
        TexParam::MinFilter(c.filter, MipFilter::None),
        TexParam::MagFilter(c.filter),
        TexParam::WrapS(Wrap::ClampToEdge),
        TexParam::WrapT(Wrap::ClampToEdge),
        TexParam::CompareMode(c.compare.is_some()),
        TexParam::CompareFunc(c.compare.unwrap_or(CompareFunc::Lequal)),
        TexParam::DepthMode(c.mode),
    ] {
        gl.tex_parameter(TextureTarget::D2, p).unwrap();
    }
    let stencil = matches!(
        c.format,
        InternalFormat::Depth24Stencil8 | InternalFormat::Depth32FStencil8
    );
    let shadow = gl.gen_framebuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, shadow).unwrap();
    let point = if stencil { P::DepthStencil } else { P::Depth };
    gl.framebuffer_texture(T::Both, point, Some(TexImageTarget::D2), 5, 0, 0)
        .unwrap();
    gl.draw_buffer(None).unwrap();
    gl.read_buffer(None, false).unwrap();
    gl.viewport(0, 0, N, N).unwrap();
    gl.clear_depth(0.875).unwrap();
    gl.clear(ClearMask::DEPTH).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    triangles(
        &mut gl,
        &[
            [[-1.0, -1.0, -0.9], [1.0, -1.0, 0.3], [0.0, 1.0, 0.77]],
            [[-1.0, 1.0, 0.1], [1.0, 1.0, -0.35], [1.0, -0.2, 0.6]],
        ],
    );
    if stencil {
        gl.enable(Capability::StencilTest).unwrap();
    }
    // Released and drawn into again without a clear.
    gl.bind_framebuffer(T::Both, 0).unwrap();
    gl.bind_framebuffer(T::Both, shadow).unwrap();
    triangles(&mut gl, &[[[-1.0, 0.0, -0.99], [0.3, -1.0, -0.2], [0.5, 1.0, 0.05]]]);
    gl.disable(Capability::StencilTest).unwrap();
    gl.disable(Capability::DepthTest).unwrap();

    // Sampled over a float colour object, r across the quad for the compare.
    let target = gl.gen_framebuffers(1).unwrap()[0];
    let rb = gl.gen_renderbuffers(1).unwrap()[0];
    gl.bind_framebuffer(T::Both, target).unwrap();
    gl.bind_renderbuffer(rb).unwrap();
    gl.renderbuffer_storage(0, F::Rgba32F, N, N).unwrap();
    gl.framebuffer_renderbuffer(T::Both, P::Color(0), rb).unwrap();
    gl.viewport(0, 0, N, N).unwrap();
    sample(&mut gl);
    let mut samples = gl.read_pixels_f32(0, 0, N, N).unwrap();
    // Bound again and cleared first (the units not copied: a spare buffer),
    // then sampled again.
    gl.bind_framebuffer(T::Both, shadow).unwrap();
    gl.clear_depth(0.625).unwrap();
    gl.clear(ClearMask::DEPTH).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    triangles(&mut gl, &[[[-1.0, -1.0, 0.5], [1.0, 0.5, -0.7], [-0.5, 1.0, 0.1]]]);
    gl.disable(Capability::DepthTest).unwrap();
    gl.bind_framebuffer(T::Both, target).unwrap();
    sample(&mut gl);
    samples.extend(gl.read_pixels_f32(0, 0, N, N).unwrap());
    let mut texels = vec![0u8; (N * N * 4) as usize];
    gl.get_tex_image(
        TexImageTarget::D2,
        0,
        PixelFormat::DepthComponent,
        PixelType::Float,
        &PixelStore::DEFAULT,
        &mut texels,
    )
    .unwrap();
    assert_eq!(gl.get_error(), None);
    (samples, texels)
}

#[test]
fn depth_rendered_into_a_texture_samples_as_its_written_texels() {
    let formats = [
        InternalFormat::DepthComponent16,
        InternalFormat::DepthComponent24,
        InternalFormat::Depth24Stencil8,
        InternalFormat::DepthComponent32,
        InternalFormat::DepthComponent32F,
        InternalFormat::Depth32FStencil8,
    ];
    let compares = [
        None,
        Some(CompareFunc::Lequal),
        Some(CompareFunc::Gequal),
        Some(CompareFunc::Less),
        Some(CompareFunc::Notequal),
    ];
    let mut cases = 0;
    for format in formats {
        for filter in [Filter::Nearest, Filter::Linear] {
            for mode in [DepthMode::Luminance, DepthMode::Intensity, DepthMode::Alpha] {
                for compare in compares {
                    for backend in [Backend::Jit, Backend::Interpreter] {
                        let c = Case {
                            format,
                            filter,
                            mode,
                            compare,
                            backend,
                        };
                        let on = run(&c, true);
                        let off = run(&c, false);
                        let what = (format, filter, mode, compare, backend);
                        assert_eq!(on.1, off.1, "glGetTexImage {what:?}");
                        let bits = |v: &[[f32; 4]]| v.iter().flatten().map(|f| f.to_bits()).collect::<Vec<_>>();
                        assert_eq!(bits(&on.0), bits(&off.0), "samples {what:?}");
                        // Something was sampled: not one value everywhere.
                        if compare.is_none_or(|f| f == CompareFunc::Lequal) {
                            assert!(on.0.iter().any(|p| *p != on.0[0]), "flat {what:?}");
                        }
                        cases += 1;
                    }
                }
            }
        }
    }
    assert_eq!(cases, 6 * 2 * 3 * 5 * 2);
}

#[test]
fn an_object_bound_again_takes_draw_pixels_before_its_first_draw() {
    // Bound again with its units in the texture, the object is assembled at
    // its first use: glDrawPixels (which does not go through the draw
    // path) must still land in it, not in the window.
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(4, 4)).unwrap();
    let fb = common::depth_texture_object(&mut gl, 2, 4);
    gl.draw_buffer(None).unwrap();
    gl.read_buffer(None, false).unwrap();
    gl.viewport(0, 0, 4, 4).unwrap();
    gl.clear_depth(1.0).unwrap();
    gl.clear(ClearMask::DEPTH).unwrap();
    gl.bind_framebuffer(T::Both, 0).unwrap();
    gl.bind_framebuffer(T::Both, fb).unwrap();
    assert_eq!(gl.samples(), 1);
    gl.window_pos(0.0, 0.0, 0.0).unwrap();
    gl.enable(Capability::DepthTest).unwrap();
    gl.depth_func(CompareFunc::Always).unwrap();
    let depth = [0.25f32; 4];
    let bytes: Vec<u8> = depth.iter().flat_map(|d| d.to_ne_bytes()).collect();
    let data = softgl::texture::PixelData {
        format: PixelFormat::DepthComponent,
        ty: PixelType::Float,
        store: PixelStore::DEFAULT,
        bytes: &bytes,
    };
    gl.draw_pixels(2, 2, softgl::pixel_rect::DrawKind::Depth, &data)
        .unwrap();
    gl.bind_framebuffer(T::Both, 0).unwrap();
    let z = common::depth_texels(&mut gl, 16);
    assert!((z[0] - 0.25).abs() < 1e-6 && (z[5] - 0.25).abs() < 1e-6, "{z:?}");
    assert_eq!((z[2], z[15]), (1.0, 1.0));
    assert_eq!(gl.get_error(), None);
}
